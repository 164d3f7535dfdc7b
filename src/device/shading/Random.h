// Counter-based random numbers for the path tracer. Every value is a pure
// function of (pixel, sample index, frame index, dimension), so an image is
// bit-identical for any thread count, tile order or MPI decomposition.
#pragma once

#include "math/Vec.h"

#include <cstdint>

namespace prism {

// The pcg4d hash of Jarzynski & Olano, "Hash Functions for GPU Rendering"
// (JCGT 9(3), 2020): an LCG step, then two rounds of cross-multiplication
// around an xorshift, so each output word depends on all four input words.
constexpr uint4 pcg4d(uint4 v)
{
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  v.x ^= v.x >> 16u;
  v.y ^= v.y >> 16u;
  v.z ^= v.z >> 16u;
  v.w ^= v.w >> 16u;
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  return v;
}

// The top 24 bits as a float in [0, 1): every value is exact and 1 is never
// returned, so `u * n` is always a valid index below n.
constexpr float unitFloatFromBits(uint32_t bits)
{
  return float(bits >> 8) * 0x1p-24f;
}

// The random numbers of one camera sample. Dimension d always gives the same
// value whatever was drawn before, so code paths that consume different
// numbers of dimensions cannot shift each other's streams.
class RandomSequence
{
 public:
  constexpr RandomSequence(
      uint2 pixel, uint32_t sampleIndex, uint32_t frameIndex)
      : m_key(pcg4d(uint4{pixel.x, pixel.y, sampleIndex, frameIndex}))
  {}

  // One number per dimension, in [0, 1).
  constexpr float get1D(uint32_t dimension) const
  {
    return unitFloatFromBits(hash(dimension).x);
  }
  // Two numbers from one dimension: one hash gives 128 independent bits.
  constexpr float2 get2D(uint32_t dimension) const
  {
    const uint4 h = hash(dimension);
    return {unitFloatFromBits(h.x), unitFloatFromBits(h.y)};
  }

  // Sequential use: each call consumes exactly one dimension.
  constexpr float next1D()
  {
    return get1D(m_dimension++);
  }
  constexpr float2 next2D()
  {
    return get2D(m_dimension++);
  }

  constexpr uint32_t dimension() const
  {
    return m_dimension;
  }
  // Lets a renderer start each bounce at a fixed dimension (e.g. 8 * depth).
  constexpr void setDimension(uint32_t dimension)
  {
    m_dimension = dimension;
  }

 private:
  constexpr uint4 hash(uint32_t dimension) const
  {
    return pcg4d(uint4{m_key.x, m_key.y, m_key.z, m_key.w + dimension});
  }

  uint4 m_key;
  uint32_t m_dimension{0};
};

} // namespace prism
