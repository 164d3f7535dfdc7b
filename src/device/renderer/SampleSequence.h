// Low-discrepancy samples for every random decision of a path: Owen-
// scrambled Sobol' points, "padded" (each decision a 2D pair of its own),
// in the hash-based form of Burley, "Practical Hash-based Owen Scrambling"
// (JCGT 9(4), 2020). Per pixel and per decision, the sample index is
// shuffled and the point scrambled with seeds hashed from both, so pixels
// and decisions are decorrelated, while any prefix of 2^k samples of one
// pixel and decision is still a (0,k,2)-net: progressive, deterministic,
// and independent of threads and tiles. See docs/sampling.md.
#pragma once

#include "SampleHash.h"

#include <cstdint>

namespace prism {

inline uint32_t reverseBits(uint32_t bits)
{
  bits = (bits << 16) | (bits >> 16);
  bits = ((bits & 0x00ff00ffu) << 8) | ((bits & 0xff00ff00u) >> 8);
  bits = ((bits & 0x0f0f0f0fu) << 4) | ((bits & 0xf0f0f0f0u) >> 4);
  bits = ((bits & 0x33333333u) << 2) | ((bits & 0xccccccccu) >> 2);
  return ((bits & 0x55555555u) << 1) | ((bits & 0xaaaaaaaau) >> 1);
}

// An Owen scramble of the bits of `x` read from the most significant one:
// each bit flipped by a hash of the bits above it (Laine and Karras's
// permutation on the reversed bits, with Vegdahl's constants).
inline uint32_t nestedUniformScramble(uint32_t x, uint32_t seed)
{
  x = reverseBits(x);
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return reverseBits(x);
}

// The first two dimensions of Sobol's sequence (a (0,2)-sequence in base
// 2), as 32-bit fixed-point fractions.
inline uint32_t sobolDimension0(uint32_t index)
{
  return reverseBits(index);
}
inline uint32_t sobolDimension1(uint32_t index)
{
  // Direction numbers of x + 1: v_0 = 1/2, v_j = v_(j-1) ^ (v_(j-1) >> 1).
  uint32_t v = 0x80000000u, result = 0;
  for (; index; index >>= 1, v ^= v >> 1) {
    if (index & 1u)
      result ^= v;
  }
  return result;
}

// Sample `index` of the sequence with this seed, in [0,1)^2.
inline float2 sobolSample2D(uint32_t index, uint32_t seed)
{
  const uint32_t shuffled = nestedUniformScramble(index, seed);
  const uint32_t x =
      nestedUniformScramble(sobolDimension0(shuffled), mixBits(seed ^ 0x1u));
  const uint32_t y =
      nestedUniformScramble(sobolDimension1(shuffled), mixBits(seed ^ 0x2u));
  // The top 24 bits: exact in a float, and never 1.
  return {
      float(x >> 8) * (1.f / 16777216.f), float(y >> 8) * (1.f / 16777216.f)};
}

// The seed of decision `dimension` of pixel (x, y): the same for every
// sample of the pixel, so its samples form one scrambled sequence.
inline uint32_t sequenceSeed(uint32_t x, uint32_t y, uint32_t dimension)
{
  return mixBits(
      x * 0x9e3779b9u ^ mixBits(y ^ mixBits(dimension + 0x632be5abu)));
}

// Where in pixel (x, y) sample `sample` looks, in [0,1)^2: the pixel centre
// for the first sample so single-sample images stay exact, then the
// pixel's sequence.
inline float2 pixelOffset(uint32_t x, uint32_t y, uint32_t sample)
{
  return sample == 0 ? float2{0.5f, 0.5f}
                     : sobolSample2D(sample, sequenceSeed(x, y, 0xffff0000u));
}

// The point on the lens (depth of field) sample `sample` of pixel (x, y)
// passes through, in [0,1)^2.
inline float2 lensSample(uint32_t x, uint32_t y, uint32_t sample)
{
  return sobolSample2D(sample, sequenceSeed(x, y, 0xffff0001u));
}

} // namespace prism
