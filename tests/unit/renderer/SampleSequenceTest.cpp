// The path tracer's sample sequence: every prefix of 2^k samples is
// stratified in every elementary interval, scrambling decorrelates seeds,
// and the points are uniform.
#include "renderer/SampleSequence.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace prism {
namespace {

// Whether the first 2^k points of `seed` put exactly one point in each cell
// of every 2^a x 2^(k-a) grid (a (0,k,2)-net in base 2).
bool isNet(uint32_t seed, int k)
{
  const uint32_t n = 1u << k;
  for (int a = 0; a <= k; a++) {
    const uint32_t cols = 1u << a, rows = 1u << (k - a);
    std::vector<int> cells(n, 0);
    for (uint32_t i = 0; i < n; i++) {
      const float2 p = sobolSample2D(i, seed);
      const uint32_t cx = uint32_t(p.x * float(cols));
      const uint32_t cy = uint32_t(p.y * float(rows));
      if (cx >= cols || cy >= rows || ++cells[cy * cols + cx] > 1)
        return false;
    }
  }
  return true;
}

TEST(SampleSequence, ReverseBitsMirrorsEveryBit)
{
  uint32_t value = 0x12345679u;
  for (int n = 0; n < 4096; n++) {
    value = value * 1664525u + 1013904223u;
    uint32_t mirrored = 0;
    for (int b = 0; b < 32; b++)
      mirrored |= ((value >> b) & 1u) << (31 - b);
    ASSERT_EQ(reverseBits(value), mirrored) << std::hex << value;
  }
  EXPECT_EQ(reverseBits(1u), 0x80000000u);
  EXPECT_EQ(reverseBits(0xffu), 0xff000000u);
}

TEST(SampleSequence, SecondDimensionFollowsItsDirectionNumbers)
{
  // Sobol's definition: XOR of the direction numbers v_j (v_0 = 1/2,
  // v_j = v_(j-1) ^ (v_(j-1) >> 1)) of the index's set bits j.
  uint32_t direction[32];
  uint32_t v = 0x80000000u;
  for (int j = 0; j < 32; j++, v ^= v >> 1)
    direction[j] = v;
  uint32_t index = 0x2545f491u;
  for (int n = 0; n < 4096; n++) {
    index = n < 256 ? uint32_t(n) : index * 1664525u + 1013904223u;
    uint32_t expected = 0;
    for (int j = 0; j < 32; j++)
      if (index & (1u << j))
        expected ^= direction[j];
    ASSERT_EQ(sobolDimension1(index), expected) << std::hex << index;
  }
}

TEST(SampleSequence, EveryPowerOfTwoPrefixIsStratified)
{
  for (uint32_t pixel = 0; pixel < 32; pixel++) {
    const uint32_t seed =
        sequenceSeed(pixel, 7 * pixel + 3, pixel % 5, pixel % 3);
    for (int k = 0; k <= 10; k++)
      EXPECT_TRUE(isNet(seed, k)) << "seed " << seed << ", 2^" << k;
  }
}

TEST(SampleSequence, ScramblingDecorrelatesSeeds)
{
  // Same sample index, neighbouring pixels, dimensions or renderer seeds:
  // the points are
  // independent (their correlation over many indices is near zero), unlike
  // an unscrambled sequence where they would be equal.
  const int n = 4096;
  for (const auto &[a, b] :
      {std::pair{sequenceSeed(10, 10, 0, 0), sequenceSeed(11, 10, 0, 0)},
          std::pair{sequenceSeed(10, 10, 0, 0), sequenceSeed(10, 10, 1, 0)},
          std::pair{sequenceSeed(10, 10, 0, 0), sequenceSeed(10, 10, 0, 1)},
          std::pair{sequenceSeed(10, 10, 0, 1), sequenceSeed(10, 10, 0, 2)}}) {
    double sa = 0, sb = 0, sab = 0, saa = 0, sbb = 0;
    for (int i = 0; i < n; i++) {
      const double x = sobolSample2D(uint32_t(i), a).x;
      const double y = sobolSample2D(uint32_t(i), b).x;
      sa += x, sb += y, sab += x * y, saa += x * x, sbb += y * y;
    }
    const double cov = sab / n - (sa / n) * (sb / n);
    const double corr =
        cov
        / std::sqrt((saa / n - sa * sa / n / n) * (sbb / n - sb * sb / n / n));
    EXPECT_LT(std::abs(corr), 0.06) << corr; // ~4 sigma for independence
  }
}

TEST(SampleSequence, RendererSeedZeroKeepsTheSequences)
{
  // Seed 0 is the hash every image was made with before renderers had a
  // seed: references stay valid. Other seeds give other sequences, no
  // seed those of another decision (the ones a pixel offset draws).
  for (uint32_t pixel = 0; pixel < 64; pixel++) {
    const uint32_t x = pixel, y = 3 * pixel + 1, dimension = pixel % 7;
    EXPECT_EQ(sequenceSeed(x, y, dimension, 0),
        mixBits(
            x * 0x9e3779b9u ^ mixBits(y ^ mixBits(dimension + 0x632be5abu))));
    for (uint32_t seed = 1; seed < 8; seed++) {
      EXPECT_NE(sequenceSeed(x, y, dimension, seed),
          sequenceSeed(x, y, dimension, 0));
      for (uint32_t other = 0; other < 8; other++)
        EXPECT_NE(
            sequenceSeed(x, y, dimension, seed), sequenceSeed(x, y, other, 0));
    }
  }
}

TEST(SampleSequence, ShuffledPrefixesDifferAcrossSeeds)
{
  // Each pixel visits the sequence in its own order: the first sample of
  // two pixels is not the same point.
  int same = 0;
  for (uint32_t pixel = 0; pixel < 256; pixel++) {
    const float2 a = sobolSample2D(0, sequenceSeed(pixel, 0, 0, 0));
    const float2 b = sobolSample2D(0, sequenceSeed(pixel + 1, 0, 0, 0));
    same += a == b;
  }
  EXPECT_EQ(same, 0);
}

TEST(SampleSequence, PointsAreUniform)
{
  // Chi-square over 16 x 16 cells, 64k points from many seeds' prefixes
  // of 256: the expected 256 per cell within the 0.001 critical value.
  std::vector<int> cells(256, 0);
  for (uint32_t pixel = 0; pixel < 256; pixel++)
    for (uint32_t i = 0; i < 256; i++) {
      const float2 p = sobolSample2D(i, sequenceSeed(pixel, 1, 2, 0));
      cells[uint32_t(p.y * 16) * 16 + uint32_t(p.x * 16)]++;
    }
  double chi2 = 0;
  for (int c : cells)
    chi2 += (c - 256.0) * (c - 256.0) / 256.0;
  // Stratified points land far more evenly than random ones would.
  EXPECT_LT(chi2, 330.5); // chi-square(255) at 0.001
}

} // namespace
} // namespace prism
