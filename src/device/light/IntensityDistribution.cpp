#include "IntensityDistribution.h"

#include "../array/Array.h"
#include "../array/ElementConversion.h"
#include "Sampling.h"

#include <algorithm>
#include <cmath>

namespace prism::light {

bool IntensityDistribution::assign(const Array &array, const char *&why)
{
  m_values.clear();
  m_averageOverC.clear();
  const size_t gammaCount =
      array.dimensions() == 1 ? array.count() : array.size(0);
  const size_t cCount = array.dimensions() == 1 ? 1 : array.size(1);
  if (gammaCount < 2) {
    why = "needs at least two values along gamma (at 0 and pi)";
    return false;
  }
  std::vector<float> values(gammaCount * cCount);
  convertToFloat(
      array.elementType(), array.begin(), values.size(), 0, values.data());
  for (float v : values) {
    if (!(std::isfinite(v) && v >= 0.f)) {
      why = "has negative or non-finite values";
      return false;
    }
  }
  m_values = std::move(values);
  m_gammaCount = gammaCount;
  m_cCount = cCount;
  // Integrating the bilinear table over C is exact with the mean of its
  // rows: linear interpolation between equally spaced, periodic samples.
  m_averageOverC.assign(gammaCount, 0.f);
  for (size_t g = 0; g < gammaCount; g++) {
    double sum = 0.0;
    for (size_t k = 0; k < cCount; k++)
      sum += m_values[g + k * gammaCount];
    m_averageOverC[g] = float(sum / double(cCount));
  }
  return true;
}

float IntensityDistribution::operator()(float3 local) const
{
  if (m_values.empty())
    return 1.f;
  const float gamma = std::acos(clamp(local.z, -1.f, 1.f));
  const float g = gamma / kPi * float(m_gammaCount - 1);
  const size_t g0 = std::min(size_t(max(g, 0.f)), m_gammaCount - 2);
  const float fg = clamp(g - float(g0), 0.f, 1.f);
  auto alongGamma = [&](size_t k) {
    const float *row = &m_values[k * m_gammaCount];
    return lerp(row[g0], row[g0 + 1], fg);
  };
  if (m_cCount == 1)
    return alongGamma(0);
  // C in [0, 2 pi) from +x towards +y; rows wrap around.
  float c = std::atan2(local.y, local.x);
  c = c < 0.f ? c + 2.f * kPi : c;
  const float scaled = c / (2.f * kPi) * float(m_cCount);
  const size_t k0 = std::min(size_t(max(scaled, 0.f)), m_cCount - 1);
  const float fc = clamp(scaled - float(k0), 0.f, 1.f);
  return lerp(alongGamma(k0), alongGamma((k0 + 1) % m_cCount), fc);
}

double IntensityDistribution::integral(
    const std::function<double(double gamma)> &weight,
    std::vector<double> breakpoints) const
{
  const double step = kPiDouble / double(m_gammaCount - 1);
  for (size_t g = 1; g + 1 < m_gammaCount; g++)
    breakpoints.push_back(double(g) * step);
  return integrateOverSphere(
      [&](double gamma) {
        const double x = gamma / step;
        const size_t g0 = std::min(size_t(std::max(x, 0.0)), m_gammaCount - 2);
        const double f = std::clamp(x - double(g0), 0.0, 1.0);
        const double average =
            (1.0 - f) * m_averageOverC[g0] + f * m_averageOverC[g0 + 1];
        return average * weight(gamma);
      },
      std::move(breakpoints));
}

} // namespace prism::light
