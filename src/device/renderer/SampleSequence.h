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
  // Bytes swap in one instruction; then the bits within each byte.
  bits = __builtin_bswap32(bits);
  bits = ((bits & 0x0f0f0f0fu) << 4) | ((bits & 0xf0f0f0f0u) >> 4);
  bits = ((bits & 0x33333333u) << 2) | ((bits & 0xccccccccu) >> 2);
  return ((bits & 0x55555555u) << 1) | ((bits & 0xaaaaaaaau) >> 1);
}

// Laine and Karras's permutation with Vegdahl's constants: each bit is
// flipped by a hash of the bits below it. On bit-reversed values that is an
// Owen scramble (each binary digit flipped by the digits above it).
inline uint32_t laineKarras(uint32_t x, uint32_t seed)
{
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

// An Owen scramble of the bits of `x` read from the most significant one.
inline uint32_t nestedUniformScramble(uint32_t x, uint32_t seed)
{
  return reverseBits(laineKarras(reverseBits(x), seed));
}

// The first two dimensions of Sobol's sequence (a (0,2)-sequence in base
// 2), as 32-bit fixed-point fractions.
inline uint32_t sobolDimension0(uint32_t index)
{
  return reverseBits(index);
}
// Sobol's second dimension, bit-reversed. Its direction numbers (v_0 = 1/2,
// v_j = v_(j-1) ^ (v_(j-1) >> 1)) are the rows of Pascal's triangle mod 2:
// reversed, v_j has bit k set exactly when k's bits are a subset of j's
// (Lucas). So output bit k is the XOR of the index bits j that contain k:
// a superset sum over the five bits of a bit's position, one shift per
// position bit, with no table and nothing a vector unit cannot do.
inline uint32_t sobolDimension1Reversed(uint32_t index)
{
  uint32_t bits = index;
  bits ^= (bits >> 1) & 0x55555555u;
  bits ^= (bits >> 2) & 0x33333333u;
  bits ^= (bits >> 4) & 0x0f0f0f0fu;
  bits ^= (bits >> 8) & 0x00ff00ffu;
  bits ^= (bits >> 16) & 0x0000ffffu;
  return bits;
}
inline uint32_t sobolDimension1(uint32_t index)
{
  return reverseBits(sobolDimension1Reversed(index));
}

// Sample `index` of the sequence with this seed, in [0,1)^2: the index
// shuffled by an Owen scramble, both coordinates Owen-scrambled. Written
// in the bit-reversed domain the scrambles work in, so four bit reversals
// do what seven would.
inline float2 sobolSample2D(uint32_t index, uint32_t seed)
{
  const uint32_t shuffled = nestedUniformScramble(index, seed);
  // nestedUniformScramble(sobolDimension0(i), s) is reverse(LK(i, s)).
  const uint32_t x = reverseBits(laineKarras(shuffled, mixBits(seed ^ 0x1u)));
  const uint32_t y = reverseBits(
      laineKarras(sobolDimension1Reversed(shuffled), mixBits(seed ^ 0x2u)));
  // The top 24 bits: exact in a float, and never 1.
  return {
      float(x >> 8) * (1.f / 16777216.f), float(y >> 8) * (1.f / 16777216.f)};
}

// One coordinate of sobolSample2D(index, seed), for one-dimensional
// decisions: half the work.
inline float sobolSampleX(uint32_t index, uint32_t seed)
{
  const uint32_t shuffled = nestedUniformScramble(index, seed);
  const uint32_t x = reverseBits(laineKarras(shuffled, mixBits(seed ^ 0x1u)));
  return float(x >> 8) * (1.f / 16777216.f);
}
inline float sobolSampleY(uint32_t index, uint32_t seed)
{
  const uint32_t shuffled = nestedUniformScramble(index, seed);
  const uint32_t y = reverseBits(
      laineKarras(sobolDimension1Reversed(shuffled), mixBits(seed ^ 0x2u)));
  return float(y >> 8) * (1.f / 16777216.f);
}

// The seed of decision `dimension` of pixel (x, y) in the sequences the
// renderer's `seed` chooses: the same for every sample of the pixel, so
// its samples form one scrambled sequence. Another renderer seed scrambles
// every sequence independently; 0 keeps the ones images were always made
// with.
inline uint32_t sequenceSeed(
    uint32_t x, uint32_t y, uint32_t dimension, uint32_t rendererSeed)
{
  uint32_t decision = mixBits(dimension + 0x632be5abu);
  if (rendererSeed != 0)
    decision = mixBits(decision ^ mixBits(rendererSeed ^ 0x5bd1e995u));
  return mixBits(x * 0x9e3779b9u ^ mixBits(y ^ decision));
}

// Where in pixel (x, y) sample `sample` of the pixel's sequence looks, in
// [0,1)^2 (a centred sample, RenderContext::centredSample(), looks through
// the centre instead).
inline float2 pixelOffset(
    uint32_t x, uint32_t y, uint32_t sample, uint32_t rendererSeed)
{
  return sobolSample2D(sample, sequenceSeed(x, y, 0xffff0000u, rendererSeed));
}

// The point on the lens (depth of field) sample `sample` of pixel (x, y)
// passes through, in [0,1)^2.
inline float2 lensSample(
    uint32_t x, uint32_t y, uint32_t sample, uint32_t rendererSeed)
{
  return sobolSample2D(sample, sequenceSeed(x, y, 0xffff0001u, rendererSeed));
}

} // namespace prism
