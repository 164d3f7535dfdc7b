// Piecewise-constant densities over [0,1) and [0,1)^2, sampled by
// inverting their cumulative distributions: the hdri light's importance
// sampling of its image (marginal over rows, conditional within a row).
#pragma once

#include "../math/Vec.h"

#include <cstddef>
#include <limits>
#include <vector>

namespace prism::light {

// A weight as the densities count it: negative and non-finite ones as 0.
inline float usableWeight(float w)
{
  return w > 0.f && w <= std::numeric_limits<float>::max() ? w : 0.f;
}

// A density on [0,1) proportional to `weights` over equal bins.
class Distribution1D
{
 public:
  Distribution1D() = default;
  // Negative and non-finite weights count as 0; all zero gives uniform.
  explicit Distribution1D(const float *weights, size_t count);

  size_t size() const
  {
    return m_weights.size();
  }
  // Sum of the weights over the bin count: the integral of the
  // unnormalised step function over [0,1).
  double integral() const
  {
    return m_integral;
  }
  // x in [0,1) with density pdf(x); `bin` is the bin x falls in.
  float sample(float u, float &pdf, size_t &bin) const;
  // The density at `x` (of bin floor(x * size)).
  float pdf(float x) const;
  // A bin of [begin, end) chosen in proportion to the weights there (a
  // range of zero weights: uniformly), and in `u` what is left of it.
  size_t sampleBetween(float &u, size_t begin, size_t end) const;

 private:
  size_t binOf(float x) const;

  std::vector<float> m_weights;
  std::vector<double> m_cdf; // size() + 1 entries, 0 ... 1
  double m_integral{0.0};
};

// A density on [0,1)^2 proportional to a width x height grid of weights,
// element (i, j) at weights[i + j * width]; x runs along the width.
class Distribution2D
{
 public:
  Distribution2D() = default;
  Distribution2D(const float *weights, size_t width, size_t height);

  bool empty() const
  {
    return m_rows.empty();
  }
  // A point of [0,1)^2 and its density.
  float2 sample(float2 u, float &pdf) const;
  float pdf(float2 p) const;
  // The mean weight (0: all weights were 0 and sampling is uniform).
  double integral() const
  {
    return m_marginal.integral();
  }
  // Row j's density along x.
  const Distribution1D &row(size_t j) const
  {
    return m_rows[j];
  }

 private:
  std::vector<Distribution1D> m_rows; // conditional densities along x
  Distribution1D m_marginal;          // density of the row (y)
};

} // namespace prism::light
