#include "Ring.h"

#include "Sampling.h"

#include <cmath>
#include <limits>

namespace prism::light {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
// Keeps a photometric ring's radiance finite at grazing angles.
constexpr float kMinCosine = 1e-6f;

// The angular part shared by the disk and its zero-radius limit.
struct RingEmission
{
  LocalFrame frame; // z the axis, x the C0 half-plane
  ConeFalloff falloff;
  std::shared_ptr<const IntensityDistribution> distribution;
  float3 intensity; // along the axis, W/sr, color included
  float3 power;

  // Intensity (W/sr) towards the unit `out`.
  float3 intensityTowards(const float3 &out) const
  {
    const float cosAxis = dot(out, frame.z);
    const float profile = falloff(cosAxis);
    if (!(profile > 0.f))
      return {0.f, 0.f, 0.f};
    const float shape =
        distribution ? (*distribution)(frame.toLocal(out)) : max(cosAxis, 0.f);
    return intensity * (shape * profile);
  }
};

class PlacedRingPoint : public PlacedLight
{
 public:
  PlacedRingPoint(float3 position, RingEmission emission)
      : m_position(position), m_emission(std::move(emission))
  {}

  LightSample sample(const float3 &point, const float2 &) const override
  {
    const float3 toLight = m_position - point;
    const float distance2 = lengthSquared(toLight);
    if (!(distance2 > 0.f))
      return {};
    const float distance = std::sqrt(distance2);
    const float3 direction = toLight / distance;
    return {direction,
        distance,
        m_emission.intensityTowards(-direction) / distance2,
        1.f,
        true};
  }
  float3 radianceAlong(const float3 &,
      const float3 &,
      float &distance,
      float &pdf) const override
  {
    distance = kInfinity;
    pdf = 0.f;
    return {0.f, 0.f, 0.f};
  }
  bool isDelta() const override
  {
    return true;
  }
  float3 power() const override
  {
    return m_emission.power;
  }

 private:
  float3 m_position;
  RingEmission m_emission;
};

// The disk or annulus, sampled uniformly by area.
class PlacedRingDisk : public PlacedLight
{
 public:
  PlacedRingDisk(
      float3 center, float radius, float innerRadius, RingEmission emission)
      : m_center(center),
        m_radius(radius),
        m_innerRadius(innerRadius),
        m_area(kPi * (radius * radius - innerRadius * innerRadius)),
        m_emission(std::move(emission))
  {}

  LightSample sample(const float3 &point, const float2 &u) const override
  {
    // r^2 uniform between the radii is uniform in area.
    const float inner2 = m_innerRadius * m_innerRadius;
    const float r = std::sqrt(inner2 + u.x * (m_radius * m_radius - inner2));
    const float phi = 2.f * kPi * u.y;
    const LocalFrame &frame = m_emission.frame;
    const float3 onDisk =
        m_center + frame.toWorld({r * std::cos(phi), r * std::sin(phi), 0.f});
    const float3 offset = onDisk - point;
    const float distance2 = lengthSquared(offset);
    if (!(distance2 > 0.f))
      return {};
    LightSample s;
    s.distance = std::sqrt(distance2);
    s.direction = offset / s.distance;
    s.pdf = areaPdf(s.direction, s.distance);
    if (!(s.pdf > 0.f) || !std::isfinite(s.pdf))
      return {};
    s.radiance = emitted(-s.direction);
    return s;
  }

  float3 radianceAlong(const float3 &point,
      const float3 &direction,
      float &distance,
      float &pdf) const override
  {
    distance = kInfinity;
    pdf = 0.f;
    const float3 &axis = m_emission.frame.z;
    const float along = dot(direction, axis);
    if (along == 0.f)
      return {0.f, 0.f, 0.f};
    const float t = dot(m_center - point, axis) / along;
    if (!(t > 0.f))
      return {0.f, 0.f, 0.f};
    const float r2 = lengthSquared(point + direction * t - m_center);
    if (r2 > m_radius * m_radius || r2 < m_innerRadius * m_innerRadius)
      return {0.f, 0.f, 0.f};
    distance = t;
    pdf = areaPdf(direction, t);
    return emitted(-direction);
  }

  float3 power() const override
  {
    return m_emission.power;
  }
  bool bounds(LightBounds &out) const override
  {
    out = {m_center, m_radius};
    return true;
  }

 private:
  float areaPdf(const float3 &direction, float distance) const
  {
    const float cosine = std::abs(dot(direction, m_emission.frame.z));
    return cosine > 0.f ? distance * distance / (m_area * cosine) : 0.f;
  }
  // L = I(w) / (A |cos|): uniform radiance for the cosine shape.
  float3 emitted(const float3 &out) const
  {
    const float cosine = std::abs(dot(out, m_emission.frame.z));
    return m_emission.intensityTowards(out)
           / (m_area * max(cosine, kMinCosine));
  }

  float3 m_center;
  float m_radius, m_innerRadius;
  float m_area;
  RingEmission m_emission;
};

} // namespace

Ring::Ring(DeviceState &device) : Light(device, "ring") {}

void Ring::commitParameters()
{
  Light::commitParameters();
  m_position = readFinite("position");
  m_direction = readDirection("direction");
  m_falloff = readConeFalloff();
  m_radius = readNonNegative("radius");
  m_innerRadius = readNonNegative("innerRadius");
  if (m_innerRadius > 0.f && !(m_innerRadius < m_radius)) {
    invalidate("'innerRadius' (%g) must be smaller than 'radius' (%g)",
        m_innerRadius,
        m_radius);
  }
  m_brightness = readBrightness({"intensity", "power", "radiance"});
  m_distributionArray = readIntensityDistribution();
  m_c0 = readDirection("c0");
  if (m_distributionArray && lengthSquared(cross(m_c0, m_direction)) < 1e-12f) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'c0' is parallel to 'direction'; the C0 half-plane is arbitrary");
  }
}

void Ring::finalize()
{
  m_distribution = buildIntensityDistribution(m_distributionArray);
  m_distributionArray = nullptr;
  const ConeFalloff falloff = m_falloff;
  const std::vector<double> kinks = {
      falloff.innerAngle(), falloff.halfAngle(), 0.5 * kPiDouble};
  if (m_distribution) {
    m_emissionIntegral = m_distribution->integral(
        [&](double gamma) { return falloff.atAngle(gamma); }, kinks);
  } else {
    // The cosine shape within the cone: the same cosine-weighted integral
    // the spot light's power is defined by.
    m_emissionIntegral = falloff.integral(true);
  }
}

std::unique_ptr<PlacedLight> Ring::place(const mat3x4 &worldFromObject) const
{
  if (!isValid())
    return nullptr;
  // Position and axes move; the radii are sizes and stay (spec 5.7).
  const float3 position = transformPoint(worldFromObject, m_position);
  const float3 axis = transformUnit(worldFromObject, m_direction);
  const float3 c0 = transformUnit(worldFromObject, m_c0);
  const float area =
      kPi * (m_radius * m_radius - m_innerRadius * m_innerRadius);

  float intensity = m_brightness.value;
  if (m_brightness.source == 1) {
    intensity = m_emissionIntegral > 0.0
                    ? float(m_brightness.value / m_emissionIntegral)
                    : 0.f;
  } else if (m_brightness.source == 2) {
    // Radiance over the disk's area; nothing for radius 0 (spec).
    intensity = m_brightness.value * area;
  }
  RingEmission emission{LocalFrame::around(axis, c0),
      m_falloff,
      m_distribution,
      m_color * intensity,
      m_color * (intensity * float(m_emissionIntegral))};
  std::unique_ptr<PlacedLight> placed;
  if (area > 0.f) {
    placed = std::make_unique<PlacedRingDisk>(
        position, m_radius, m_innerRadius, std::move(emission));
  } else {
    placed = std::make_unique<PlacedRingPoint>(position, std::move(emission));
  }
  placeShared(*placed);
  return placed;
}

} // namespace prism::light
