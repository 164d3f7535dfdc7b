// Cubic convolution weights (Catmull-Rom, a = -0.5) shared by the field
// filters: four taps reproduce quadratics exactly, and the weights of one
// axis sum to 1 with an absolute sum of at most 1.25.
#pragma once

#include <array>

namespace prism {

// Largest absolute weight sum of one axis (reached at t = 1/2).
constexpr float kCatmullRomAbsoluteWeightSum = 1.25f;

// How far a tricubic value may leave [min, max] of its 64 taps, as a
// fraction of (max - min): the negative weights sum to at most
// (S - 1) / 2 when the weights sum to 1 and their absolute values to S.
constexpr float kTricubicOvershoot =
    (kCatmullRomAbsoluteWeightSum * kCatmullRomAbsoluteWeightSum
            * kCatmullRomAbsoluteWeightSum
        - 1.f)
    / 2.f;

// Weights of the taps at -1, 0, 1, 2 for a point at `t` in [0, 1] past tap 0.
inline std::array<float, 4> catmullRomWeights(float t)
{
  const float t2 = t * t;
  const float t3 = t2 * t;
  return {0.5f * (-t3 + 2.f * t2 - t),
      0.5f * (3.f * t3 - 5.f * t2 + 2.f),
      0.5f * (-3.f * t3 + 4.f * t2 + t),
      0.5f * (t3 - t2)};
}

// d/dt of catmullRomWeights(t): the taps' weights of the derivative.
inline std::array<float, 4> catmullRomDerivativeWeights(float t)
{
  const float t2 = t * t;
  return {0.5f * (-3.f * t2 + 4.f * t - 1.f),
      0.5f * (9.f * t2 - 10.f * t),
      0.5f * (-9.f * t2 + 8.f * t + 1.f),
      0.5f * (3.f * t2 - 2.f * t)};
}

} // namespace prism
