// The hashed random numbers: in [0, 1), uniform, and independent across
// seeds and positions in a stream.
#include "renderer/SampleHash.h"

#include "../shading/ShadingTestUtil.h"

#include <gtest/gtest.h>

#include <vector>

namespace prism {
namespace {

TEST(HashedStream, NumbersAreUniformInTheUnitInterval)
{
  constexpr int kBins = 64, kCount = 64000;
  std::vector<double> counts(kBins, 0.0), expected(kBins, kCount / kBins);
  for (uint32_t seed = 0; seed < 64; seed++) {
    HashedStream stream(seed);
    for (int i = 0; i < kCount / 64; i++) {
      const float u = stream.next();
      ASSERT_GE(u, 0.f);
      ASSERT_LT(u, 1.f);
      counts[int(u * kBins)]++;
    }
  }
  const test::ChiSquare chi = test::chiSquare(counts, expected);
  EXPECT_LT(chi.statistic, chi.critical);
}

TEST(HashedStream, SuccessiveNumbersAndSeedsAreUncorrelated)
{
  // The correlation of (u_n, u_n+1) within streams and of the first
  // numbers of neighbouring seeds: both near 0 for independent numbers
  // (standard error 1/sqrt(n), here about 0.004).
  constexpr int kCount = 65536;
  double within = 0.0, across = 0.0;
  for (uint32_t seed = 0; seed < kCount; seed++) {
    HashedStream stream(seed), neighbour(seed + 1);
    const double a = stream.next() - 0.5, b = stream.next() - 0.5;
    within += a * b;
    across += a * (neighbour.next() - 0.5);
  }
  // Covariance over the variance of a uniform number (1/12).
  EXPECT_NEAR(12.0 * within / kCount, 0.0, 0.02);
  EXPECT_NEAR(12.0 * across / kCount, 0.0, 0.02);
}

TEST(HashedSample2D, CoordinatesAreUniformAndIndependent)
{
  constexpr int kBins = 8, kCount = 64000;
  std::vector<double> counts(kBins * kBins, 0.0),
      expected(kBins * kBins, double(kCount) / (kBins * kBins));
  for (int i = 0; i < kCount; i++) {
    const float2 p = hashedSample2D(uint32_t(i % 256), uint32_t(i / 256), 3, 9);
    counts[int(p.y * kBins) * kBins + int(p.x * kBins)]++;
  }
  const test::ChiSquare chi = test::chiSquare(counts, expected);
  EXPECT_LT(chi.statistic, chi.critical);
}

} // namespace
} // namespace prism
