#include "LightSelector.h"

#include "../math/Luminance.h"

#include <algorithm>
#include <cmath>

namespace prism {
namespace {

// The share of every choice made uniformly among the lights.
constexpr float kUniformShare = 0.1f;

} // namespace

void LightSelector::build(
    const std::vector<std::unique_ptr<PlacedLight>> &lights, float sceneRadius)
{
  m_probability.assign(lights.size(), 0.f);
  m_cdf.clear();
  if (lights.empty())
    return;
  const float crossSection =
      3.14159265f * std::max(sceneRadius * sceneRadius, 1e-12f);
  std::vector<double> weight(lights.size(), 0.0);
  double total = 0.0;
  for (size_t i = 0; i < lights.size(); i++) {
    float w = std::max(luminance(lights[i]->power()), 0.f);
    if (lights[i]->isInfinite())
      w *= crossSection;
    weight[i] = std::isfinite(w) ? w : 0.0;
    total += weight[i];
  }
  const float uniform = 1.f / float(lights.size());
  const float powerShare = total > 0.0 ? 1.f - kUniformShare : 0.f;
  const float uniformShare = 1.f - powerShare;
  double sum = 0.0;
  for (size_t i = 0; i < lights.size(); i++) {
    const float p =
        uniformShare * uniform
        + (total > 0.0 ? powerShare * float(weight[i] / total) : 0.f);
    m_probability[i] = p;
    sum += p;
    m_cdf.push_back(float(sum));
  }
  m_cdf.back() = 1.f; // whatever rounding did, u < 1 picks a light
}

size_t LightSelector::pick(float u, float &probability) const
{
  const size_t index = std::min(
      size_t(std::upper_bound(m_cdf.begin(), m_cdf.end(), u) - m_cdf.begin()),
      m_cdf.size() - 1);
  probability = m_probability[index];
  return index;
}

} // namespace prism
