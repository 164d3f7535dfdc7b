// The counter-based RNG: determinism per key, independence of keys and
// dimensions, uniformity (chi-square at significance 0.001).
#include "shading/Random.h"

#include "ShadingTestUtil.h"

#include <gtest/gtest.h>

#include <vector>

using namespace prism;

TEST(Random, SameKeyGivesSameNumbers)
{
  const RandomSequence a({12, 34}, 5, 6);
  RandomSequence b({12, 34}, 5, 6);
  for (uint32_t d = 0; d < 1000; d++) {
    EXPECT_EQ(a.get1D(d), b.get1D(d));
    EXPECT_EQ(a.get2D(d), b.get2D(d));
  }
  // Sequential draws are the same numbers, whatever came before.
  for (uint32_t d = 0; d < 100; d++) {
    if (d % 2 == 0)
      EXPECT_EQ(b.next1D(), a.get1D(d));
    else
      EXPECT_EQ(b.next2D(), a.get2D(d));
  }
  EXPECT_EQ(b.dimension(), 100u);
  b.setDimension(7);
  EXPECT_EQ(b.next1D(), a.get1D(7));
}

TEST(Random, EveryKeyComponentMatters)
{
  const RandomSequence base({12, 34}, 5, 6);
  const RandomSequence others[] = {RandomSequence({13, 34}, 5, 6),
      RandomSequence({12, 35}, 5, 6),
      RandomSequence({12, 34}, 6, 6),
      RandomSequence({12, 34}, 5, 7)};
  for (const RandomSequence &other : others) {
    int equal = 0;
    for (uint32_t d = 0; d < 64; d++)
      equal += other.get1D(d) == base.get1D(d);
    EXPECT_LE(equal, 1);
  }
}

TEST(Random, RangeIsHalfOpen)
{
  EXPECT_EQ(unitFloatFromBits(0u), 0.f);
  EXPECT_LT(unitFloatFromBits(0xffffffffu), 1.f);
  const RandomSequence r({1, 2}, 3, 4);
  for (uint32_t d = 0; d < 10000; d++) {
    const float u = r.get1D(d);
    ASSERT_GE(u, 0.f);
    ASSERT_LT(u, 1.f);
  }
}

// The renderer's pattern: one dimension across a block of pixels and
// samples, and many dimensions of one sample.
TEST(Random, ChiSquareUniform1D)
{
  constexpr int kBins = 100;
  std::vector<double> acrossPixels(kBins, 0.0), acrossDimensions(kBins, 0.0);
  int n = 0;
  for (uint32_t y = 0; y < 128; y++) {
    for (uint32_t x = 0; x < 128; x++) {
      for (uint32_t s = 0; s < 4; s++) {
        const RandomSequence r({x, y}, s, 0);
        acrossPixels[int(r.get1D(3) * kBins)] += 1.0;
        acrossDimensions[int(r.get1D(x + 128 * s) * kBins)] += 1.0;
        n++;
      }
    }
  }
  const std::vector<double> expected(kBins, double(n) / kBins);
  EXPECT_TRUE(test::passesChiSquare(acrossPixels, expected));
  EXPECT_TRUE(test::passesChiSquare(acrossDimensions, expected));
}

TEST(Random, ChiSquareUniform2DAndUncorrelated)
{
  constexpr int kBins = 16;
  std::vector<double> counts(kBins * kBins, 0.0);
  double correlation = 0.0;
  constexpr int kCount = 160000;
  for (int i = 0; i < kCount; i++) {
    const RandomSequence r({uint32_t(i % 400), uint32_t(i / 400)}, 0, 9);
    const float2 u = r.get2D(1);
    counts[int(u.y * kBins) * kBins + int(u.x * kBins)] += 1.0;
    // Consecutive dimensions must not correlate.
    correlation += (r.get1D(1) - 0.5) * (r.get1D(2) - 0.5);
  }
  const std::vector<double> expected(
      kBins * kBins, double(kCount) / (kBins * kBins));
  EXPECT_TRUE(test::passesChiSquare(counts, expected));
  // Each product has standard deviation 1/12: 5 sigma of the mean.
  EXPECT_LT(std::abs(correlation / kCount), 5.0 / 12.0 / std::sqrt(kCount));
}
