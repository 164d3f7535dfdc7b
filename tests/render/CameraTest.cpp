// Cameras (spec 5.2): perspective, orthographic and omnidirectional
// projections, the up vector, imageRegion (crop, flip and overscan beyond
// [0, 1]) and every stereoMode. Where the spec fixes how two renders
// relate (a crop is part of the full image, the left half of side by side
// is the left eye), the test checks that too, beside its reference.
#include "RenderTest.h"

#include <algorithm>
#include <cmath>

namespace {

constexpr float kPi = 3.14159265f;

const Vec3 kRed{0.9f, 0.1f, 0.1f};
const Vec3 kGreen{0.1f, 0.8f, 0.1f};
const Vec3 kBlue{0.1f, 0.2f, 0.9f};
const Vec3 kYellow{0.9f, 0.8f, 0.1f};
const Vec3 kMagenta{0.8f, 0.1f, 0.8f};
const Vec3 kCyan{0.1f, 0.8f, 0.8f};
const Vec3 kWhite{0.9f, 0.9f, 0.9f};

class CameraScene : public RenderTest
{
 protected:
  // Markers around the origin: a white sphere (radius 0.4) at the origin,
  // red at +x, green at +y (both radius 0.3, 1.2 away) and a small blue one
  // (0.2) in front at z = 1.5; behind them at z = -2 a wall of two
  // triangles, dark red at the lower left, dark green at the lower right,
  // dark blue at the top.
  ANARIWorld markers()
  {
    ANARIGeometry spheres = newGeometry("sphere");
    setArray(spheres,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{0, 0, 0}, {1.2f, 0, 0}, {0, 1.2f, 0}, {0, 0, 1.5f}});
    setArray(spheres,
        "vertex.radius",
        ANARI_FLOAT32,
        std::vector<float>{0.4f, 0.3f, 0.3f, 0.2f});
    setArray(spheres,
        "vertex.color",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{kWhite, kRed, kGreen, kBlue});
    ANARIGeometry wall = newGeometry("triangle");
    setArray(wall,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{-4, -3, -2}, {4, -3, -2}, {4, 3, -2}, {-4, 3, -2}});
    setArray(wall,
        "primitive.index",
        ANARI_UINT32_VEC3,
        std::vector<uint32_t>{0, 1, 2, 0, 2, 3});
    setArray(wall,
        "vertex.color",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{0.3f, 0.05f, 0.05f},
            {0.05f, 0.3f, 0.05f},
            {0.05f, 0.05f, 0.3f},
            {0.05f, 0.05f, 0.3f}});
    ANARIMaterial material = newMatte("color");
    return newWorld(
        {newSurface(spheres, material), newSurface(wall, material)});
  }
  // A perspective camera at (0, 0, 5) looking down -z with fovy 40 degrees;
  // `extra` sets further parameters before the commit.
  template <typename Extra>
  ANARICamera perspective(float aspect, Extra extra)
  {
    ANARICamera camera = keep(anariNewCamera(device(), "perspective"));
    setVec3(camera, "position", {0, 0, 5});
    setVec3(camera, "direction", {0, 0, -1});
    setVec3(camera, "up", {0, 1, 0});
    setFloat(camera, "aspect", aspect);
    setFloat(camera, "fovy", 40.f * kPi / 180.f);
    extra(camera);
    anariCommitParameters(device(), camera);
    return camera;
  }
  ANARICamera perspective(float aspect)
  {
    return perspective(aspect, [](ANARICamera) {});
  }
  ANARICamera stereo(float aspect, const char *mode)
  {
    return perspective(aspect, [&](ANARICamera camera) {
      setString(camera, "stereoMode", mode);
      setFloat(camera, "interpupillaryDistance", 0.6f);
    });
  }
  void setImageRegion(ANARICamera camera, const Vec4 &lowerAndUpper)
  {
    anariSetParameter(device(),
        camera,
        "imageRegion",
        ANARI_FLOAT32_BOX2,
        lowerAndUpper.data());
  }
};

// The white sphere in the middle, red to its right, green above it, the
// near blue sphere over the white one's centre and larger than its radius
// suggests; the wall fills the frame, dark red lower left, dark green
// lower right, dark blue along the top.
using PerspectiveCamera = CameraScene;
TEST_F(PerspectiveCamera, Raycast)
{
  renderAndCompare(markers(), perspective(1.5f), newRenderer(), 96, 64);
}

// The same scene with up = +x: the picture turns a quarter
// counterclockwise, so red is above the centre, green to its left and the
// dark green wall corner at the upper right.
using CameraUp = CameraScene;
TEST_F(CameraUp, Raycast)
{
  ANARICamera camera = perspective(1.f, [&](ANARICamera c) {
    setVec3(c, "up", {1, 0, 0});
  });
  renderAndCompare(markers(), camera, newRenderer(), 64, 64);
}

// Orthographic, 4 units high: sizes do not shrink with distance, so the
// blue sphere is exactly half the white one's size, and red and green
// stand 1.2 units (19 pixels) from the centre.
using OrthographicCamera = CameraScene;
TEST_F(OrthographicCamera, Raycast)
{
  renderAndCompare(markers(),
      newOrthographicCamera({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 4.f, 1.5f),
      newRenderer(),
      96,
      64);
}

// An equirectangular panorama from the origin (looking down -z, up +y) of
// six spheres 3 units away: white ahead (-z) in the middle, red (+x) at
// three quarters of the width, cyan (-x) at one quarter, yellow behind
// (+z) split across the left and right edges, green (+y) along the top
// and magenta (-y) along the bottom.
using OmnidirectionalCamera = CameraScene;
TEST_F(OmnidirectionalCamera, Raycast)
{
  ANARIGeometry spheres = newGeometry("sphere");
  setArray(spheres,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{
          {0, 0, -3}, {3, 0, 0}, {-3, 0, 0}, {0, 0, 3}, {0, 3, 0}, {0, -3, 0}});
  setArray(spheres,
      "vertex.color",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{kWhite, kRed, kCyan, kYellow, kGreen, kMagenta});
  setFloat(spheres, "radius", 1.f);
  ANARICamera camera = keep(anariNewCamera(device(), "omnidirectional"));
  setVec3(camera, "position", {0, 0, 0});
  setVec3(camera, "direction", {0, 0, -1});
  setVec3(camera, "up", {0, 1, 0});
  anariCommitParameters(device(), camera);
  renderAndCompare(newWorld({newSurface(spheres, newMatte("color"))}),
      camera,
      newRenderer(),
      128,
      64);
}

// imageRegion ((0.5, 0.5), (1, 1)): the upper right quarter of the square
// view, the green sphere's lower right and the red sphere's upper half
// magnified; it equals that quarter of a full 128 x 128 render.
using ImageRegionCrop = CameraScene;
TEST_F(ImageRegionCrop, Raycast)
{
  ANARIWorld world = markers();
  ANARIRenderer renderer = newRenderer();
  ANARICamera cropped = perspective(1.f, [&](ANARICamera c) {
    setImageRegion(c, {0.5f, 0.5f, 1, 1});
  });
  renderAndCompare(world, cropped, renderer, 64, 64);
  expectSameImage(render(world, cropped, renderer, 64, 64),
      crop(render(world, perspective(1.f), renderer, 128, 128), 64, 64, 64, 64),
      "the cropped render against the upper right of the full one");
}

// imageRegion ((1, 0), (0, 1)) mirrors the view left to right: red left
// of the centre, the dark green wall corner at the lower left.
using ImageRegionFlip = CameraScene;
TEST_F(ImageRegionFlip, Raycast)
{
  ANARIWorld world = markers();
  ANARIRenderer renderer = newRenderer();
  ANARICamera flipped = perspective(1.f, [&](ANARICamera c) {
    setImageRegion(c, {1, 0, 0, 1});
  });
  renderAndCompare(world, flipped, renderer, 64, 64);
  expectSameImage(render(world, flipped, renderer, 64, 64),
      mirrorHorizontally(render(world, perspective(1.f), renderer, 64, 64)),
      "the flipped render against the mirrored plain one");
}

// imageRegion ((-0.5, 0), (1.5, 1)) with the aspect of the square [0, 1]
// sensor: overscan to twice the width, so the middle 64 x 64 of the
// 128 x 64 frame is the plain square view, undistorted, and beside it the
// rest of the wall, its ends and the black background beyond them.
using ImageRegionOverscan = CameraScene;
TEST_F(ImageRegionOverscan, Raycast)
{
  ANARIWorld world = markers();
  ANARIRenderer renderer = newRenderer();
  ANARICamera wide = perspective(1.f, [&](ANARICamera c) {
    setImageRegion(c, {-0.5f, 0, 1.5f, 1});
  });
  renderAndCompare(world, wide, renderer, 128, 64);
  expectSameImage(crop(render(world, wide, renderer, 128, 64), 32, 0, 64, 64),
      render(world, perspective(1.f), renderer, 64, 64),
      "the middle of the overscan render against the plain one");
}

// stereoMode left with an exaggerated interpupillaryDistance of 0.6: the
// eye moves 0.3 to the left, so everything shifts right, the nearer the
// more: the blue sphere sits right of the white one's centre.
using StereoLeft = CameraScene;
TEST_F(StereoLeft, Raycast)
{
  renderAndCompare(markers(), stereo(1.f, "left"), newRenderer(), 64, 64);
}

// stereoMode right: the mirror case, the blue sphere left of the white
// one's centre.
using StereoRight = CameraScene;
TEST_F(StereoRight, Raycast)
{
  renderAndCompare(markers(), stereo(1.f, "right"), newRenderer(), 64, 64);
}

// sideBySide with the aspect of the whole 128 x 64 frame: the left half is
// the left eye's view, the right half the right eye's, each exactly the
// 64 x 64 render of stereoMode left / right.
using StereoSideBySide = CameraScene;
TEST_F(StereoSideBySide, Raycast)
{
  ANARIWorld world = markers();
  ANARIRenderer renderer = newRenderer();
  ANARICamera camera = stereo(2.f, "sideBySide");
  renderAndCompare(world, camera, renderer, 128, 64);
  const auto both = render(world, camera, renderer, 128, 64);
  expectSameImage(crop(both, 0, 0, 64, 64),
      render(world, stereo(1.f, "left"), renderer, 64, 64),
      "the left half against stereoMode left");
  expectSameImage(crop(both, 64, 0, 64, 64),
      render(world, stereo(1.f, "right"), renderer, 64, 64),
      "the right half against stereoMode right");
}

// topBottom with the aspect of the whole 64 x 128 frame: the top half is
// the left eye's view, the bottom half the right eye's.
using StereoTopBottom = CameraScene;
TEST_F(StereoTopBottom, Raycast)
{
  ANARIWorld world = markers();
  ANARIRenderer renderer = newRenderer();
  ANARICamera camera = stereo(0.5f, "topBottom");
  renderAndCompare(world, camera, renderer, 64, 128);
  const auto both = render(world, camera, renderer, 64, 128);
  expectSameImage(crop(both, 0, 64, 64, 64),
      render(world, stereo(1.f, "left"), renderer, 64, 64),
      "the top half against stereoMode left");
  expectSameImage(crop(both, 0, 0, 64, 64),
      render(world, stereo(1.f, "right"), renderer, 64, 64),
      "the bottom half against stereoMode right");
}

} // namespace

namespace {

// The columns and rows of `image` holding opaque pixels (under a
// renderer with a transparent background, those something covers).
struct Extent
{
  uint32_t columns{0}, rows{0};
};
Extent coveredExtent(const prism::image::Image &image)
{
  uint32_t left = image.width, right = 0, bottom = image.height, top = 0;
  for (uint32_t y = 0; y < image.height; y++) {
    for (uint32_t x = 0; x < image.width; x++) {
      if (image.at(x, y).a < 0.5f)
        continue;
      left = std::min(left, x);
      right = std::max(right, x);
      bottom = std::min(bottom, y);
      top = std::max(top, y);
    }
  }
  if (left > right)
    return {};
  return {right - left + 1, top - bottom + 1};
}

// ANARI 1.2 gives 'aspect' no default: unset, the camera takes the frame's
// width / height, so a sphere in a 400 x 200 frame is round (as many
// pixels wide as high, within a pixel), not stretched to twice its width
// as an aspect of 1 would. A sphere of radius 1 at distance 5 seen with
// fovy 40 degrees spans tan(asin(1/5)) / tan(20 deg) of the 200 rows, 112.
class UnsetAspect : public RenderTest
{
 protected:
  ANARIWorld sphere()
  {
    ANARIGeometry spheres = newGeometry("sphere");
    setArray(spheres,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{0, 0, 0}});
    setFloat(spheres, "radius", 1.f);
    return newWorld({newSurface(spheres, newMatte(kWhite))});
  }
  // A committed camera of `subtype` at (0, 0, 5) looking down -z, its
  // `size` parameter (fovy, height) set to `value`, 'aspect' unset.
  ANARICamera unsetAspect(const char *subtype, const char *size, float value)
  {
    ANARICamera camera = keep(anariNewCamera(device(), subtype));
    setVec3(camera, "position", {0, 0, 5});
    setVec3(camera, "direction", {0, 0, -1});
    setVec3(camera, "up", {0, 1, 0});
    setFloat(camera, size, value);
    anariCommitParameters(device(), camera);
    return camera;
  }
  ANARIRenderer transparentRenderer()
  {
    ANARIRenderer renderer = newRenderer();
    setVec4(renderer, "background", {0, 0, 0, 0});
    anariCommitParameters(device(), renderer);
    return renderer;
  }
};
using UnsetAspectPerspective = UnsetAspect;
TEST_F(UnsetAspectPerspective, Raycast)
{
  ANARICamera camera = unsetAspect("perspective", "fovy", 40.f * kPi / 180.f);
  const Extent extent =
      coveredExtent(render(sphere(), camera, transparentRenderer(), 400, 200));
  const float expected =
      std::tan(std::asin(0.2f)) / std::tan(20.f * kPi / 180.f) * 200.f;
  EXPECT_NEAR(float(extent.rows), expected, 1.5f);
  EXPECT_NEAR(float(extent.columns), float(extent.rows), 1.f);
}

// The orthographic camera 4 units high: the sphere of diameter 2 covers
// half the 200 rows and, following the frame's aspect, 100 columns.
using UnsetAspectOrthographic = UnsetAspect;
TEST_F(UnsetAspectOrthographic, Raycast)
{
  ANARICamera camera = unsetAspect("orthographic", "height", 4.f);
  const Extent extent =
      coveredExtent(render(sphere(), camera, transparentRenderer(), 400, 200));
  EXPECT_NEAR(float(extent.rows), 100.f, 1.f);
  EXPECT_NEAR(float(extent.columns), 100.f, 1.f);
}

} // namespace
