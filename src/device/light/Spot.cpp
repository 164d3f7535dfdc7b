#include "Spot.h"

#include "Sampling.h"

#include <cmath>
#include <limits>

namespace prism::light {
namespace {

class PlacedSpot : public PlacedLight
{
 public:
  PlacedSpot(float3 position,
      float3 axis,
      const ConeFalloff &falloff,
      float3 intensity,
      float3 power,
      float decay)
      : m_position(position),
        m_axis(axis),
        m_falloff(falloff),
        m_intensity(intensity),
        m_power(power),
        m_decay(decay)
  {}

  LightSample sample(const float3 &point, const float2 &) const override
  {
    const float3 toLight = m_position - point;
    const float distance2 = lengthSquared(toLight);
    if (!(distance2 > 0.f))
      return {};
    const float distance = std::sqrt(distance2);
    const float3 direction = toLight / distance;
    const float profile = m_falloff(-dot(direction, m_axis));
    return {direction,
        distance,
        m_intensity * (profile * distanceFalloff(distance2, m_decay)),
        1.f,
        true};
  }
  float3 radianceAlong(const float3 &,
      const float3 &,
      float &distance,
      float &pdf) const override
  {
    distance = std::numeric_limits<float>::infinity();
    pdf = 0.f;
    return {0.f, 0.f, 0.f};
  }
  bool isDelta() const override
  {
    return true;
  }
  float3 power() const override
  {
    return m_power;
  }

 private:
  float3 m_position;
  float3 m_axis; // unit emission axis
  ConeFalloff m_falloff;
  float3 m_intensity; // on the axis, W/sr, color included
  float3 m_power;
  float m_decay; // the falloff's exponent (2: inverse square)
};

} // namespace

Spot::Spot(DeviceState &device) : Light(device, "spot") {}

void Spot::commitParameters()
{
  Light::commitParameters();
  m_position = readFinite("position");
  m_direction = readDirection("direction");
  m_falloff = readConeFalloff();
  m_brightness = readBrightness({"intensity", "power"});
  m_decay = lightParam<float>("decay");
}

void Spot::finalize()
{
  // For choosing lights, the flux actually emitted: the integral of I(w).
  m_solidAngle = float(m_falloff.integral(false));
  m_intensity = m_brightness.value;
  if (m_brightness.source == 1) {
    // Spec 5.7.6: power = integral over the cone of I(w) cos(theta); about
    // pi (1 - cos^2(openingAngle / 2)) I without falloff.
    const double weighted = m_falloff.integral(true);
    m_intensity = weighted > 0.0 ? float(m_brightness.value / weighted) : 0.f;
  }
}

std::unique_ptr<PlacedLight> Spot::place(const mat3x4 &worldFromObject) const
{
  if (!isValid())
    return nullptr;
  const float3 position = transformPoint(worldFromObject, m_position);
  const float3 axis = transformUnit(worldFromObject, m_direction);
  const float3 intensity = m_color * m_intensity;
  const float3 flux = intensity * m_solidAngle;
  auto placed = std::make_unique<PlacedSpot>(
      position, axis, m_falloff, intensity, flux, m_decay);
  placeShared(*placed);
  return placed;
}

} // namespace prism::light
