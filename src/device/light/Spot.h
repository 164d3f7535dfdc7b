// The spot light (KHR_LIGHT_SPOT): a point emitting into a cone, full inside
// openingAngle - 2 falloffAngle and fading to zero at openingAngle by a
// smoothstep (spec 5.7.6). Brightness: intensity (W/sr) on the axis, else
// power (W), which the spec defines as the cosine-weighted integral of the
// intensity over the cone.
#pragma once

#include "ConeFalloff.h"
#include "Light.h"

namespace prism::light {

class Spot : public Light
{
 public:
  explicit Spot(DeviceState &device);

  void finalize() override;
  std::unique_ptr<PlacedLight> place(
      const mat3x4 &worldFromObject) const override;

  // On-axis intensity after the precedence (W/sr).
  float intensity() const
  {
    return m_intensity;
  }
  const ConeFalloff &falloff() const
  {
    return m_falloff;
  }

 protected:
  void commitParameters() override;

 private:
  float3 m_position{0.f, 0.f, 0.f};
  float3 m_direction{0.f, 0.f, -1.f}; // unit
  ConeFalloff m_falloff;
  Brightness m_brightness;
  float m_intensity{1.f};
  float m_decay{2.f};      // PRISM_LIGHT_DECAY
  float m_solidAngle{0.f}; // integral of the profile over the sphere
};

} // namespace prism::light
