// Which light next-event estimation samples: chosen in proportion to the
// light's emitted power, so a dim fill light does not take half the shadow
// rays from the sun. Part of the choice stays uniform, so a light whose
// power says little about its effect here (a spot aimed at the camera's
// corner of the scene) is never starved.
#pragma once

#include "PlacedLight.h"

#include <memory>
#include <vector>

namespace prism {

class LightSelector
{
 public:
  // `sceneRadius` turns infinite lights' power per cross-section into
  // power through the scene.
  void build(const std::vector<std::unique_ptr<PlacedLight>> &lights,
      float sceneRadius);

  bool empty() const
  {
    return m_cdf.empty();
  }
  // The light for `u` in [0,1) and the probability it was chosen with.
  size_t pick(float u, float &probability) const;
  // The probability pick() chooses light `index`.
  float probability(size_t index) const
  {
    return m_probability[index];
  }

 private:
  std::vector<float> m_probability;
  std::vector<float> m_cdf; // m_cdf[i]: probability of lights 0..i
};

} // namespace prism
