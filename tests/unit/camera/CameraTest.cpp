// Camera rays against analytic answers: perspective, orthographic and
// omnidirectional projection, imageRegion, depth of field, stereo, clipping.
#include "Device.h"
#include "camera/Omnidirectional.h"
#include "camera/Orthographic.h"
#include "camera/Perspective.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace prism {
namespace {

constexpr float kTolerance = 1e-5f;
constexpr float kPi = float(M_PI);

void collect(const void *userPtr,
    ANARIDevice,
    ANARIObject,
    ANARIDataType,
    ANARIStatusSeverity severity,
    ANARIStatusCode,
    const char *message)
{
  if (severity <= ANARI_SEVERITY_WARNING)
    ((std::vector<std::string> *)userPtr)->push_back(message);
}

void expectNear(float3 actual, float3 expected, float tolerance = kTolerance)
{
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

float angleBetween(float3 a, float3 b)
{
  return std::acos(clamp(dot(normalize(a), normalize(b)), -1.f, 1.f));
}

// Where `ray` crosses the plane at `distance` along `normal` from `point`.
float3 crossPlane(const Ray &ray, float3 point, float3 normal, float distance)
{
  const float t =
      (distance - dot(ray.origin - point, normal)) / dot(ray.direction, normal);
  return ray.origin + ray.direction * t;
}

class CameraTest : public ::testing::Test
{
 protected:
  void SetUp() override
  {
    ANARIStatusCallback callback = collect;
    m_device.setParameter(m_device.this_device(),
        "statusCallback",
        ANARI_STATUS_CALLBACK,
        &callback);
    m_device.setParameter(m_device.this_device(),
        "statusCallbackUserData",
        ANARI_VOID_POINTER,
        &m_warnings);
  }
  void TearDown() override
  {
    // Valid parameters must commit silently.
    if (!m_expectWarnings) {
      EXPECT_TRUE(m_warnings.empty()) << m_warnings.front();
    }
  }

  template <typename T>
  void set(Camera &camera, const char *name, ANARIDataType type, T value)
  {
    camera.stageParameter(name, Parameter::make(type, &value, nullptr));
  }
  void setFloat(Camera &camera, const char *name, float value)
  {
    set(camera, name, ANARI_FLOAT32, value);
  }
  void setVec3(Camera &camera, const char *name, float3 value)
  {
    set(camera, name, ANARI_FLOAT32_VEC3, value);
  }
  void setString(Camera &camera, const char *name, const char *value)
  {
    camera.stageParameter(name, Parameter::make(ANARI_STRING, value, nullptr));
  }
  void setRegion(Camera &camera, float2 lower, float2 upper)
  {
    const float box[4] = {lower.x, lower.y, upper.x, upper.y};
    camera.stageParameter(
        "imageRegion", Parameter::make(ANARI_FLOAT32_BOX2, box, nullptr));
  }
  void commit(Camera &camera)
  {
    camera.snapshotForCommit();
    camera.applyCommit();
  }

  Device m_device{nullptr};
  std::vector<std::string> m_warnings;
  bool m_expectWarnings{false};
};

// Perspective /////////////////////////////////////////////////////////////

TEST_F(CameraTest, PerspectiveCentreRayIsDirection)
{
  Perspective camera(m_device);
  setVec3(camera, "position", {1, 2, 3});
  setVec3(camera, "direction", {2, 0, -2});
  commit(camera);
  const Ray ray = camera.generateRay({0.5f, 0.5f});
  expectNear(ray.origin, {1, 2, 3});
  expectNear(ray.direction, normalize(float3{1, 0, -1}));
  EXPECT_EQ(ray.tMin, 0.f);
  EXPECT_EQ(ray.tMax, std::numeric_limits<float>::infinity());
}

TEST_F(CameraTest, PerspectiveDefaultsLookDownMinusZ)
{
  Perspective camera(m_device);
  commit(camera);
  expectNear(camera.generateRay({0.5f, 0.5f}).direction, {0, 0, -1});
  // Default fovy is pi/3: the top edge is 30 degrees up.
  const Ray top = camera.generateRay({0.5f, 1.f});
  EXPECT_NEAR(angleBetween(top.direction, {0, 0, -1}), kPi / 6.f, kTolerance);
  EXPECT_GT(top.direction.y, 0.f);
}

TEST_F(CameraTest, PerspectiveEdgeAnglesFollowFovyAndAspect)
{
  const float fovy = 0.8f;
  const float aspect = 1.5f;
  Perspective camera(m_device);
  setFloat(camera, "fovy", fovy);
  setFloat(camera, "aspect", aspect);
  setVec3(camera, "direction", {0, 0, -1});
  commit(camera);
  const float3 forward{0, 0, -1};

  const Ray top = camera.generateRay({0.5f, 1.f});
  EXPECT_NEAR(angleBetween(top.direction, forward), fovy / 2, kTolerance);
  EXPECT_GT(top.direction.y, 0.f);
  const Ray bottom = camera.generateRay({0.5f, 0.f});
  EXPECT_NEAR(angleBetween(bottom.direction, forward), fovy / 2, kTolerance);
  EXPECT_LT(bottom.direction.y, 0.f);

  const Ray right = camera.generateRay({1.f, 0.5f});
  EXPECT_NEAR(std::tan(angleBetween(right.direction, forward)),
      aspect * std::tan(fovy / 2),
      kTolerance);
  EXPECT_GT(right.direction.x, 0.f);

  // The corner: both offsets at once on the image plane at distance 1.
  const Ray corner = camera.generateRay({1.f, 1.f});
  const float3 onPlane = corner.direction / -corner.direction.z;
  EXPECT_NEAR(onPlane.x, aspect * std::tan(fovy / 2), kTolerance);
  EXPECT_NEAR(onPlane.y, std::tan(fovy / 2), kTolerance);
}

TEST_F(CameraTest, RayDirectionsAreUnitVectors)
{
  Perspective perspective(m_device);
  setFloat(perspective, "fovy", 2.f);
  setFloat(perspective, "aspect", 3.f);
  setFloat(perspective, "apertureRadius", 0.3f);
  setFloat(perspective, "focusDistance", 2.f);
  commit(perspective);
  Omnidirectional omni(m_device);
  commit(omni);
  for (float x : {0.f, 0.1f, 0.5f, 0.9f, 1.f}) {
    for (float y : {0.f, 0.3f, 1.f}) {
      EXPECT_NEAR(
          length(perspective.generateRay({x, y}, {0.1f, 0.8f}).direction),
          1.f,
          kTolerance);
      EXPECT_NEAR(length(omni.generateRay({x, y}).direction), 1.f, kTolerance);
    }
  }
}

TEST_F(CameraTest, UpIsOrthogonalisedAgainstDirection)
{
  Perspective camera(m_device);
  setVec3(camera, "direction", {0, 0, -1});
  setVec3(camera, "up", {0, 1, 1}); // tilted; only its part across counts
  commit(camera);
  const Ray top = camera.generateRay({0.5f, 1.f});
  EXPECT_NEAR(top.direction.x, 0.f, kTolerance);
  EXPECT_GT(top.direction.y, 0.f);
}

TEST_F(CameraTest, ParallelUpIsReplacedWithAWarning)
{
  m_expectWarnings = true;
  Perspective camera(m_device);
  setVec3(camera, "up", {0, 0, 2});
  commit(camera);
  EXPECT_EQ(m_warnings.size(), 1u);
  const Ray ray = camera.generateRay({0.5f, 0.5f});
  expectNear(ray.direction, {0, 0, -1});
  EXPECT_TRUE(std::isfinite(camera.generateRay({0.f, 0.f}).direction.x));
}

// imageRegion /////////////////////////////////////////////////////////////

TEST_F(CameraTest, ImageRegionCropsTheSensor)
{
  Perspective full(m_device);
  setFloat(full, "aspect", 1.25f);
  commit(full);
  Perspective cropped(m_device);
  setFloat(cropped, "aspect", 1.25f);
  setRegion(cropped, {0.25f, 0.25f}, {0.75f, 0.75f});
  commit(cropped);
  for (float x : {0.f, 0.5f, 1.f}) {
    for (float y : {0.f, 0.3f, 1.f}) {
      expectNear(cropped.generateRay({x, y}).direction,
          full.generateRay({0.25f + 0.5f * x, 0.25f + 0.5f * y}).direction);
    }
  }
}

TEST_F(CameraTest, ImageRegionOutsideUnitSquareExtendsTheView)
{
  const float fovy = 1.f;
  Perspective camera(m_device);
  setFloat(camera, "fovy", fovy);
  setRegion(camera, {0.f, -0.5f}, {1.f, 1.5f});
  commit(camera);
  // Sensor y = 1.5 is twice as far from the centre as the frame's edge.
  const Ray top = camera.generateRay({0.5f, 1.f});
  EXPECT_NEAR(std::tan(angleBetween(top.direction, {0, 0, -1})),
      2.f * std::tan(fovy / 2),
      kTolerance);
  expectNear(camera.generateRay({0.5f, 0.5f}).direction, {0, 0, -1});
}

TEST_F(CameraTest, ReversedImageRegionFlipsTheImage)
{
  Perspective camera(m_device);
  setRegion(camera, {1.f, 0.f}, {0.f, 1.f});
  commit(camera);
  EXPECT_GT(camera.generateRay({0.f, 0.5f}).direction.x, 0.f);
  EXPECT_LT(camera.generateRay({1.f, 0.5f}).direction.x, 0.f);
}

// Orthographic ////////////////////////////////////////////////////////////

TEST_F(CameraTest, OrthographicRaysAreParallelAndSpanHeightTimesAspect)
{
  const float height = 2.f;
  const float aspect = 1.5f;
  Orthographic camera(m_device);
  setVec3(camera, "position", {1, 1, 1});
  setVec3(camera, "direction", {1, 0, 0});
  setVec3(camera, "up", {0, 0, 1});
  setFloat(camera, "height", height);
  setFloat(camera, "aspect", aspect);
  commit(camera);
  const float3 right = cross(float3{1, 0, 0}, float3{0, 0, 1});
  for (float x : {0.f, 0.4f, 1.f}) {
    for (float y : {0.f, 0.7f, 1.f})
      expectNear(camera.generateRay({x, y}).direction, {1, 0, 0});
  }
  expectNear(camera.generateRay({0.5f, 0.5f}).origin, {1, 1, 1});
  const float3 left = camera.generateRay({0.f, 0.5f}).origin;
  const float3 rightEdge = camera.generateRay({1.f, 0.5f}).origin;
  expectNear(rightEdge - left, right * (height * aspect));
  const float3 bottom = camera.generateRay({0.5f, 0.f}).origin;
  const float3 top = camera.generateRay({0.5f, 1.f}).origin;
  expectNear(top - bottom, float3{0, 0, height});
}

TEST_F(CameraTest, OrthographicImageRegionCrops)
{
  Orthographic camera(m_device);
  setFloat(camera, "height", 4.f);
  setRegion(camera, {0.25f, 0.25f}, {0.75f, 0.75f});
  commit(camera);
  expectNear(camera.generateRay({0.f, 0.f}).origin, {-1, -1, 0});
  expectNear(camera.generateRay({1.f, 1.f}).origin, {1, 1, 0});
}

// Omnidirectional /////////////////////////////////////////////////////////

TEST_F(CameraTest, OmnidirectionalCentreLooksAlongDirection)
{
  Omnidirectional camera(m_device);
  setVec3(camera, "position", {0, 1, 0});
  setVec3(camera, "direction", {1, 0, 0});
  setVec3(camera, "up", {0, 0, 1});
  setString(camera, "layout", "equirectangular");
  commit(camera);
  const float3 right = cross(float3{1, 0, 0}, float3{0, 0, 1}); // (0,-1,0)
  const Ray centre = camera.generateRay({0.5f, 0.5f});
  expectNear(centre.origin, {0, 1, 0});
  expectNear(centre.direction, {1, 0, 0});
  // Both vertical edges look backwards, the middle of the top row up.
  expectNear(camera.generateRay({0.f, 0.5f}).direction, {-1, 0, 0});
  expectNear(camera.generateRay({1.f, 0.5f}).direction, {-1, 0, 0});
  expectNear(camera.generateRay({0.5f, 1.f}).direction, {0, 0, 1});
  expectNear(camera.generateRay({0.5f, 0.f}).direction, {0, 0, -1});
  // Longitude grows to the right, like the view from inside the sphere.
  expectNear(camera.generateRay({0.75f, 0.5f}).direction, right);
  expectNear(camera.generateRay({0.25f, 0.5f}).direction, -right);
  // Latitude is linear in y: 3/4 up the image is 45 degrees above.
  expectNear(
      camera.generateRay({0.5f, 0.75f}).direction, normalize(float3{1, 0, 1}));
}

TEST_F(CameraTest, OmnidirectionalUnknownLayoutWarns)
{
  m_expectWarnings = true;
  Omnidirectional camera(m_device);
  setString(camera, "layout", "cubemap");
  commit(camera);
  EXPECT_EQ(m_warnings.size(), 1u);
  expectNear(camera.generateRay({0.5f, 0.5f}).direction, {0, 0, -1});
}

// Depth of field //////////////////////////////////////////////////////////

const float2 kLensSamples[] = {{0.5f, 0.5f},
    {0.f, 0.f},
    {0.99f, 0.01f},
    {0.2f, 0.7f},
    {0.9f, 0.95f},
    {0.5f, 0.1f}};

TEST_F(CameraTest, PerspectiveDepthOfFieldFocusesOnThePlane)
{
  const float aperture = 0.25f;
  const float focus = 3.f;
  Perspective camera(m_device);
  setVec3(camera, "position", {1, 0, 2});
  setVec3(camera, "direction", {0, 0, -1});
  setFloat(camera, "apertureRadius", aperture);
  setFloat(camera, "focusDistance", focus);
  commit(camera);
  EXPECT_TRUE(camera.hasDepthOfField());
  const float3 position{1, 0, 2};
  const float3 forward{0, 0, -1};
  for (float2 screen : {float2{0.3f, 0.8f}, float2{0.5f, 0.5f}}) {
    const float3 focal =
        crossPlane(camera.generateRay(screen), position, forward, focus);
    bool spread = false;
    for (float2 lens : kLensSamples) {
      const Ray ray = camera.generateRay(screen, lens);
      expectNear(crossPlane(ray, position, forward, focus), focal, 1e-4f);
      // Lens points lie on the aperture disk in the camera's plane.
      EXPECT_NEAR(dot(ray.origin - position, forward), 0.f, kTolerance);
      EXPECT_LE(length(ray.origin - position), aperture + kTolerance);
      EXPECT_NEAR(length(ray.direction), 1.f, kTolerance);
      spread |= length(ray.origin - position) > 0.1f;
    }
    EXPECT_TRUE(spread);
  }
  // The lens centre is the pinhole.
  expectNear(camera.generateRay({0.3f, 0.8f}, {0.5f, 0.5f}).origin, position);
}

TEST_F(CameraTest, LensEdgeSamplesReachTheApertureRadius)
{
  Perspective camera(m_device);
  setFloat(camera, "apertureRadius", 0.5f);
  commit(camera);
  for (float2 lens : {float2{0.f, 0.5f}, float2{0.f, 0.f}, float2{1.f, 1.f}})
    EXPECT_NEAR(length(camera.generateRay({0.5f, 0.5f}, lens).origin),
        0.5f,
        kTolerance);
}

TEST_F(CameraTest, WithoutApertureLensSamplesDoNotMatter)
{
  Perspective camera(m_device);
  commit(camera);
  EXPECT_FALSE(camera.hasDepthOfField());
  const Ray a = camera.generateRay({0.2f, 0.3f}, {0.5f, 0.5f});
  const Ray b = camera.generateRay({0.2f, 0.3f}, {0.9f, 0.1f});
  expectNear(a.origin, b.origin);
  expectNear(a.direction, b.direction);
}

TEST_F(CameraTest, OrthographicDepthOfFieldFocusesOnThePlane)
{
  const float focus = 5.f;
  Orthographic camera(m_device);
  setFloat(camera, "height", 2.f);
  setFloat(camera, "apertureRadius", 0.1f);
  setFloat(camera, "focusDistance", focus);
  commit(camera);
  const float2 screen{0.9f, 0.2f};
  const Ray pinhole = camera.generateRay(screen);
  expectNear(pinhole.direction, {0, 0, -1});
  const float3 focal = pinhole.origin + pinhole.direction * focus;
  for (float2 lens : kLensSamples) {
    const Ray ray = camera.generateRay(screen, lens);
    expectNear(crossPlane(ray, {0, 0, 0}, {0, 0, -1}, focus), focal, 1e-4f);
  }
}

TEST_F(CameraTest, OmnidirectionalDepthOfFieldFocusesOnTheSphere)
{
  const float focus = 2.f;
  Omnidirectional camera(m_device);
  setFloat(camera, "apertureRadius", 0.2f);
  setFloat(camera, "focusDistance", focus);
  commit(camera);
  const float2 screen{0.8f, 0.6f};
  const Ray pinhole = camera.generateRay(screen);
  const float3 focal = pinhole.origin + pinhole.direction * focus;
  for (float2 lens : kLensSamples) {
    const Ray ray = camera.generateRay(screen, lens);
    // The lens disk faces the pinhole ray.
    EXPECT_NEAR(dot(ray.origin, pinhole.direction), 0.f, kTolerance);
    const float3 toFocal = focal - ray.origin;
    expectNear(ray.direction, normalize(toFocal), 1e-4f);
  }
}

TEST_F(CameraTest, InvalidDepthOfFieldValuesWarn)
{
  m_expectWarnings = true;
  Perspective camera(m_device);
  setFloat(camera, "apertureRadius", -1.f);
  setFloat(camera, "focusDistance", 0.f);
  commit(camera);
  EXPECT_EQ(m_warnings.size(), 2u);
  EXPECT_FALSE(camera.hasDepthOfField());
}

// Stereo //////////////////////////////////////////////////////////////////

TEST_F(CameraTest, StereoEyesSitIpdApartAlongRight)
{
  const float ipd = 0.1f;
  const float3 right = cross(float3{1, 0, 0}, float3{0, 1, 0}); // (0,0,1)
  Perspective left(m_device);
  Perspective rightEye(m_device);
  for (auto *camera : {&left, &rightEye}) {
    setVec3(*camera, "position", {0, 1, 0});
    setVec3(*camera, "direction", {1, 0, 0});
    setFloat(*camera, "interpupillaryDistance", ipd);
  }
  setString(left, "stereoMode", "left");
  setString(rightEye, "stereoMode", "right");
  commit(left);
  commit(rightEye);
  for (float2 screen : {float2{0.5f, 0.5f}, float2{0.1f, 0.9f}}) {
    const Ray l = left.generateRay(screen);
    const Ray r = rightEye.generateRay(screen);
    expectNear(r.origin - l.origin, right * ipd);
    expectNear(0.5f * (l.origin + r.origin), {0, 1, 0});
    expectNear(l.direction, r.direction); // parallel eyes
  }
}

TEST_F(CameraTest, StereoDefaultIpd)
{
  Perspective left(m_device);
  Perspective right(m_device);
  setString(left, "stereoMode", "left");
  setString(right, "stereoMode", "right");
  commit(left);
  commit(right);
  expectNear(right.generateRay({0.5f, 0.5f}).origin
                 - left.generateRay({0.5f, 0.5f}).origin,
      {0.0635f, 0, 0});
}

TEST_F(CameraTest, SideBySideMapsLeftHalfToLeftEye)
{
  const float aspect = 2.f; // of the whole frame: each eye is square
  Perspective both(m_device);
  setString(both, "stereoMode", "sideBySide");
  setFloat(both, "aspect", aspect);
  setRegion(both, {0.1f, 0.f}, {0.9f, 1.f});
  commit(both);
  Perspective left(m_device);
  Perspective right(m_device);
  for (auto *camera : {&left, &right})
    setRegion(*camera, {0.1f, 0.f}, {0.9f, 1.f});
  setString(left, "stereoMode", "left");
  setString(right, "stereoMode", "right");
  commit(left);
  commit(right);
  for (float x : {0.f, 0.3f, 0.49f}) {
    for (float y : {0.f, 0.6f}) {
      const Ray a = both.generateRay({x, y});
      const Ray b = left.generateRay({2.f * x, y});
      expectNear(a.origin, b.origin);
      expectNear(a.direction, b.direction);
      const Ray c = both.generateRay({0.5f + x, y});
      const Ray d = right.generateRay({2.f * x, y});
      expectNear(c.origin, d.origin);
      expectNear(c.direction, d.direction);
    }
  }
  EXPECT_LT(both.generateRay({0.25f, 0.5f}).origin.x, 0.f);
  EXPECT_GT(both.generateRay({0.75f, 0.5f}).origin.x, 0.f);
}

TEST_F(CameraTest, TopBottomMapsTopHalfToLeftEye)
{
  Orthographic both(m_device);
  setString(both, "stereoMode", "topBottom");
  setFloat(both, "aspect", 0.5f); // of the whole frame: each eye is square
  commit(both);
  Orthographic left(m_device);
  Orthographic right(m_device);
  setString(left, "stereoMode", "left");
  setString(right, "stereoMode", "right");
  commit(left);
  commit(right);
  for (float x : {0.f, 0.7f}) {
    for (float y : {0.f, 0.2f, 0.49f}) {
      expectNear(both.generateRay({x, 0.5f + y}).origin,
          left.generateRay({x, 2.f * y}).origin);
      expectNear(both.generateRay({x, y}).origin,
          right.generateRay({x, 2.f * y}).origin);
    }
  }
}

TEST_F(CameraTest, OmnidirectionalStereoBaselineTurnsWithLongitude)
{
  const float ipd = 0.2f;
  Omnidirectional left(m_device);
  Omnidirectional right(m_device);
  for (auto *camera : {&left, &right})
    setFloat(*camera, "interpupillaryDistance", ipd);
  setString(left, "stereoMode", "left");
  setString(right, "stereoMode", "right");
  commit(left);
  commit(right);
  // Looking ahead (-z) the right eye is at +x; looking right (+x), at +z.
  expectNear(right.generateRay({0.5f, 0.5f}).origin
                 - left.generateRay({0.5f, 0.5f}).origin,
      {ipd, 0, 0});
  expectNear(right.generateRay({0.75f, 0.5f}).origin
                 - left.generateRay({0.75f, 0.5f}).origin,
      {0, 0, ipd});
  expectNear(right.generateRay({0.75f, 0.5f}).direction, {1, 0, 0});
}

TEST_F(CameraTest, UnknownStereoModeWarnsAndIsMono)
{
  m_expectWarnings = true;
  Perspective camera(m_device);
  setString(camera, "stereoMode", "anaglyph");
  commit(camera);
  EXPECT_EQ(m_warnings.size(), 1u);
  expectNear(camera.generateRay({0.25f, 0.5f}).origin, {0, 0, 0});
}

// Clipping ////////////////////////////////////////////////////////////////

TEST_F(CameraTest, PerspectiveNearFarAreDistancesAlongTheView)
{
  const float3 position{0, 0, 1};
  const float3 forward{0, 0, -1};
  Perspective camera(m_device);
  setVec3(camera, "position", position);
  setFloat(camera, "near", 0.5f);
  setFloat(camera, "far", 10.f);
  setFloat(camera, "apertureRadius", 0.05f);
  commit(camera);
  const Ray centre = camera.generateRay({0.5f, 0.5f});
  EXPECT_NEAR(centre.tMin, 0.5f, kTolerance);
  EXPECT_NEAR(centre.tMax, 10.f, 1e-4f);
  for (float2 lens : kLensSamples) {
    const Ray corner = camera.generateRay({0.f, 1.f}, lens);
    EXPECT_GT(corner.tMin, 0.5f);
    const float3 nearPoint = corner.origin + corner.direction * corner.tMin;
    const float3 farPoint = corner.origin + corner.direction * corner.tMax;
    EXPECT_NEAR(dot(nearPoint - position, forward), 0.5f, kTolerance);
    EXPECT_NEAR(dot(farPoint - position, forward), 10.f, 1e-4f);
  }
}

TEST_F(CameraTest, OrthographicNearFar)
{
  Orthographic camera(m_device);
  setFloat(camera, "near", 1.f);
  setFloat(camera, "far", 4.f);
  commit(camera);
  const Ray ray = camera.generateRay({0.1f, 0.9f});
  EXPECT_FLOAT_EQ(ray.tMin, 1.f);
  EXPECT_FLOAT_EQ(ray.tMax, 4.f);
}

TEST_F(CameraTest, InvalidNearFarIsIgnored)
{
  m_expectWarnings = true;
  Perspective camera(m_device);
  setFloat(camera, "near", 5.f);
  setFloat(camera, "far", 1.f);
  commit(camera);
  EXPECT_EQ(m_warnings.size(), 1u);
  const Ray ray = camera.generateRay({0.5f, 0.5f});
  EXPECT_EQ(ray.tMin, 0.f);
  EXPECT_EQ(ray.tMax, std::numeric_limits<float>::infinity());
}

TEST_F(CameraTest, OmnidirectionalHasNoClipping)
{
  Omnidirectional camera(m_device);
  commit(camera);
  const Ray ray = camera.generateRay({0.3f, 0.3f});
  EXPECT_EQ(ray.tMin, 0.f);
  EXPECT_EQ(ray.tMax, std::numeric_limits<float>::infinity());
}

// Shutter /////////////////////////////////////////////////////////////////

TEST_F(CameraTest, ShutterDefaultsToAnInstant)
{
  Perspective camera(m_device);
  commit(camera);
  EXPECT_EQ(camera.shutter(), (float2{0.5f, 0.5f}));
}

TEST_F(CameraTest, ShutterIsClampedToTheUnitInterval)
{
  Perspective camera(m_device);
  set(camera, "shutter", ANARI_FLOAT32_BOX1, float2{-0.5f, 2.f});
  commit(camera);
  EXPECT_EQ(camera.shutter(), (float2{0.f, 1.f}));
  set(camera, "shutter", ANARI_FLOAT32_BOX1, float2{0.2f, 0.6f});
  commit(camera);
  EXPECT_EQ(camera.shutter(), (float2{0.2f, 0.6f}));
}

TEST_F(CameraTest, ReversedShutterWarns)
{
  m_expectWarnings = true;
  Orthographic camera(m_device);
  set(camera, "shutter", ANARI_FLOAT32_BOX1, float2{0.8f, 0.2f});
  commit(camera);
  EXPECT_EQ(m_warnings.size(), 1u);
  EXPECT_EQ(camera.shutter(), (float2{0.5f, 0.5f}));
}

TEST_F(CameraTest, EveryExtensionParameterIsRead)
{
  // Unread parameters would be warned about after the commit.
  Perspective camera(m_device);
  setFloat(camera, "apertureRadius", 0.1f);
  setFloat(camera, "focusDistance", 2.f);
  setString(camera, "stereoMode", "sideBySide");
  setFloat(camera, "interpupillaryDistance", 0.07f);
  set(camera, "shutter", ANARI_FLOAT32_BOX1, float2{0.f, 1.f});
  setFloat(camera, "near", 0.1f);
  setFloat(camera, "far", 100.f);
  commit(camera);
  Omnidirectional omni(m_device);
  setString(omni, "layout", "equirectangular");
  setString(omni, "stereoMode", "topBottom");
  commit(omni);
}

} // namespace
} // namespace prism

namespace prism {
namespace {

// Renderers build primary rays from Camera::pinhole() in bulk; those rays
// must be exactly the ones generateRay() gives.
TEST_F(CameraTest, PinholeBasisMatchesGenerateRay)
{
  Perspective camera(m_device);
  setVec3(camera, "position", {1, 2, 3});
  setVec3(camera, "direction", {0.3f, -0.2f, -1.f});
  setFloat(camera, "aspect", 1.5f);
  setRegion(camera, {-0.2f, 0.1f}, {0.9f, 1.3f});
  commit(camera);
  Camera::Pinhole pinhole;
  ASSERT_TRUE(camera.pinhole(pinhole, 1.f));
  for (float x : {0.f, 0.37f, 1.f}) {
    for (float y : {0.f, 0.61f, 1.f}) {
      const float3 d =
          normalize(pinhole.corner + pinhole.dx * x + pinhole.dy * y);
      const Ray ray = camera.generateRay({x, y});
      expectNear(d, ray.direction);
      expectNear(pinhole.origin, ray.origin);
    }
  }
  // Stereo, depth of field and clipping need generateRay().
  setString(camera, "stereoMode", "left");
  commit(camera);
  EXPECT_FALSE(camera.pinhole(pinhole, 1.f));
}

// ANARI 1.2: 'aspect' has no default; unset (or invalid), the image takes
// the frame's width / height, so a 2:1 frame is twice as wide in view as
// it is high, and pinhole() agrees with generateRay().
TEST_F(CameraTest, UnsetAspectFollowsTheFrame)
{
  Perspective camera(m_device);
  setFloat(camera, "fovy", float(M_PI / 2.0)); // tan(fovy / 2) = 1
  commit(camera);
  const Ray right = camera.generateRay({1.f, 0.5f}, {0.5f, 0.5f}, 0.5f, 2.f);
  expectNear(right.direction, normalize(float3{2, 0, -1}));
  const Ray top = camera.generateRay({0.5f, 1.f}, {0.5f, 0.5f}, 0.5f, 2.f);
  expectNear(top.direction, normalize(float3{0, 1, -1}));
  Camera::Pinhole pinhole;
  ASSERT_TRUE(camera.pinhole(pinhole, 2.f));
  expectNear(normalize(pinhole.corner + pinhole.dx + pinhole.dy * 0.5f),
      right.direction);
  // A given aspect wins over the frame's.
  setFloat(camera, "aspect", 1.f);
  commit(camera);
  expectNear(camera.generateRay({1.f, 0.5f}, {0.5f, 0.5f}, 0.5f, 2.f).direction,
      normalize(float3{1, 0, -1}));

  Orthographic ortho(m_device);
  setFloat(ortho, "height", 2.f);
  commit(ortho);
  expectNear(ortho.generateRay({1.f, 0.5f}, {0.5f, 0.5f}, 0.5f, 2.f).origin,
      {2, 0, 0});
  m_expectWarnings = true;
  setFloat(ortho, "aspect", -1.f); // reported; the frame's ratio stays
  commit(ortho);
  ASSERT_EQ(m_warnings.size(), 1u);
  EXPECT_NE(m_warnings[0].find("'aspect' (-1) must be > 0"), std::string::npos);
  expectNear(ortho.generateRay({1.f, 0.5f}, {0.5f, 0.5f}, 0.5f, 3.f).origin,
      {3, 0, 0});
}

} // namespace
} // namespace prism
