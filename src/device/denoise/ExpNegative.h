// exp(-x) without a libm call: every tap of every à-trous pass needs one.
#pragma once

#include <bit>
#include <cstdint>

namespace prism::denoising {

// exp(-x) for x >= 0, within 3e-6 (relative 1e-5); 0 for x >= 87, +inf
// and NaN.
inline float expNegative(float x)
{
  const float t = x * 1.44269504f; // in powers of two
  if (!(t < 126.f))                // also catches NaN and +inf
    return 0.f;
  const int whole = int(t);
  const float u = (t - float(whole)) * 0.69314718f; // in [0, ln 2)
  // Taylor series of exp(-u); the dropped 8th term is below 1.3e-6.
  float fraction = 1.f - u * (1.f / 7.f);
  fraction = 1.f - u * (1.f / 6.f) * fraction;
  fraction = 1.f - u * (1.f / 5.f) * fraction;
  fraction = 1.f - u * (1.f / 4.f) * fraction;
  fraction = 1.f - u * (1.f / 3.f) * fraction;
  fraction = 1.f - u * (1.f / 2.f) * fraction;
  fraction = 1.f - u * fraction;
  return fraction * std::bit_cast<float>(uint32_t(127 - whole) << 23);
}

} // namespace prism::denoising
