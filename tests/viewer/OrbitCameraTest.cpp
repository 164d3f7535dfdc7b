// Camera math: orbit keeps the distance to the pivot and turns about up,
// pan moves eye and target together, zoom never passes the target.
#include "OrbitCamera.h"

#include "Math.h"

#include <gtest/gtest.h>

#include <cmath>

namespace prism::viewer {
namespace {

using scenes::operator-;

scene_io::CameraSetup frontView()
{
  scene_io::CameraSetup setup;
  setup.eye = {0.f, 0.f, 10.f};
  setup.at = {0.f, 0.f, 0.f};
  setup.up = {0.f, 1.f, 0.f};
  setup.fovyDegrees = 60.f;
  return setup;
}

void expectNear(const Vec3 &a, const Vec3 &b, float tolerance = 1e-4f)
{
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(a[i], b[i], tolerance) << "component " << i;
}

TEST(OrbitCamera, NinetyDegreesOfYawMovesTheEyeToItsRight)
{
  OrbitCamera camera;
  camera.reset(frontView(), {0.f, 0.f, 0.f});
  camera.orbit(90.f, 0.f);
  expectNear(camera.pose().eye, {10.f, 0.f, 0.f});
  expectNear(camera.pose().at, {0.f, 0.f, 0.f});
  camera.orbit(270.f, 0.f);
  expectNear(camera.pose().eye, {0.f, 0.f, 10.f});
}

TEST(OrbitCamera, OrbitTurnsAboutThePivotNotTheTarget)
{
  OrbitCamera camera;
  camera.reset(frontView(), {0.f, 0.f, 5.f});
  camera.orbit(180.f, 0.f);
  // Eye (0,0,10) and target (0,0,0) mirrored through (0,0,5).
  expectNear(camera.pose().eye, {0.f, 0.f, 0.f});
  expectNear(camera.pose().at, {0.f, 0.f, 10.f});
}

TEST(OrbitCamera, PitchRaisesTheEyeAndStopsShortOfThePole)
{
  OrbitCamera camera;
  camera.reset(frontView(), {0.f, 0.f, 0.f});
  camera.orbit(0.f, 30.f);
  EXPECT_NEAR(
      camera.pose().eye[1], 10.f * std::sin(30.f * 3.14159265f / 180.f), 1e-3f);
  EXPECT_NEAR(camera.distance(), 10.f, 1e-4f);
  camera.orbit(0.f, 500.f);
  const Vec3 view = scenes::normalize(camera.pose().at - camera.pose().eye);
  // One degree from straight down.
  EXPECT_NEAR(view[1], -std::cos(1.f * 3.14159265f / 180.f), 1e-4f);
}

TEST(OrbitCamera, PanMovesEyeAndTargetByAFractionOfTheViewHeight)
{
  OrbitCamera camera;
  camera.reset(frontView(), {0.f, 0.f, 0.f});
  camera.pan(0.5f, 0.f);
  // The view is 2 * 10 * tan(30 degrees) high at the target.
  const float height = 20.f * std::tan(30.f * 3.14159265f / 180.f);
  expectNear(camera.pose().at, {0.5f * height, 0.f, 0.f}, 1e-3f);
  expectNear(camera.pose().eye, {0.5f * height, 0.f, 10.f}, 1e-3f);
}

TEST(OrbitCamera, ZoomScalesTheDistanceAndNeverReachesTheTarget)
{
  OrbitCamera camera;
  camera.reset(frontView(), {0.f, 0.f, 0.f});
  camera.zoom(0.5f);
  expectNear(camera.pose().eye, {0.f, 0.f, 5.f});
  camera.zoom(0.f);
  camera.zoom(-1.f);
  camera.zoom(NAN);
  expectNear(camera.pose().eye, {0.f, 0.f, 5.f});
  for (int i = 0; i < 100; ++i)
    camera.zoom(1e-3f);
  EXPECT_GT(camera.distance(), 0.f);
}

TEST(OrbitCamera, FlyMovesAlongTheViewAndLookTurnsAboutTheEye)
{
  OrbitCamera camera;
  camera.reset(frontView(), {0.f, 0.f, 0.f});
  camera.fly(2.f, 1.f, 0.5f);
  expectNear(camera.pose().eye, {1.f, 0.5f, 8.f});
  expectNear(camera.pose().at, {1.f, 0.5f, -2.f});
  camera.look(90.f, 0.f); // turn right: towards +x
  const Vec3 view = scenes::normalize(camera.pose().at - camera.pose().eye);
  expectNear(view, {1.f, 0.f, 0.f});
  expectNear(camera.pose().eye, {1.f, 0.5f, 8.f});
}

TEST(OrbitCamera, FocusAndFieldOfViewAreKeptSane)
{
  OrbitCamera camera;
  camera.reset(frontView(), {0.f, 0.f, 0.f});
  EXPECT_FLOAT_EQ(camera.pose().focusDistance, 10.f);
  camera.focusOn({3.f, 0.f, 4.f}); // 6 along the view
  EXPECT_FLOAT_EQ(camera.pose().focusDistance, 6.f);
  camera.focusOn({0.f, 0.f, 20.f}); // behind: ignored
  EXPECT_FLOAT_EQ(camera.pose().focusDistance, 6.f);
  camera.setFovy(500.f);
  EXPECT_FLOAT_EQ(camera.pose().fovyDegrees, 170.f);
  camera.setAperture(-1.f);
  EXPECT_FLOAT_EQ(camera.pose().apertureRadius, 0.f);
}

} // namespace
} // namespace prism::viewer
