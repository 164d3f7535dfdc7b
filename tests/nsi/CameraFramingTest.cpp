// The framing arithmetic on its own, against values worked out by hand.
#include "CameraFraming.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using prism::nsi::frameCamera;
using prism::nsi::ScreenSettings;

TEST(CameraFraming, DefaultWindowIsTheWholeSensor)
{
  ScreenSettings screen;
  screen.width = 400;
  screen.height = 200;
  const auto f = frameCamera(false, 90, screen);
  // s = tan(45 deg) = 1, window [-2, 2] x [-1, 1]: fovy 90 deg, aspect 2.
  EXPECT_NEAR(f.fovy, M_PI / 2, 1e-6);
  EXPECT_NEAR(f.aspect, 2, 1e-6);
  EXPECT_EQ(f.imageRegion, (std::array<float, 4>{0, 0, 1, 1}));
  EXPECT_EQ(f.frameWidth, 400u);
  EXPECT_EQ(f.frameHeight, 200u);
}

TEST(CameraFraming, OffCentreWindowUsesTheEnclosingSensor)
{
  ScreenSettings screen;
  screen.width = screen.height = 100;
  screen.hasWindow = true;
  screen.window = {0, -1, 2, 0.5};
  const auto f = frameCamera(true, 0, screen);
  // Enclosing sensor [-2, 2] x [-1, 1]: height 2, aspect 2; the window is
  // x in [0.5, 1], y in [0, 0.75] of it.
  EXPECT_NEAR(f.height, 2, 1e-6);
  EXPECT_NEAR(f.aspect, 2, 1e-6);
  EXPECT_NEAR(f.imageRegion[0], 0.5, 1e-6);
  EXPECT_NEAR(f.imageRegion[1], 0.0, 1e-6);
  EXPECT_NEAR(f.imageRegion[2], 1.0, 1e-6);
  EXPECT_NEAR(f.imageRegion[3], 0.75, 1e-6);
}

TEST(CameraFraming, CropKeepsWholePixels)
{
  ScreenSettings screen;
  screen.width = 10;
  screen.height = 10;
  screen.crop = {0.25, 0.0, 0.5, 0.42};
  const auto f = frameCamera(false, 60, screen);
  // Columns 2..4 (floor 2.5, ceil 5), rows 0..4 from the top (ceil 4.2).
  EXPECT_EQ(f.frameWidth, 3u);
  EXPECT_EQ(f.frameHeight, 5u);
  EXPECT_NEAR(f.imageRegion[0], 0.2, 1e-6);
  EXPECT_NEAR(f.imageRegion[2], 0.5, 1e-6);
  EXPECT_NEAR(f.imageRegion[1], 0.5, 1e-6);
  EXPECT_NEAR(f.imageRegion[3], 1.0, 1e-6);
}

TEST(CameraFraming, DegenerateInputStaysFinite)
{
  ScreenSettings screen;
  screen.width = 0;
  screen.height = 0;
  screen.hasWindow = true;
  screen.window = {1, 1, 1, 1};
  screen.crop = {2, 2, -1, -1};
  const auto f = frameCamera(false, 1e9, screen);
  EXPECT_TRUE(std::isfinite(f.fovy) && f.fovy > 0);
  EXPECT_GE(f.frameWidth, 1u);
  EXPECT_GE(f.frameHeight, 1u);
  // Not-a-number windows and crops fall back to the defaults.
  screen.width = 8;
  screen.height = 4;
  screen.window = {NAN, 0, 1, 1};
  screen.crop = {0, NAN, 1, 1};
  const auto g = frameCamera(false, 90, screen);
  EXPECT_EQ(g.frameWidth, 8u);
  EXPECT_EQ(g.frameHeight, 4u);
  EXPECT_NEAR(g.aspect, 2.f, 1e-6);
}

} // namespace
