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

// Uniform numbers in [0, 1) one after another from a seed (counter-based:
// the n-th number is a hash of seed and n), for decisions whose count is
// not known ahead, such as collisions tracked through a volume.
class HashedStream
{
 public:
  explicit HashedStream(uint32_t seed) : m_seed(mixBits(seed)) {}
  float next()
  {
    const uint32_t h = mixBits(m_seed ^ (m_counter++ * 0x9e3779b9u));
    return float(h >> 8) * (1.f / 16777216.f);
  }

 private:
  uint32_t m_seed;
  uint32_t m_counter{0};
};

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

// Where in its exposure sample n of pixel (x, y) falls, in [0, 1): a van
// der Corput sequence rotated per pixel, so n samples cover the exposure
// evenly (error ~1/n, not ~1/sqrt(n), for motion blur) without pixels
// sharing times; the renderer's seed chooses the rotations. (A centred
// sample, RenderContext::centredSample(), is at the middle instead.)
inline float exposureSample(
    uint32_t x, uint32_t y, uint32_t sample, uint32_t rendererSeed)
{
  uint32_t bits = sample;
  bits = (bits << 16) | (bits >> 16);
  bits = ((bits & 0x00ff00ffu) << 8) | ((bits & 0xff00ff00u) >> 8);
  bits = ((bits & 0x0f0f0f0fu) << 4) | ((bits & 0xf0f0f0f0u) >> 4);
  bits = ((bits & 0x33333333u) << 2) | ((bits & 0xccccccccu) >> 2);
  bits = ((bits & 0x55555555u) << 1) | ((bits & 0xaaaaaaaau) >> 1);
  const float radicalInverse = float(bits >> 8) * (1.f / 16777216.f);
  const float rotation = hashedSample2D(x, y, rendererSeed, 3).x;
  const float u = radicalInverse + rotation;
  return u >= 1.f ? u - 1.f : u;
}

} // namespace prism
