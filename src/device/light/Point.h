// The point light (KHR_LIGHT_POINT), a sphere light when radius > 0: an
// isotropic emitter whose brightness is the first of intensity (W/sr),
// power (W) or radiance (W/sr/m^2) set (spec 5.7.3).
#pragma once

#include "Light.h"

namespace prism::light {

class Point : public Light
{
 public:
  explicit Point(DeviceState &device);

  void finalize() override;
  std::unique_ptr<PlacedLight> place(
      const mat3x4 &worldFromObject) const override;

  // Intensity in every direction after the precedence (W/sr).
  float intensity() const
  {
    return m_intensity;
  }

 protected:
  void commitParameters() override;

 private:
  float3 m_position{0.f, 0.f, 0.f};
  float m_radius{0.f};
  Brightness m_brightness;
  float m_intensity{1.f};
  float m_decay{2.f}; // PRISM_LIGHT_DECAY
};

} // namespace prism::light
