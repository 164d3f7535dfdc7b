// Samplers (spec 5.10) as the color of a matte material: image1D and
// image2D under every filter and wrap mode, image3D, primitive and
// transform samplers, and sRGB texels. Rectangles face an orthographic
// camera, so the raycast renderer shows sampled values unshaded; texture
// coordinates come from vertex attributes, and inTransform / inOffset map
// them to [-1, 2] so three periods of the image show and every wrap mode
// looks different. Each test names what it expects pixel by pixel.
#include "RenderTest.h"

namespace {

const Vec3 kRed{0.9f, 0.1f, 0.1f};
const Vec3 kGreen{0.1f, 0.8f, 0.1f};
const Vec3 kBlue{0.1f, 0.2f, 0.9f};
const Vec3 kYellow{0.9f, 0.8f, 0.1f};
const Vec3 kMagenta{0.8f, 0.1f, 0.8f};
const Vec3 kCyan{0.1f, 0.8f, 0.8f};
const Vec3 kWhite{0.9f, 0.9f, 0.9f};
const Vec3 kGrey{0.3f, 0.3f, 0.3f};

class SamplerScene : public RenderTest
{
 protected:
  // A rectangle of two triangles from (x0, y0) to (x1, y1) in the plane
  // z = 0 with `attribute` given per corner (lower left, lower right,
  // upper right, upper left) as elements of `type`.
  ANARIGeometry rectangle(float x0,
      float y0,
      float x1,
      float y1,
      const char *attribute,
      ANARIDataType type,
      const std::vector<float> &corners)
  {
    ANARIGeometry geometry = newGeometry("triangle");
    setArray(geometry,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{x0, y0, 0}, {x1, y0, 0}, {x1, y1, 0}, {x0, y1, 0}});
    setArray(geometry,
        "primitive.index",
        ANARI_UINT32_VEC3,
        std::vector<uint32_t>{0, 1, 2, 0, 2, 3});
    if (attribute)
      setArray(geometry, attribute, type, corners);
    return geometry;
  }
  // A committed matte material colored by `sampler` (committed here).
  ANARIMaterial sampled(ANARISampler sampler)
  {
    anariCommitParameters(device(), sampler);
    ANARIMaterial material = keep(anariNewMaterial(device(), "matte"));
    setObject(material, "color", ANARI_SAMPLER, sampler);
    anariCommitParameters(device(), material);
    return material;
  }
  ANARICamera flatCamera(float height, float aspect)
  {
    return newOrthographicCamera(
        {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, height, aspect);
  }

  // Four texels red, green, blue, white along a 96 x 16 strip whose
  // attribute0 runs from 0 (left) to 1 (right), sampled at 3 u - 1: each
  // third of the strip (32 pixels) is one period, each texel 8 pixels.
  void renderImage1D(const char *filter, const char *wrapMode)
  {
    ANARISampler sampler = newSampler("image1D");
    setObject(sampler,
        "image",
        ANARI_ARRAY1D,
        newArray1D(ANARI_FLOAT32_VEC3,
            std::vector<Vec3>{kRed, kGreen, kBlue, kWhite}));
    setString(sampler, "filter", filter);
    setString(sampler, "wrapMode", wrapMode);
    setMat4(sampler, "inTransform", scaling({3, 1, 1}));
    setVec4(sampler, "inOffset", {-1, 0, 0, 0});
    ANARIGeometry strip = rectangle(
        -1, -0.25f, 1, 0.25f, "vertex.attribute0", ANARI_FLOAT32, {0, 1, 1, 0});
    renderAndCompare(newWorld({newSurface(strip, sampled(sampler))}),
        flatCamera(1.f / 3.f, 6.f),
        newRenderer(),
        96,
        16);
  }

  // A 4 x 2 image, bottom row red, green, blue, grey and top row yellow,
  // cyan, magenta, white (texel row 0 at v = 0, the bottom), over a 96 x 96
  // square whose attribute0 is (u, v) in [0, 1]^2, sampled at
  // (3 u - 1, 3 v - 1): the middle of a 3 x 3 grid of 32-pixel tiles is
  // the image itself, texels 8 pixels wide and 16 high.
  void renderImage2D(
      const char *filter, const char *wrapMode1, const char *wrapMode2)
  {
    ANARISampler sampler = newSampler("image2D");
    const std::vector<Vec3> texels = {
        kRed, kGreen, kBlue, kGrey, kYellow, kCyan, kMagenta, kWhite};
    setObject(sampler,
        "image",
        ANARI_ARRAY2D,
        newArray2D(ANARI_FLOAT32_VEC3, texels.data(), 4, 2));
    setString(sampler, "filter", filter);
    setString(sampler, "wrapMode1", wrapMode1);
    setString(sampler, "wrapMode2", wrapMode2);
    setMat4(sampler, "inTransform", scaling({3, 3, 1}));
    setVec4(sampler, "inOffset", {-1, -1, 0, 0});
    ANARIGeometry square = rectangle(-1,
        -1,
        1,
        1,
        "vertex.attribute0",
        ANARI_FLOAT32_VEC2,
        {0, 0, 1, 0, 1, 1, 0, 1});
    renderAndCompare(newWorld({newSurface(square, sampled(sampler))}),
        flatCamera(2.f, 1.f),
        newRenderer(),
        96,
        96);
  }

  // A 2 x 2 x 2 image (layer 0: red, green / blue, yellow; layer 1: cyan,
  // magenta / white, grey; x then y then z) on three squares whose
  // attribute1 is (u, v, w) with w 0.25 (left), 0.4 (middle) and 0.75
  // (right), read through inAttribute "attribute1".
  void renderImage3D(const char *filter)
  {
    ANARISampler sampler = newSampler("image3D");
    const std::vector<Vec3> texels = {
        kRed, kGreen, kBlue, kYellow, kCyan, kMagenta, kWhite, kGrey};
    setObject(sampler,
        "image",
        ANARI_ARRAY3D,
        newArray3D(ANARI_FLOAT32_VEC3, texels.data(), 2, 2, 2));
    setString(sampler, "filter", filter);
    setString(sampler, "inAttribute", "attribute1");
    ANARIMaterial material = sampled(sampler);
    std::vector<ANARISurface> surfaces;
    const float depths[3] = {0.25f, 0.4f, 0.75f};
    for (int i = 0; i < 3; i++) {
      const float x = -1.f + float(i), w = depths[i];
      surfaces.push_back(newSurface(rectangle(x - 0.45f,
                                        -0.45f,
                                        x + 0.45f,
                                        0.45f,
                                        "vertex.attribute1",
                                        ANARI_FLOAT32_VEC3,
                                        {0, 0, w, 1, 0, w, 1, 1, w, 0, 1, w}),
          material));
    }
    renderAndCompare(
        newWorld(surfaces), flatCamera(1.f, 3.f), newRenderer(), 96, 32);
  }
};

// clampToEdge: red for the first 32 pixels, then red, green, blue, white
// 8 pixels each, then white to the end.
using Image1DNearestClampToEdge = SamplerScene;
TEST_F(Image1DNearestClampToEdge, Raycast)
{
  renderImage1D("nearest", "clampToEdge");
}

// repeat: red, green, blue, white three times over.
using Image1DNearestRepeat = SamplerScene;
TEST_F(Image1DNearestRepeat, Raycast)
{
  renderImage1D("nearest", "repeat");
}

// mirrorRepeat: white, blue, green, red | red, green, blue, white | white,
// blue, green, red: every other period reversed, mirrored about the
// period boundaries.
using Image1DNearestMirrorRepeat = SamplerScene;
TEST_F(Image1DNearestMirrorRepeat, Raycast)
{
  renderImage1D("nearest", "mirrorRepeat");
}

// linear clampToEdge: pure red up to the first texel centre (pixel 36),
// blends between texel centres 8 pixels apart, pure white from the last
// texel centre (pixel 60) on.
using Image1DLinearClampToEdge = SamplerScene;
TEST_F(Image1DLinearClampToEdge, Raycast)
{
  renderImage1D("linear", "clampToEdge");
}

// linear repeat: the blends of clampToEdge in every period, and between
// periods white blends back into red (pure red or white only at texel
// centres).
using Image1DLinearRepeat = SamplerScene;
TEST_F(Image1DLinearRepeat, Raycast)
{
  renderImage1D("linear", "repeat");
}

// linear mirrorRepeat: as the nearest mirror pattern but blended; the
// period boundaries (pixels 32 and 64) sit in flat runs of one color
// (red at 32, white at 64) 8 pixels wide, where a texel meets its mirror.
using Image1DLinearMirrorRepeat = SamplerScene;
TEST_F(Image1DLinearMirrorRepeat, Raycast)
{
  renderImage1D("linear", "mirrorRepeat");
}

// clampToEdge: the image in the middle tile; the tiles left and right
// repeat its left and right texel columns horizontally, the tiles above
// and below its top and bottom rows vertically, the corner tiles its
// corner texels (red lower left, grey lower right, yellow upper left,
// white upper right).
using Image2DNearestClampToEdge = SamplerScene;
TEST_F(Image2DNearestClampToEdge, Raycast)
{
  renderImage2D("nearest", "clampToEdge", "clampToEdge");
}

// repeat: the image nine times, every tile identical (red at each tile's
// lower left).
using Image2DNearestRepeat = SamplerScene;
TEST_F(Image2DNearestRepeat, Raycast)
{
  renderImage2D("nearest", "repeat", "repeat");
}

// mirrorRepeat: the middle tile is the image; its left and right
// neighbours are mirrored left to right, the ones above and below upside
// down, the corners both, so texels meet their mirror images across every
// tile boundary.
using Image2DNearestMirrorRepeat = SamplerScene;
TEST_F(Image2DNearestMirrorRepeat, Raycast)
{
  renderImage2D("nearest", "mirrorRepeat", "mirrorRepeat");
}

// linear clampToEdge: smooth blends between texel centres inside the
// middle tile, constant beyond the outermost texel centres.
using Image2DLinearClampToEdge = SamplerScene;
TEST_F(Image2DLinearClampToEdge, Raycast)
{
  renderImage2D("linear", "clampToEdge", "clampToEdge");
}

// linear repeat: nine identical blended tiles, blending across tile
// boundaries into the opposite edge (no seams).
using Image2DLinearRepeat = SamplerScene;
TEST_F(Image2DLinearRepeat, Raycast)
{
  renderImage2D("linear", "repeat", "repeat");
}

// linear mirrorRepeat: blended, mirrored across every tile boundary, with
// flat bands where a texel meets its mirror image.
using Image2DLinearMirrorRepeat = SamplerScene;
TEST_F(Image2DLinearMirrorRepeat, Raycast)
{
  renderImage2D("linear", "mirrorRepeat", "mirrorRepeat");
}

// wrapMode1 repeat, wrapMode2 mirrorRepeat: every row of tiles repeats the
// same way horizontally (tiles identical left to right), and the rows
// above and below the middle are upside down.
using Image2DWrapPerAxis = SamplerScene;
TEST_F(Image2DWrapPerAxis, Raycast)
{
  renderImage2D("nearest", "repeat", "mirrorRepeat");
}

// nearest: left square layer 0 (red lower left, green lower right, blue
// upper left, yellow upper right), middle square layer 0 too (w 0.4 is
// still in the first half), right square layer 1 (cyan, magenta / white,
// grey).
using Image3DNearest = SamplerScene;
TEST_F(Image3DNearest, Raycast)
{
  renderImage3D("nearest");
}

// linear: left and right squares blend layer 0 and layer 1 alone (w at
// texel centres) smoothly between the four colors; the middle one is 70%
// layer 0 and 30% layer 1.
using Image3DLinear = SamplerScene;
TEST_F(Image3DLinear, Raycast)
{
  renderImage3D("linear");
}

// Three squares of two triangles each (primitives 0 to 5, each square's
// lower right triangle first); the primitive sampler reads an array of
// eight colors from inOffset 2 on, so the lower right triangles are, left
// to right, blue, magenta, white and the upper left ones yellow, cyan,
// grey; the first two colors (red, green) do not show.
using PrimitiveSampler = SamplerScene;
TEST_F(PrimitiveSampler, Raycast)
{
  std::vector<Vec3> positions;
  for (int i = 0; i < 3; i++) {
    const float x0 = -1.45f + float(i), x1 = x0 + 0.9f;
    positions.insert(positions.end(),
        {{x0, -0.45f, 0},
            {x1, -0.45f, 0},
            {x1, 0.45f, 0},
            {x0, -0.45f, 0},
            {x1, 0.45f, 0},
            {x0, 0.45f, 0}});
  }
  ANARIGeometry triangles = newGeometry("triangle");
  setArray(triangles, "vertex.position", ANARI_FLOAT32_VEC3, positions);
  ANARISampler sampler = newSampler("primitive");
  setObject(sampler,
      "array",
      ANARI_ARRAY1D,
      newArray1D(ANARI_FLOAT32_VEC3,
          std::vector<Vec3>{
              kRed, kGreen, kBlue, kYellow, kMagenta, kCyan, kWhite, kGrey}));
  const uint64_t offset = 2;
  anariSetParameter(device(), sampler, "inOffset", ANARI_UINT64, &offset);
  renderAndCompare(newWorld({newSurface(triangles, sampled(sampler))}),
      flatCamera(1.f, 3.f),
      newRenderer(),
      96,
      32);
}

// A square whose attribute2 is (u, v, 0.5, 1) over [0, 1]^2; the transform
// sampler's outTransform swizzles it to (v, 0.5, u) and outOffset adds
// (0.2, 0, 0): red 0.2 at the bottom to 1.2 (saturated) at the top, green
// 0.5 throughout, blue 0 at the left to 1 at the right.
using TransformSampler = SamplerScene;
TEST_F(TransformSampler, Raycast)
{
  ANARISampler sampler = newSampler("transform");
  setString(sampler, "inAttribute", "attribute2");
  // Column-major: column j holds where input component j goes.
  setMat4(sampler,
      "outTransform",
      {0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1});
  setVec4(sampler, "outOffset", {0.2f, 0, 0, 0});
  ANARIGeometry square = rectangle(-1,
      -1,
      1,
      1,
      "vertex.attribute2",
      ANARI_FLOAT32_VEC4,
      {0, 0, 0.5f, 1, 1, 0, 0.5f, 1, 1, 1, 0.5f, 1, 0, 1, 0.5f, 1});
  renderAndCompare(newWorld({newSurface(square, sampled(sampler))}),
      flatCamera(2.f, 1.f),
      newRenderer(),
      64,
      64);
}

// Four strips, each a nearest image2D of four texels with the bytes 0, 64,
// 128, 255 in every channel it has, from bottom to top:
//   UFIXED8_VEC4 (linear): PNG codes 0, 137, 188, 255 (grey);
//   UFIXED8_R_SRGB: red only, decoded from sRGB, so the PNG repeats the
//     bytes: 0, 64, 128, 255;
//   UFIXED8_RGB_SRGB: the same codes in grey;
//   UFIXED8_RGBA_SRGB: the same codes in grey (alpha is not color).
using SamplerSrgb = SamplerScene;
TEST_F(SamplerSrgb, Raycast)
{
  const ANARIDataType types[4] = {ANARI_UFIXED8_VEC4,
      ANARI_UFIXED8_R_SRGB,
      ANARI_UFIXED8_RGB_SRGB,
      ANARI_UFIXED8_RGBA_SRGB};
  const int channels[4] = {4, 1, 3, 4};
  const uint8_t levels[4] = {0, 64, 128, 255};
  std::vector<ANARISurface> surfaces;
  for (int i = 0; i < 4; i++) {
    std::vector<uint8_t> texels;
    for (uint8_t level : levels)
      texels.insert(texels.end(), size_t(channels[i]), level);
    ANARISampler sampler = newSampler("image2D");
    setObject(sampler,
        "image",
        ANARI_ARRAY2D,
        newArray2D(types[i], texels.data(), 4, 1));
    setString(sampler, "filter", "nearest");
    const float y = -0.75f + 0.5f * float(i);
    surfaces.push_back(newSurface(rectangle(-1,
                                      y - 0.2f,
                                      1,
                                      y + 0.2f,
                                      "vertex.attribute0",
                                      ANARI_FLOAT32_VEC2,
                                      {0, 0, 1, 0, 1, 1, 0, 1}),
        sampled(sampler)));
  }
  renderAndCompare(
      newWorld(surfaces), flatCamera(2.f, 1.f), newRenderer(), 64, 64);
}

} // namespace
