// The path tracer's random streams: one seed per pixel and sample, a pair
// per stream. Every input matters, and the numbers are uniform in 1D and 2D
// (chi-square at significance 0.001) and uncorrelated across streams and
// between a pair's two numbers.
#include "renderer/SampleHash.h"

#include "../shading/ShadingTestUtil.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace prism;

TEST(SampleHash, EveryInputChangesTheNumbers)
{
  const uint32_t seed = pathSeed(12, 34, 5);
  EXPECT_EQ(seed, pathSeed(12, 34, 5));
  int equal = 0;
  for (uint32_t other : {pathSeed(13, 34, 5),
           pathSeed(12, 35, 5),
           pathSeed(12, 34, 6),
           pathSeed(34, 12, 5)}) {
    for (uint32_t stream = 0; stream < 64; stream++)
      equal +=
          seededSample2D(other, stream).x == seededSample2D(seed, stream).x;
  }
  for (uint32_t stream = 1; stream < 64; stream++)
    equal += seededSample2D(seed, stream).x == seededSample2D(seed, 0).x;
  EXPECT_LE(equal, 1);
}

TEST(SampleHash, StreamsAreUniformAcrossPixelsAndSamples)
{
  constexpr int kBins = 100;
  std::vector<double> first(kBins, 0.0), deep(kBins, 0.0), second(kBins, 0.0);
  int n = 0;
  for (uint32_t y = 0; y < 128; y++) {
    for (uint32_t x = 0; x < 128; x++) {
      for (uint32_t s = 0; s < 4; s++) {
        const uint32_t seed = pathSeed(x, y, s);
        first[int(seededSample2D(seed, 0).x * kBins)] += 1.0;
        deep[int(seededSample2D(seed, 0x10000u + 97u * 7u).x * kBins)] += 1.0;
        second[int(seededSample2D(seed, 3).y * kBins)] += 1.0;
        n++;
      }
    }
  }
  const std::vector<double> expected(kBins, double(n) / kBins);
  EXPECT_TRUE(test::passesChiSquare(first, expected));
  EXPECT_TRUE(test::passesChiSquare(deep, expected));
  EXPECT_TRUE(test::passesChiSquare(second, expected));
}

TEST(SampleHash, PairsAreUniformIn2DAndStreamsUncorrelated)
{
  constexpr int kBins = 16;
  constexpr int kCount = 160000;
  std::vector<double> counts(kBins * kBins, 0.0);
  double acrossStreams = 0.0, withinPair = 0.0;
  for (int i = 0; i < kCount; i++) {
    const uint32_t seed = pathSeed(uint32_t(i % 400), uint32_t(i / 400), 2);
    const float2 u = seededSample2D(seed, 5);
    counts[int(u.y * kBins) * kBins + int(u.x * kBins)] += 1.0;
    acrossStreams += (u.x - 0.5) * (seededSample2D(seed, 6).x - 0.5);
    withinPair += (u.x - 0.5) * (u.y - 0.5);
  }
  const std::vector<double> expected(
      kBins * kBins, double(kCount) / (kBins * kBins));
  EXPECT_TRUE(test::passesChiSquare(counts, expected));
  // Each product has standard deviation 1/12: 5 sigma of the mean.
  const double limit = 5.0 / 12.0 / std::sqrt(double(kCount));
  EXPECT_LT(std::abs(acrossStreams / kCount), limit);
  EXPECT_LT(std::abs(withinPair / kCount), limit);
}
