// The samplers' sine and cosine agree with libm's (double precision as the
// reference) to float rounding over whole turns, negative ones included.
#include "math/Trig.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace prism {
namespace {

constexpr double kTolerance = 3e-7; // a few float ulps of a unit value

TEST(Trig, QuarterTurnMatchesLibm)
{
  for (int i = -1000; i <= 1000; i++) {
    const float x = float(i) / 1000.f * std::numbers::pi_v<float> / 4.f;
    const float2 cs = cosSinQuarter(x);
    EXPECT_NEAR(cs.x, std::cos(double(x)), kTolerance) << x;
    EXPECT_NEAR(cs.y, std::sin(double(x)), kTolerance) << x;
  }
}

TEST(Trig, WholeTurnsMatchLibm)
{
  for (int i = -8000; i <= 8000; i++) {
    const float u = float(i) / 4000.f; // -2 to 2 turns, every octant edge
    const float2 cs = cosSinTurn(u);
    const double angle = 2.0 * std::numbers::pi * double(u);
    EXPECT_NEAR(cs.x, std::cos(angle), kTolerance) << u;
    EXPECT_NEAR(cs.y, std::sin(angle), kTolerance) << u;
  }
  // Points of the unit circle: cos^2 + sin^2 = 1 to rounding.
  for (int i = 0; i < 1000; i++) {
    const float2 cs = cosSinTurn(float(i) / 1000.f);
    EXPECT_NEAR(cs.x * cs.x + cs.y * cs.y, 1.f, 4e-7f);
  }
}

TEST(Trig, OutOfRangeTurnsGiveAngleZero)
{
  // Outside |u| < 2^20 (and NaN) no int conversion overflows (UBSan would
  // report it): the angle is 0.
  for (float u : {std::nanf(""), INFINITY, -INFINITY, 1e30f, -1e30f, 0x1p20f}) {
    const float2 cs = cosSinTurn(u);
    EXPECT_EQ(cs.x, 1.f) << u;
    EXPECT_EQ(cs.y, 0.f) << u;
  }
  // Just inside the range the result is still on the circle.
  const float2 cs = cosSinTurn(0x1p20f - 0.25f);
  EXPECT_NEAR(cs.x * cs.x + cs.y * cs.y, 1.f, 4e-7f);
}

} // namespace
} // namespace prism
