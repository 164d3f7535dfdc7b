// Motion blur (KHR_CAMERA_SHUTTER with the motion extensions): each scene
// accumulates 32 samples per pixel over the shutter, so whatever moves is
// smeared along its path while the rest stays sharp. Instances moved by
// matrices and by scale/rotation/translation keys, deforming triangles and
// quads, a moving camera, a rolling shutter, and one path-traced scene.
#include "RenderTest.h"

#include <cmath>

namespace {

constexpr float kPi = 3.14159265f;
constexpr uint32_t kFrames = 32;
constexpr uint32_t kWidth = 96, kHeight = 64;
constexpr float kAspect = float(kWidth) / float(kHeight);

const Vec3 kRed{0.9f, 0.1f, 0.1f};
const Vec3 kGreen{0.1f, 0.8f, 0.1f};
const Vec3 kBlue{0.1f, 0.2f, 0.9f};
const Vec3 kYellow{0.9f, 0.8f, 0.1f};
const Vec3 kGrey{0.4f, 0.4f, 0.4f};

// A quaternion (i, j, k, w) turning `radians` about the unit `axis`.
Vec4 rotationAbout(const Vec3 &axis, float radians)
{
  const float s = std::sin(0.5f * radians);
  return {axis[0] * s, axis[1] * s, axis[2] * s, std::cos(0.5f * radians)};
}

class MotionScene : public RenderTest
{
 protected:
  // Sets the camera's shutter and commits it.
  void setShutter(ANARICamera camera, float open, float close)
  {
    const float shutter[2] = {open, close};
    anariSetParameter(device(), camera, "shutter", ANARI_FLOAT32_BOX1, shutter);
    anariCommitParameters(device(), camera);
  }
  // Looking at the origin from +z, the whole shutter open.
  ANARICamera frontView()
  {
    ANARICamera camera =
        newPerspectiveCamera({0, 0, 4}, {0, 0, -1}, {0, 1, 0}, kAspect);
    setShutter(camera, 0.f, 1.f);
    return camera;
  }
  // A grey wall at z = -1 behind everything: shows what stays sharp.
  ANARISurface wall()
  {
    ANARIGeometry quad = newGeometry("quad");
    setArray(quad,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{-4, -3, -1}, {4, -3, -1}, {4, 3, -1}, {-4, 3, -1}});
    return newSurface(quad, newMatte(kGrey));
  }
  // Three spheres in a row (red, green, blue), radius 0.3, around the
  // origin.
  ANARIGroup spheres()
  {
    ANARIGeometry g = newGeometry("sphere");
    setArray(g,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{-0.7f, 0, 0}, {0, 0, 0}, {0.7f, 0, 0}});
    setArray(g,
        "vertex.color",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{kRed, kGreen, kBlue});
    setFloat(g, "radius", 0.3f);
    return newGroup({newSurface(g, newMatte("color"))});
  }
  // A unit square in the xy plane, a color per corner.
  ANARIGroup colorSquare()
  {
    ANARIGeometry g = newGeometry("quad");
    setArray(g,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{-0.5f, -0.5f, 0},
            {0.5f, -0.5f, 0},
            {0.5f, 0.5f, 0},
            {-0.5f, 0.5f, 0}});
    setArray(g,
        "vertex.color",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{kRed, kGreen, kBlue, kYellow});
    return newGroup({newSurface(g, newMatte("color"))});
  }
  ANARIInstance movingInstance(const char *subtype, ANARIGroup group)
  {
    ANARIInstance instance = keep(anariNewInstance(device(), subtype));
    setObject(instance, "group", ANARI_GROUP, group);
    return instance;
  }
  // An ARRAY1D of one FLOAT32_VEC3 array per key.
  ANARIArray1D vertexKeys(const std::vector<std::vector<Vec3>> &keys)
  {
    std::vector<ANARIArray1D> arrays;
    for (const auto &key : keys)
      arrays.push_back(newArray1D(ANARI_FLOAT32_VEC3, key));
    return newArray1D(ANARI_ARRAY1D, arrays.data(), arrays.size());
  }
  void renderBlurred(ANARIWorld world, ANARICamera camera)
  {
    renderAndCompare(
        world, camera, newRenderer(), kWidth, kHeight, {}, kFrames);
  }
};

using InstanceMotionTransform = MotionScene;
using InstanceMotionScaleRotationTranslation = MotionScene;
using TriangleMotionDeformation = MotionScene;
using QuadMotionDeformation = MotionScene;
using CameraMotionTransformation = MotionScene;
using RollingShutter = MotionScene;
using MotionBlurPathTraced = MotionScene;

// The three spheres swing along a bent path through three keys, from the
// lower left over the top to the lower right: a smeared arc in front of a
// sharp wall.
TEST_F(InstanceMotionTransform, Raycast)
{
  ANARIInstance instance = movingInstance("motionTransform", spheres());
  setArray(instance,
      "motion.transform",
      ANARI_FLOAT32_MAT4,
      std::vector<Mat4>{translation({-1.2f, -0.6f, 0}),
          translation({0, 0.6f, 0}),
          translation({1.2f, -0.6f, 0})});
  anariCommitParameters(device(), instance);
  renderBlurred(newWorld({wall()}, {instance}), frontView());
}

// The square spins a quarter turn about z while it shrinks to half its
// size and drifts right: a fan of corner colors, sharpest near its centre.
TEST_F(InstanceMotionScaleRotationTranslation, Raycast)
{
  ANARIInstance instance =
      movingInstance("motionScaleRotationTranslation", colorSquare());
  setArray(instance,
      "motion.scale",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{{2, 2, 1}, {1, 1, 1}});
  setArray(instance,
      "motion.rotation",
      ANARI_FLOAT32_QUAT_IJKW,
      std::vector<Vec4>{
          rotationAbout({0, 0, 1}, 0.f), rotationAbout({0, 0, 1}, 0.5f * kPi)});
  setArray(instance,
      "motion.translation",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{{-0.5f, 0, 0}, {0.5f, 0, 0}});
  anariCommitParameters(device(), instance);
  renderBlurred(newWorld({wall()}, {instance}), frontView());
}

// A yellow triangle whose top vertex sweeps from left to right over the
// shutter while the other two stay: sharp base, fanned apex. The vertex
// normals turn with it (lit more from the right at the end).
TEST_F(TriangleMotionDeformation, Raycast)
{
  ANARIGeometry triangle = newGeometry("triangle");
  setObject(triangle,
      "motion.vertex.position",
      ANARI_ARRAY1D,
      vertexKeys({{{-1, -1, 0}, {1, -1, 0}, {-1.5f, 1, 0}},
          {{-1, -1, 0}, {1, -1, 0}, {1.5f, 1, 0}}}));
  setObject(triangle,
      "motion.vertex.normal",
      ANARI_ARRAY1D,
      vertexKeys({{{0, 0, 1}, {0, 0, 1}, {-0.6f, 0, 0.8f}},
          {{0, 0, 1}, {0, 0, 1}, {0.6f, 0, 0.8f}}}));
  renderBlurred(
      newWorld({wall(), newSurface(triangle, newMatte(kYellow))}), frontView());
}

// Two quads: the left one grows from a sliver to full height (a gradient
// fading upwards), the right one slides down and back up through three
// keys (blurred top and bottom, solid middle).
TEST_F(QuadMotionDeformation, Raycast)
{
  ANARIGeometry quads = newGeometry("quad");
  const std::vector<Vec3> growSmall = {{-1.6f, -0.8f, 0},
      {-0.4f, -0.8f, 0},
      {-0.4f, -0.6f, 0},
      {-1.6f, -0.6f, 0}};
  const std::vector<Vec3> growTall = {
      {-1.6f, -0.8f, 0}, {-0.4f, -0.8f, 0}, {-0.4f, 0.8f, 0}, {-1.6f, 0.8f, 0}};
  auto slide = [](float y) {
    return std::vector<Vec3>{{0.4f, y - 0.4f, 0},
        {1.6f, y - 0.4f, 0},
        {1.6f, y + 0.4f, 0},
        {0.4f, y + 0.4f, 0}};
  };
  auto join = [](std::vector<Vec3> a, const std::vector<Vec3> &b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  const std::vector<Vec3> half = {
      {-1.6f, -0.8f, 0}, {-0.4f, -0.8f, 0}, {-0.4f, 0.1f, 0}, {-1.6f, 0.1f, 0}};
  setObject(quads,
      "motion.vertex.position",
      ANARI_ARRAY1D,
      vertexKeys({join(growSmall, slide(0.4f)),
          join(half, slide(-0.4f)),
          join(growTall, slide(0.4f))}));
  setArray(quads,
      "primitive.color",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{kGreen, kBlue});
  renderBlurred(
      newWorld({wall(), newSurface(quads, newMatte("color"))}), frontView());
}

// The camera pans: it turns 20 degrees about y (to the left) while it
// steps 0.5 to the right, keyed by decomposed rotation and translation.
// The spheres and the wall smear horizontally, the near spheres most.
TEST_F(CameraMotionTransformation, Raycast)
{
  ANARIInstance still = newInstance(spheres());
  anariCommitParameters(device(), still);
  ANARICamera camera = frontView();
  setArray(camera,
      "motion.rotation",
      ANARI_FLOAT32_QUAT_IJKW,
      std::vector<Vec4>{rotationAbout({0, 1, 0}, 0.f),
          rotationAbout({0, 1, 0}, 20.f * kPi / 180.f)});
  setArray(camera,
      "motion.translation",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{{0, 0, 0}, {0.5f, 0, 0}});
  anariCommitParameters(device(), camera);
  renderBlurred(newWorld({wall()}, {still}), camera);
}

// Three upright bars move right; the shutter rolls down the image, each
// line open for a tenth of the shutter: the bars lean, their tops where
// they started and their bottoms where they ended, with short smears.
TEST_F(RollingShutter, Raycast)
{
  ANARIGeometry bars = newGeometry("quad");
  std::vector<Vec3> corners;
  for (float x : {-1.5f, -0.5f, 0.5f}) {
    for (const Vec3 &c : std::vector<Vec3>{{x - 0.1f, -1, 0},
             {x + 0.1f, -1, 0},
             {x + 0.1f, 1, 0},
             {x - 0.1f, 1, 0}})
      corners.push_back(c);
  }
  setArray(bars, "vertex.position", ANARI_FLOAT32_VEC3, corners);
  ANARIGroup group = newGroup({newSurface(bars, newMatte(kRed))});
  ANARIInstance instance = movingInstance("motionTransform", group);
  setArray(instance,
      "motion.transform",
      ANARI_FLOAT32_MAT4,
      std::vector<Mat4>{translation({-0.5f, 0, 0}), translation({0.9f, 0, 0})});
  anariCommitParameters(device(), instance);
  ANARICamera camera = frontView();
  setString(camera, "rollingShutterDirection", "down");
  setFloat(camera, "rollingShutterDuration", 0.1f);
  anariCommitParameters(device(), camera);
  renderBlurred(newWorld({wall()}, {instance}), camera);
}

// Path traced under a white sky: the three spheres drop onto a white floor
// during the shutter. Their smeared trails darken the floor less than the
// sharp contact shadows they leave at the end.
TEST_F(MotionBlurPathTraced, PathTracer)
{
  ANARIGeometry floor = newGeometry("quad");
  setArray(floor,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{
          {-4, -0.3f, -3}, {4, -0.3f, -3}, {4, -0.3f, 3}, {-4, -0.3f, 3}});
  ANARIInstance instance = movingInstance("motionTransform", spheres());
  setArray(instance,
      "motion.transform",
      ANARI_FLOAT32_MAT4,
      std::vector<Mat4>{translation({0, 1.2f, 0}), translation({0, 0, 0})});
  anariCommitParameters(device(), instance);
  ANARIRenderer renderer = newRenderer("pathtracer");
  setFloat(renderer, "ambientRadiance", 1.f);
  anariCommitParameters(device(), renderer);
  ANARICamera camera =
      newPerspectiveCamera({0, 1.5f, 3.5f}, {0, -0.4f, -1}, {0, 1, 0}, kAspect);
  setShutter(camera, 0.f, 1.f);
  renderAndCompare(
      newWorld({newSurface(floor, newMatte({0.8f, 0.8f, 0.8f}))}, {instance}),
      camera,
      renderer,
      kWidth,
      kHeight,
      {},
      kFrames);
}

} // namespace
