// Materials (spec 5.11): matte color from a constant, a sampler or an
// attribute, the physicallyBased baseColor, and alphaMode opaque, blend
// and mask with alphaCutoff and opacity. Strips face an orthographic
// camera in front of an opaque blue backdrop, so the raycast renderer
// shows color * coverage + backdrop * (1 - coverage) unshaded.
#include "RenderTest.h"

namespace {

const Vec3 kRed{0.9f, 0.1f, 0.1f};
const Vec3 kGreen{0.1f, 0.8f, 0.1f};
const Vec3 kBlue{0.1f, 0.2f, 0.9f};
const Vec3 kYellow{0.9f, 0.8f, 0.1f};

class MaterialScene : public RenderTest
{
 protected:
  // A rectangle of two triangles from x -1 to 1 and y0 to y1 at depth z,
  // with per-vertex arrays given at the left and right edges:
  // vertex.color red with alpha 0 at the left to 1 at the right,
  // vertex.attribute0 0.5 everywhere, vertex.attribute1 0 to 1.
  ANARIGeometry strip(float y0, float y1, float z = 0.f)
  {
    ANARIGeometry geometry = newGeometry("triangle");
    setArray(geometry,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{-1, y0, z}, {1, y0, z}, {1, y1, z}, {-1, y1, z}});
    setArray(geometry,
        "primitive.index",
        ANARI_UINT32_VEC3,
        std::vector<uint32_t>{0, 1, 2, 0, 2, 3});
    const Vec4 clear{kRed[0], kRed[1], kRed[2], 0.f};
    const Vec4 solid{kRed[0], kRed[1], kRed[2], 1.f};
    setArray(geometry,
        "vertex.color",
        ANARI_FLOAT32_VEC4,
        std::vector<Vec4>{clear, solid, solid, clear});
    setArray(geometry,
        "vertex.attribute0",
        ANARI_FLOAT32,
        std::vector<float>{0.5f, 0.5f, 0.5f, 0.5f});
    setArray(geometry,
        "vertex.attribute1",
        ANARI_FLOAT32,
        std::vector<float>{0, 1, 1, 0});
    return geometry;
  }
  // An uncommitted matte material.
  ANARIMaterial matte()
  {
    return keep(anariNewMaterial(device(), "matte"));
  }
  // The world of `surfaces` in front of an opaque blue backdrop at z = -1.
  ANARIWorld withBackdrop(std::vector<ANARISurface> surfaces)
  {
    ANARIGeometry backdrop = newGeometry("triangle");
    setArray(backdrop,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{-2, -2, -1}, {2, -2, -1}, {2, 2, -1}, {-2, 2, -1}});
    setArray(backdrop,
        "primitive.index",
        ANARI_UINT32_VEC3,
        std::vector<uint32_t>{0, 1, 2, 0, 2, 3});
    surfaces.push_back(newSurface(backdrop, newMatte(kBlue)));
    return newWorld(surfaces);
  }
  ANARICamera flatCamera()
  {
    return newOrthographicCamera({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 2.f, 1.f);
  }
};

// Four squares, left to right: matte without a color (the default grey
// 0.8), a constant color (green), a transform sampler passing attribute1
// (a black-to-red ramp), and the attribute named "attribute1" (the same
// ramp).
using MatteColor = MaterialScene;
TEST_F(MatteColor, Raycast)
{
  std::vector<ANARISurface> surfaces;
  for (int i = 0; i < 4; i++) {
    ANARIMaterial material = matte();
    if (i == 1)
      setVec3(material, "color", kGreen);
    if (i == 2) {
      ANARISampler sampler = newSampler("transform");
      setString(sampler, "inAttribute", "attribute1");
      anariCommitParameters(device(), sampler);
      setObject(material, "color", ANARI_SAMPLER, sampler);
    }
    if (i == 3)
      setString(material, "color", "attribute1");
    anariCommitParameters(device(), material);
    ANARIGeometry square = newGeometry("triangle");
    const float x0 = -1.95f + float(i), x1 = x0 + 0.9f;
    setArray(square,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{
            {x0, -0.45f, 0}, {x1, -0.45f, 0}, {x1, 0.45f, 0}, {x0, 0.45f, 0}});
    setArray(square,
        "primitive.index",
        ANARI_UINT32_VEC3,
        std::vector<uint32_t>{0, 1, 2, 0, 2, 3});
    setArray(square,
        "vertex.attribute1",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 0, 0}});
    surfaces.push_back(newSurface(square, material));
  }
  renderAndCompare(newWorld(surfaces),
      newOrthographicCamera({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 1.f, 4.f),
      newRenderer(),
      128,
      32);
}

// alphaMode opaque (the default) ignores opacity: the top strip (red with
// a color alpha ramping 0 to 1) and the bottom strip (constant yellow with
// opacity 0.3) are solid; the blue backdrop shows only between them.
using AlphaOpaque = MaterialScene;
TEST_F(AlphaOpaque, Raycast)
{
  ANARIMaterial ramp = matte();
  setString(ramp, "color", "color");
  anariCommitParameters(device(), ramp);
  ANARIMaterial faint = matte();
  setVec3(faint, "color", kYellow);
  setFloat(faint, "opacity", 0.3f);
  anariCommitParameters(device(), faint);
  renderAndCompare(withBackdrop({newSurface(strip(0.1f, 0.8f), ramp),
                       newSurface(strip(-0.8f, -0.1f), faint)}),
      flatCamera(),
      newRenderer(),
      64,
      64);
}

// alphaMode blend, from top to bottom:
//   color "color": red over blue with coverage ramping 0 (left, pure
//     blue) to 1 (right, pure red);
//   constant yellow with opacity 0.5: an even half-and-half mix;
//   color "color" times opacity "attribute0" (0.5): the ramp to half red.
using AlphaBlend = MaterialScene;
TEST_F(AlphaBlend, Raycast)
{
  ANARIMaterial ramp = matte();
  setString(ramp, "color", "color");
  setString(ramp, "alphaMode", "blend");
  anariCommitParameters(device(), ramp);
  ANARIMaterial half = matte();
  setVec3(half, "color", kYellow);
  setFloat(half, "opacity", 0.5f);
  setString(half, "alphaMode", "blend");
  anariCommitParameters(device(), half);
  ANARIMaterial halfRamp = matte();
  setString(halfRamp, "color", "color");
  setString(halfRamp, "opacity", "attribute0");
  setString(halfRamp, "alphaMode", "blend");
  anariCommitParameters(device(), halfRamp);
  renderAndCompare(withBackdrop({newSurface(strip(0.4f, 0.9f), ramp),
                       newSurface(strip(-0.25f, 0.25f), half),
                       newSurface(strip(-0.9f, -0.4f), halfRamp)}),
      flatCamera(),
      newRenderer(),
      64,
      64);
}

// alphaMode mask, from top to bottom:
//   the red alpha ramp with the default alphaCutoff 0.5: blue left of the
//     middle, solid red from the middle (pixel 32) on;
//   the same with alphaCutoff 0.25: red from a quarter (pixel 16) on;
//   constant yellow whose opacity is an image1D sampler of attribute1
//     (nearest, texels 1, 0, 1, 0): yellow, blue, yellow, blue quarters.
using AlphaMask = MaterialScene;
TEST_F(AlphaMask, Raycast)
{
  ANARIMaterial half = matte();
  setString(half, "color", "color");
  setString(half, "alphaMode", "mask");
  anariCommitParameters(device(), half);
  ANARIMaterial quarter = matte();
  setString(quarter, "color", "color");
  setString(quarter, "alphaMode", "mask");
  setFloat(quarter, "alphaCutoff", 0.25f);
  anariCommitParameters(device(), quarter);
  ANARISampler stripes = newSampler("image1D");
  setObject(stripes,
      "image",
      ANARI_ARRAY1D,
      newArray1D(ANARI_FLOAT32, std::vector<float>{1, 0, 1, 0}));
  setString(stripes, "filter", "nearest");
  setString(stripes, "inAttribute", "attribute1");
  anariCommitParameters(device(), stripes);
  ANARIMaterial cutOut = matte();
  setVec3(cutOut, "color", kYellow);
  setObject(cutOut, "opacity", ANARI_SAMPLER, stripes);
  setString(cutOut, "alphaMode", "mask");
  anariCommitParameters(device(), cutOut);
  renderAndCompare(withBackdrop({newSurface(strip(0.4f, 0.9f), half),
                       newSurface(strip(-0.25f, 0.25f), quarter),
                       newSurface(strip(-0.9f, -0.4f), cutOut)}),
      flatCamera(),
      newRenderer(),
      64,
      64);
}

// physicallyBased, as the raycast renderer sees it (base color and
// opacity), from top to bottom:
//   constant baseColor green: solid green;
//   baseColor "color" (the red alpha ramp), alphaMode opaque: solid red,
//     the fourth component is ignored;
//   the same with alphaMode blend: red over blue ramping 0 to 1, as matte.
using PhysicallyBased = MaterialScene;
TEST_F(PhysicallyBased, Raycast)
{
  ANARIMaterial constant = keep(anariNewMaterial(device(), "physicallyBased"));
  setVec3(constant, "baseColor", kGreen);
  anariCommitParameters(device(), constant);
  ANARIMaterial opaque = keep(anariNewMaterial(device(), "physicallyBased"));
  setString(opaque, "baseColor", "color");
  anariCommitParameters(device(), opaque);
  ANARIMaterial blend = keep(anariNewMaterial(device(), "physicallyBased"));
  setString(blend, "baseColor", "color");
  setString(blend, "alphaMode", "blend");
  anariCommitParameters(device(), blend);
  renderAndCompare(withBackdrop({newSurface(strip(0.4f, 0.9f), constant),
                       newSurface(strip(-0.25f, 0.25f), opaque),
                       newSurface(strip(-0.9f, -0.4f), blend)}),
      flatCamera(),
      newRenderer(),
      64,
      64);
}

} // namespace
