// Sine and cosine for the samplers' angles, without libm's call: on a
// quarter turn around zero their Taylor series reach float precision in a
// handful of multiply-adds (the first terms left out are below 2e-9), and
// a turn is split into quarter turns exactly (multiplying by 4 is exact).
#pragma once

#include "Vec.h"

#include <cmath>

namespace prism {

// cos and sin of x for |x| <= pi/4.
inline float2 cosSinQuarter(float x)
{
  const float x2 = x * x;
  const float s =
      x
      * (1.f
          + x2
                * (-1.f / 6.f
                    + x2
                          * (1.f / 120.f
                              + x2 * (-1.f / 5040.f + x2 * (1.f / 362880.f)))));
  const float c =
      1.f
      + x2
            * (-0.5f
                + x2
                      * (1.f / 24.f
                          + x2
                                * (-1.f / 720.f
                                    + x2
                                          * (1.f / 40320.f
                                              + x2 * (-1.f / 3628800.f)))));
  return {c, s};
}

// cos and sin of 2 pi u, for |u| < 2^20 (a sampler's u is in [0, 1)); a
// u outside that (or NaN) gives the angle 0 rather than an int conversion
// out of range, which would be undefined.
inline float2 cosSinTurn(float u)
{
  constexpr float kQuarterTurn = 1.5707963267948966f;
  const float quarters = std::abs(u) < 0x1p20f ? 4.f * u : 0.f;
  // The nearest whole quarter (a conversion, not a libm call on x86-64's
  // baseline, which has no rounding instruction).
  const int nearest = int(quarters + (quarters >= 0.f ? 0.5f : -0.5f));
  const float2 cs = cosSinQuarter((quarters - float(nearest)) * kQuarterTurn);
  // Rotate by the whole quarter turns.
  switch (nearest & 3) {
  case 0:
    return cs;
  case 1:
    return {-cs.y, cs.x};
  case 2:
    return {-cs.x, -cs.y};
  default:
    return {cs.y, -cs.x};
  }
}

} // namespace prism
