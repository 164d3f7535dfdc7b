// The directional light (KHR_LIGHT_DIRECTIONAL): light from infinitely far
// away, arriving along `direction` or, with angularDiameter > 0, from a disk
// of that apparent size (a sun with soft shadows). Brightness: irradiance
// (W/m^2 on a plane facing the light), else radiance (W/sr/m^2 of the disk);
// irradiance wins when both are set (spec 5.7.1).
#pragma once

#include "Light.h"

namespace prism::light {

class Directional : public Light
{
 public:
  explicit Directional(DeviceState &device);

  void finalize() override;
  std::unique_ptr<PlacedLight> place(
      const mat3x4 &worldFromObject) const override;

  // Irradiance on a plane facing the light (W/m^2).
  float irradiance() const
  {
    return m_irradiance;
  }
  // Radiance of the disk (W/sr/m^2); 0 for a zero angular diameter.
  float radiance() const
  {
    return m_radiance;
  }

 protected:
  void commitParameters() override;

 private:
  float3 m_direction{0.f, 0.f, -1.f}; // unit, the way the light travels
  float m_angularDiameter{0.f};
  Brightness m_brightness;
  float m_irradiance{1.f};
  float m_radiance{0.f};
};

} // namespace prism::light
