// Deterministic per-pixel random numbers from a hash of (pixel, sample,
// stream): the same image for any thread count or tile order.
#pragma once

#include "../math/Vec.h"

#include <cstdint>

namespace prism {

// A well-mixed 32-bit hash (a two-round multiply-xorshift).
inline uint32_t mixBits(uint32_t x)
{
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// A point in [0,1)^2 for pixel (x, y), sample `sample` and `stream` (one
// stream per independent random choice).
inline float2 hashedSample2D(
    uint32_t x, uint32_t y, uint32_t sample, uint32_t stream)
{
  const uint32_t h =
      mixBits(x * 0x9e3779b9u ^ mixBits(y ^ mixBits(sample ^ mixBits(stream))));
  const uint32_t g = mixBits(h ^ 0x68bc21ebu);
  return {
      float(h >> 8) * (1.f / 16777216.f), float(g >> 8) * (1.f / 16777216.f)};
}

// Where in pixel (x, y) sample `sample` looks, in [0,1)^2: the pixel centre
// for the first sample so single-sample images stay exact.
inline float2 pixelOffset(uint32_t x, uint32_t y, uint32_t sample)
{
  return sample == 0 ? float2{0.5f, 0.5f} : hashedSample2D(x, y, sample, 0);
}

} // namespace prism
