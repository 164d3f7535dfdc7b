// Surface attributes (spec 3.13, 5.5, 5.9): every source of "color" and the
// generic attributes, their precedence (instance uniform < geometry uniform
// < primitive.* < vertex.* < faceVarying.*), face-varying values on
// triangles and quads, and the element types a color array may have. Every
// surface is matte with its color taken from an attribute, seen straight on
// by an orthographic camera, so the raycast renderer shows attribute values
// unshaded.
#include "RenderTest.h"

namespace {

const Vec3 kRed{0.9f, 0.1f, 0.1f};
const Vec3 kGreen{0.1f, 0.8f, 0.1f};
const Vec3 kBlue{0.1f, 0.2f, 0.9f};
const Vec3 kYellow{0.9f, 0.8f, 0.1f};
const Vec3 kMagenta{0.8f, 0.1f, 0.8f};
const Vec3 kCyan{0.1f, 0.8f, 0.8f};
const Vec3 kWhite{0.9f, 0.9f, 0.9f};
const Vec4 kOrange{0.9f, 0.5f, 0.1f, 1.f};
const Vec4 kGreyBackground{0.3f, 0.3f, 0.3f, 1.f};

class AttributeScene : public RenderTest
{
 protected:
  // The raycast renderer over a grey background, so black (the default of
  // an attribute nobody set) stands out.
  ANARIRenderer greyRenderer()
  {
    ANARIRenderer renderer = newRenderer();
    setVec4(renderer, "background", kGreyBackground);
    anariCommitParameters(device(), renderer);
    return renderer;
  }
  ANARICamera flatCamera(float height, float aspect)
  {
    return newOrthographicCamera(
        {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, height, aspect);
  }
  // A 0.8 x 0.8 square centred at (x, y) made of two triangles over four
  // shared vertices (lower left, lower right, upper right, upper left),
  // split along the diagonal from lower left to upper right.
  ANARIGeometry trianglePanel(float x, float y)
  {
    ANARIGeometry geometry = newGeometry("triangle");
    setArray(geometry, "vertex.position", ANARI_FLOAT32_VEC3, square(x, y));
    setArray(geometry,
        "primitive.index",
        ANARI_UINT32_VEC3,
        std::vector<uint32_t>{0, 1, 2, 0, 2, 3});
    return geometry;
  }
  // The same square as two quads, a left and a right half, over six shared
  // vertices (bottom row left to right, then top row left to right).
  ANARIGeometry quadPanel(float x, float y)
  {
    ANARIGeometry geometry = newGeometry("quad");
    setArray(geometry,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{x - 0.4f, y - 0.4f, 0},
            {x, y - 0.4f, 0},
            {x + 0.4f, y - 0.4f, 0},
            {x - 0.4f, y + 0.4f, 0},
            {x, y + 0.4f, 0},
            {x + 0.4f, y + 0.4f, 0}});
    setArray(geometry,
        "primitive.index",
        ANARI_UINT32_VEC4,
        std::vector<uint32_t>{0, 1, 4, 3, 1, 2, 5, 4});
    return geometry;
  }
  static std::vector<Vec3> square(float x, float y)
  {
    return {{x - 0.4f, y - 0.4f, 0},
        {x + 0.4f, y - 0.4f, 0},
        {x + 0.4f, y + 0.4f, 0},
        {x - 0.4f, y + 0.4f, 0}};
  }
};

// Five columns, each adding the next source of "color", over a grey
// background; top row triangles, bottom row quads (each panel two
// primitives split as in trianglePanel / quadPanel):
//   1 nothing set: black, the default (0, 0, 0, 1);
//   2 uniform color: orange;
//   3 + primitive.color: red first primitive, green second;
//   4 + vertex.color: blue at the bottom to cyan and white at the top;
//   5 + faceVarying.color: each primitive with its own corners (yellow
//     triangle / magenta triangle; yellow / magenta quad) and white at the
//     upper right corner of each, discontinuous along the shared edge.
using AttributePrecedence = AttributeScene;
TEST_F(AttributePrecedence, Raycast)
{
  std::vector<ANARISurface> surfaces;
  for (int row = 0; row < 2; row++) {
    const bool quads = row == 1;
    for (int column = 0; column < 5; column++) {
      const float x = -2.f + float(column), y = quads ? -0.5f : 0.5f;
      ANARIGeometry g = quads ? quadPanel(x, y) : trianglePanel(x, y);
      if (column >= 1)
        setVec4(g, "color", kOrange);
      if (column >= 2) {
        setArray(g,
            "primitive.color",
            ANARI_FLOAT32_VEC3,
            std::vector<Vec3>{kRed, kGreen});
      }
      if (column >= 3) {
        setArray(g,
            "vertex.color",
            ANARI_FLOAT32_VEC3,
            quads
                ? std::vector<Vec3>{kBlue, kBlue, kBlue, kCyan, kWhite, kWhite}
                : std::vector<Vec3>{kBlue, kBlue, kWhite, kCyan});
      }
      if (column >= 4) {
        // Corners in primitive.index order.
        setArray(g,
            "faceVarying.color",
            ANARI_FLOAT32_VEC3,
            quads ? std::vector<Vec3>{kYellow,
                kYellow,
                kWhite,
                kYellow,
                kMagenta,
                kMagenta,
                kWhite,
                kMagenta}
                  : std::vector<Vec3>{
                      kYellow, kYellow, kWhite, kMagenta, kWhite, kMagenta});
      }
      surfaces.push_back(newSurface(g, newMatte("color")));
    }
  }
  renderAndCompare(
      newWorld(surfaces), flatCamera(2.f, 2.5f), greyRenderer(), 160, 64);
}

// One group of three panels instanced twice. Left to right the panels set
// no color, a uniform blue color and a red-to-green vertex.color. The top
// instance has the uniform color orange, which only the first panel shows
// (geometry attributes take precedence); the bottom instance sets none, so
// its first panel is black.
using AttributeInstance = AttributeScene;
TEST_F(AttributeInstance, Raycast)
{
  ANARIGeometry none = trianglePanel(-1.f, 0);
  ANARIGeometry uniform = trianglePanel(0, 0);
  setVec4(uniform, "color", {kBlue[0], kBlue[1], kBlue[2], 1.f});
  ANARIGeometry perVertex = trianglePanel(1.f, 0);
  setArray(perVertex,
      "vertex.color",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{kRed, kGreen, kGreen, kRed});
  ANARIMaterial material = newMatte("color");
  ANARIGroup group = newGroup({newSurface(none, material),
      newSurface(uniform, material),
      newSurface(perVertex, material)});
  ANARIInstance colored = newInstance(group);
  setMat4(colored, "transform", translation({0, 0.5f, 0}));
  setVec4(colored, "color", kOrange);
  anariCommitParameters(device(), colored);
  ANARIInstance plain = newInstance(group);
  setMat4(plain, "transform", translation({0, -0.5f, 0}));
  anariCommitParameters(device(), plain);
  renderAndCompare(newWorld({}, {colored, plain}),
      flatCamera(2.f, 1.5f),
      greyRenderer(),
      96,
      64);
}

// One quad panel (two quads) read through attribute0..3 from left to
// right, each array of another element type, completed to (x, y, z, w)
// with 0 for missing x, y, z:
//   attribute0 FLOAT32 0 (left) to 1 (right): a black-to-red ramp;
//   attribute1 FLOAT32_VEC2 (x ramp, y ramp): black lower left, red lower
//     right, green upper left, yellow upper right;
//   attribute2 FLOAT32_VEC3: blue along the bottom, cyan along the top;
//   attribute3 FLOAT32_VEC4 set uniformly to magenta on the geometry.
// The instance sets all four uniformly to white, hidden by the geometry's.
using AttributeGeneric = AttributeScene;
TEST_F(AttributeGeneric, Raycast)
{
  ANARIGeometry panel = quadPanel(0, 0);
  setArray(panel,
      "vertex.attribute0",
      ANARI_FLOAT32,
      std::vector<float>{0, 0.5f, 1, 0, 0.5f, 1});
  setArray(panel,
      "vertex.attribute1",
      ANARI_FLOAT32_VEC2,
      std::vector<float>{0, 0, 0.5f, 0, 1, 0, 0, 1, 0.5f, 1, 1, 1});
  setArray(panel,
      "vertex.attribute2",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{kBlue, kBlue, kBlue, kCyan, kCyan, kCyan});
  setVec4(panel, "attribute3", {kMagenta[0], kMagenta[1], kMagenta[2], 1.f});
  std::vector<ANARIInstance> instances;
  const char *names[4] = {
      "attribute0", "attribute1", "attribute2", "attribute3"};
  for (int i = 0; i < 4; i++) {
    ANARIInstance instance =
        newInstance(newGroup({newSurface(panel, newMatte(names[i]))}));
    setMat4(instance, "transform", translation({-1.5f + float(i), 0, 0}));
    for (const char *name : names)
      setVec4(instance, name, {1, 1, 1, 1});
    anariCommitParameters(device(), instance);
    instances.push_back(instance);
  }
  renderAndCompare(
      newWorld({}, instances), flatCamera(1.f, 4.f), greyRenderer(), 128, 32);
}

// vertex.color arrays of five element types, one strip each from bottom
// to top, every strip ramping from 0 (left) to full (right):
//   FLOAT32 (x, 0, 0, 1): black to red;
//   FLOAT32_VEC2 (x, 1 - x, 0, 1): green to red;
//   UFIXED8_VEC3 0..255 in blue: black to blue, as the float ramps;
//   UFIXED16_VEC4 0..65535 in all four: black to white;
//   UFIXED8_RGB_SRGB 0..255 grey, decoded from sRGB: black to white, but
//     darker in between than the UFIXED16 strip (the middle vertex, 128,
//     is 0.216 linear rather than 0.5).
// Each strip has three vertices along the bottom and three along the top,
// so the middle column holds the middle value exactly.
using AttributeColorTypes = AttributeScene;
TEST_F(AttributeColorTypes, Raycast)
{
  std::vector<ANARISurface> surfaces;
  auto strip = [&](int index, ANARIDataType type, auto values) {
    const float y = -0.8f + 0.4f * float(index);
    ANARIGeometry g = newGeometry("quad");
    setArray(g,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{-1, y - 0.15f, 0},
            {0, y - 0.15f, 0},
            {1, y - 0.15f, 0},
            {-1, y + 0.15f, 0},
            {0, y + 0.15f, 0},
            {1, y + 0.15f, 0}});
    setArray(g,
        "primitive.index",
        ANARI_UINT32_VEC4,
        std::vector<uint32_t>{0, 1, 4, 3, 1, 2, 5, 4});
    // The same left, middle and right values along the bottom and top.
    auto both = values;
    both.insert(both.end(), values.begin(), values.end());
    setArray(g, "vertex.color", type, both);
    surfaces.push_back(newSurface(g, newMatte("color")));
  };
  strip(0, ANARI_FLOAT32, std::vector<float>{0, 0.5f, 1});
  strip(1, ANARI_FLOAT32_VEC2, std::vector<Vec2>{{0, 1}, {0.5f, 0.5f}, {1, 0}});
  using Rgb8 = std::array<uint8_t, 3>;
  strip(2,
      ANARI_UFIXED8_VEC3,
      std::vector<Rgb8>{{0, 0, 0}, {0, 0, 128}, {0, 0, 255}});
  using Rgba16 = std::array<uint16_t, 4>;
  const uint16_t h = 32768, f = 65535;
  strip(3,
      ANARI_UFIXED16_VEC4,
      std::vector<Rgba16>{{0, 0, 0, 0}, {h, h, h, h}, {f, f, f, f}});
  strip(4,
      ANARI_UFIXED8_RGB_SRGB,
      std::vector<Rgb8>{{0, 0, 0}, {128, 128, 128}, {255, 255, 255}});
  renderAndCompare(
      newWorld(surfaces), flatCamera(2.f, 1.f), greyRenderer(), 64, 64);
}

// A fan of four indexed triangles around a shared centre vertex; vertex
// colors make it all grey, faceVarying.color (taking precedence) gives each
// triangle its own outer corners (red bottom, green right, blue top, yellow
// left) fading to white at the centre, with hard edges between triangles.
using FaceVaryingTriangle = AttributeScene;
TEST_F(FaceVaryingTriangle, Raycast)
{
  ANARIGeometry fan = newGeometry("triangle");
  setArray(fan,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{{0, 0, 0},
          {-0.9f, -0.9f, 0},
          {0.9f, -0.9f, 0},
          {0.9f, 0.9f, 0},
          {-0.9f, 0.9f, 0}});
  setArray(fan,
      "primitive.index",
      ANARI_UINT32_VEC3,
      std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 1});
  const Vec3 grey{0.4f, 0.4f, 0.4f};
  setArray(fan, "vertex.color", ANARI_FLOAT32_VEC3, std::vector<Vec3>(5, grey));
  setArray(fan,
      "faceVarying.color",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{kWhite,
          kRed,
          kRed,
          kWhite,
          kGreen,
          kGreen,
          kWhite,
          kBlue,
          kBlue,
          kWhite,
          kYellow,
          kYellow});
  renderAndCompare(newWorld({newSurface(fan, newMatte("color"))}),
      flatCamera(2.f, 1.f),
      greyRenderer(),
      64,
      64);
}

// A 2 x 2 grid of indexed quads over nine shared vertices; faceVarying
// colors give each quad one color (lower left red, lower right green,
// upper left blue, upper right yellow) fading to white at the shared
// centre corner, with hard edges between quads.
using FaceVaryingQuad = AttributeScene;
TEST_F(FaceVaryingQuad, Raycast)
{
  std::vector<Vec3> positions;
  for (int y = 0; y < 3; y++) {
    for (int x = 0; x < 3; x++)
      positions.push_back(
          {-0.9f + 0.9f * float(x), -0.9f + 0.9f * float(y), 0.f});
  }
  ANARIGeometry grid = newGeometry("quad");
  setArray(grid, "vertex.position", ANARI_FLOAT32_VEC3, positions);
  // Each quad lists the centre vertex (4) third.
  setArray(grid,
      "primitive.index",
      ANARI_UINT32_VEC4,
      std::vector<uint32_t>{0, 1, 4, 3, 2, 5, 4, 1, 6, 3, 4, 7, 8, 7, 4, 5});
  std::vector<Vec3> corners;
  for (const Vec3 &c : {kRed, kGreen, kBlue, kYellow})
    corners.insert(corners.end(), {c, c, kWhite, c});
  setArray(grid, "faceVarying.color", ANARI_FLOAT32_VEC3, corners);
  // Moved off centre by 0.01 so no pixel centre lies exactly on a quad's
  // inner diagonal (see QuadWatertight in GeometryTest.cpp).
  ANARICamera camera =
      newOrthographicCamera({0.01f, 0.01f, 5}, {0, 0, -1}, {0, 1, 0}, 2.f, 1.f);
  renderAndCompare(newWorld({newSurface(grid, newMatte("color"))}),
      camera,
      greyRenderer(),
      64,
      64);
}

} // namespace
