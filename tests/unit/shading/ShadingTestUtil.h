// Statistics and random numbers shared by the shading tests.
#pragma once

#include "renderer/SampleHash.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace prism {

// Independent random numbers for test case `key`, set `set`, by dimension,
// from the renderer's hash (renderer/SampleHash.h): the device's one
// random-number module.
class RandomSequence
{
 public:
  RandomSequence(uint2 key, uint32_t set, uint32_t) : m_key(key), m_set(set) {}
  float get1D(uint32_t dimension) const
  {
    return get2D(dimension).x;
  }
  float2 get2D(uint32_t dimension) const
  {
    return hashedSample2D(m_key.x, m_key.y, m_set, dimension);
  }

 private:
  uint2 m_key;
  uint32_t m_set;
};

// The i-th of a set of independent uniform points on the unit square.
inline float2 uniform2(uint32_t i)
{
  return RandomSequence({i, 0}, 0, 0).get2D(0);
}

} // namespace prism

namespace prism::test {

// Upper critical value of the chi-square distribution with `dof` degrees of
// freedom at significance 0.001 (Wilson-Hilferty; within 1% for dof >= 10).
inline double chiSquareCritical(int dof)
{
  const double k = dof;
  const double z = 3.0902; // standard normal quantile at 0.999
  const double a = 2.0 / (9.0 * k);
  const double c = 1.0 - a + z * std::sqrt(a);
  return k * c * c * c;
}

struct ChiSquare
{
  double statistic;
  double critical; // at significance 0.001
};

// Pearson's test of counts against expectations; cells expecting fewer than
// 5 counts are pooled so the chi-square approximation holds.
inline ChiSquare chiSquare(
    const std::vector<double> &observed, const std::vector<double> &expected)
{
  double statistic = 0.0, pooledObserved = 0.0, pooledExpected = 0.0;
  int cells = 0;
  for (size_t i = 0; i < observed.size(); i++) {
    if (expected[i] < 5.0) {
      pooledObserved += observed[i];
      pooledExpected += expected[i];
      continue;
    }
    const double d = observed[i] - expected[i];
    statistic += d * d / expected[i];
    cells++;
  }
  if (pooledExpected > 0.0) {
    const double d = pooledObserved - pooledExpected;
    statistic += d * d / pooledExpected;
    cells++;
  }
  return {statistic, chiSquareCritical(cells - 1)};
}

// Passes when the counts are consistent with the expectations at
// significance 0.001; the failure message carries the statistic.
inline ::testing::AssertionResult passesChiSquare(
    const std::vector<double> &observed, const std::vector<double> &expected)
{
  const ChiSquare result = chiSquare(observed, expected);
  if (result.statistic < result.critical)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "chi-square " << result.statistic
                                       << " >= critical " << result.critical;
}

} // namespace prism::test
