// The ring light (KHR_LIGHT_RING): a disk (an annulus with innerRadius) at
// `position` facing `direction`, emitting into a cone with the spot light's
// smoothstep falloff (spec 5.7.5). It is an area light, so without
// intensityDistribution its radiance is uniform and its intensity falls
// with the cosine; `intensity` (W/sr) is the intensity along the axis.
// With a table (C-gamma around `direction`, C0 along c0) the table gives
// the intensity's angular shape instead of the cosine, still within the
// cone. radius 0 makes it a delta light with the same intensity.
#pragma once

#include "Light.h"

namespace prism::light {

class Ring : public Light
{
 public:
  explicit Ring(DeviceState &device);

  void finalize() override;
  std::unique_ptr<PlacedLight> place(
      const mat3x4 &worldFromObject) const override;

 protected:
  void commitParameters() override;

 private:
  float3 m_position{0.f, 0.f, 0.f};
  float3 m_direction{0.f, 0.f, -1.f}; // unit
  float3 m_c0{1.f, 0.f, 0.f};         // unit
  ConeFalloff m_falloff;
  float m_radius{0.f};
  float m_innerRadius{0.f};
  Brightness m_brightness;
  Array *m_distributionArray{nullptr}; // until finalize(), see Light.h
  std::shared_ptr<const IntensityDistribution> m_distribution;
  // Integral over the sphere of the intensity per unit `intensity` (sr).
  double m_emissionIntegral{0.0};
};

} // namespace prism::light
