#include "Distribution2D.h"

#include <algorithm>
#include <cmath>

namespace prism::light {
namespace {

// The largest float below 1, so samples stay in [0,1).
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

} // namespace

Distribution1D::Distribution1D(const float *weights, size_t count)
    : m_weights(weights, weights + count), m_cdf(count + 1, 0.0)
{
  for (float &w : m_weights)
    w = usableWeight(w);
  double sum = 0.0;
  for (size_t i = 0; i < count; i++) {
    sum += m_weights[i];
    m_cdf[i + 1] = sum;
  }
  if (!(sum > 0.0)) {
    // Nothing to prefer: a uniform density is still a valid one.
    std::fill(m_weights.begin(), m_weights.end(), 1.f);
    for (size_t i = 0; i <= count; i++)
      m_cdf[i] = double(i);
    sum = double(count);
  }
  for (double &c : m_cdf)
    c /= sum;
  m_cdf[count] = 1.0;
  m_integral = count ? sum / double(count) : 0.0;
}

size_t Distribution1D::binOf(float x) const
{
  const size_t n = m_weights.size();
  const float scaled = x * float(n);
  return scaled >= 0.f ? std::min(size_t(scaled), n - 1) : 0;
}

float Distribution1D::sample(float u, float &pdf, size_t &bin) const
{
  const size_t n = m_weights.size();
  // The bin whose cdf interval holds u; zero-weight bins have empty
  // intervals and are never chosen.
  const auto above = std::upper_bound(m_cdf.begin(), m_cdf.end(), double(u));
  bin = size_t(std::clamp<ptrdiff_t>(above - m_cdf.begin() - 1, 0, n - 1));
  const double width = m_cdf[bin + 1] - m_cdf[bin];
  const double offset =
      width > 0.0 ? std::clamp((double(u) - m_cdf[bin]) / width, 0.0, 1.0)
                  : 0.5;
  pdf = float(m_weights[bin] / m_integral);
  return std::min(float((double(bin) + offset) / double(n)), kOneMinusEpsilon);
}

float Distribution1D::pdf(float x) const
{
  return float(m_weights[binOf(x)] / m_integral);
}

size_t Distribution1D::sampleBetween(float &u, size_t begin, size_t end) const
{
  const double low = m_cdf[begin], high = m_cdf[end];
  if (!(high > low)) {
    const float scaled = u * float(end - begin);
    const size_t bin = begin + std::min(size_t(scaled), end - begin - 1);
    u = std::clamp(scaled - float(bin - begin), 0.f, kOneMinusEpsilon);
    return bin;
  }
  const double target = low + double(u) * (high - low);
  const auto above = std::upper_bound(m_cdf.begin() + ptrdiff_t(begin) + 1,
      m_cdf.begin() + ptrdiff_t(end),
      target);
  const size_t bin = size_t(above - m_cdf.begin()) - 1;
  const double width = m_cdf[bin + 1] - m_cdf[bin];
  u = width > 0.0 ? std::clamp(
          float((target - m_cdf[bin]) / width), 0.f, kOneMinusEpsilon)
                  : 0.5f;
  return bin;
}

Distribution2D::Distribution2D(
    const float *weights, size_t width, size_t height)
{
  if (width == 0 || height == 0)
    return;
  m_rows.reserve(height);
  std::vector<float> rowIntegrals(height);
  for (size_t j = 0; j < height; j++) {
    m_rows.emplace_back(weights + j * width, width);
    // A row of zeros became uniform inside its Distribution1D; its share
    // of the marginal stays 0, so it is never chosen.
    double sum = 0.0;
    for (size_t i = 0; i < width; i++)
      sum += usableWeight(weights[i + j * width]);
    rowIntegrals[j] = float(sum / double(width));
  }
  m_marginal = Distribution1D(rowIntegrals.data(), height);
}

float2 Distribution2D::sample(float2 u, float &pdf) const
{
  float pdfY = 0.f, pdfX = 0.f;
  size_t row = 0, column = 0;
  const float y = m_marginal.sample(u.y, pdfY, row);
  const float x = m_rows[row].sample(u.x, pdfX, column);
  pdf = pdfX * pdfY;
  return {x, y};
}

float Distribution2D::pdf(float2 p) const
{
  const size_t height = m_rows.size();
  const float scaled = p.y * float(height);
  const size_t row = scaled >= 0.f ? std::min(size_t(scaled), height - 1) : 0;
  return m_marginal.pdf(p.y) * m_rows[row].pdf(p.x);
}

} // namespace prism::light
