#include "Point.h"

#include "Sampling.h"

#include <cmath>
#include <limits>

namespace prism::light {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

enum Source { kIntensity, kPower, kRadiance };

// radius 0: all light leaves one point; irradiance falls with 1/d^2.
class PlacedPoint : public PlacedLight
{
 public:
  PlacedPoint(float3 position, float3 intensity, float decay)
      : m_position(position), m_intensity(intensity), m_decay(decay)
  {}

  LightSample sample(const float3 &point, const float2 &) const override
  {
    const float3 toLight = m_position - point;
    const float distance2 = lengthSquared(toLight);
    if (!(distance2 > 0.f))
      return {};
    const float distance = std::sqrt(distance2);
    return {toLight / distance,
        distance,
        m_intensity * distanceFalloff(distance2, m_decay),
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
    return m_intensity * (4.f * kPi);
  }

 private:
  float3 m_position;
  float3 m_intensity; // W/sr, color included
  float m_decay;      // the falloff's exponent (2: inverse square)
};

// radius > 0: a sphere of uniform radiance, sampled uniformly in the cone of
// directions it subtends, so every sample hits it.
class PlacedSphere : public PlacedLight
{
 public:
  PlacedSphere(
      float3 center, float radius, float3 radiance, float3 power, float decay)
      : m_center(center),
        m_radius(radius),
        m_radiance(radiance),
        m_power(power),
        m_decay(decay)
  {}

  LightSample sample(const float3 &point, const float2 &u) const override
  {
    float capHeight = 0.f;
    float distanceToCenter = 0.f;
    if (!cone(point, capHeight, distanceToCenter))
      return {};
    const LocalFrame frame =
        LocalFrame::around((m_center - point) / distanceToCenter);
    const float3 local = sampleUniformCap(u, capHeight);
    const float3 direction = normalize(frame.toWorld(local));
    LightSample s;
    s.direction = direction;
    s.distance = entryDistance(point, direction);
    s.radiance = m_radiance * decayScale(distanceToCenter);
    s.pdf = uniformCapPdf(capHeight);
    return s;
  }
  float3 radianceAlong(const float3 &point,
      const float3 &direction,
      float &distance,
      float &pdf) const override
  {
    distance = kInfinity;
    pdf = 0.f;
    float capHeight = 0.f;
    float distanceToCenter = 0.f;
    if (!cone(point, capHeight, distanceToCenter))
      return {0.f, 0.f, 0.f};
    // Inside the subtended cone exactly when the ray hits the sphere.
    const float3 axis = (m_center - point) / distanceToCenter;
    if (!insideCap(direction, axis, capHeight))
      return {0.f, 0.f, 0.f};
    distance = entryDistance(point, direction);
    pdf = uniformCapPdf(capHeight);
    return m_radiance * decayScale(distanceToCenter);
  }
  float3 power() const override
  {
    return m_power;
  }
  bool bounds(LightBounds &out) const override
  {
    out = {m_center, m_radius};
    return true;
  }

 private:
  // A sphere's light falls with the inverse square by itself: another
  // decay scales its radiance by d^(2 - decay), d from its centre.
  float decayScale(float distanceToCenter) const
  {
    const float d2 = distanceToCenter * distanceToCenter;
    return m_decay == 2.f ? 1.f : d2 * distanceFalloff(d2, m_decay);
  }
  // The cone of directions from `point` that hit the sphere; false from
  // inside, where the outward-emitting surface is not seen.
  bool cone(const float3 &point, float &capHeight, float &distance) const
  {
    const float distance2 = lengthSquared(m_center - point);
    const float radius2 = m_radius * m_radius;
    if (!(distance2 > radius2))
      return false;
    distance = std::sqrt(distance2);
    const float sin2 = radius2 / distance2;
    // 1 - cos = sin^2 / (1 + cos) avoids cancellation for small spheres.
    capHeight = sin2 / (1.f + std::sqrt(max(0.f, 1.f - sin2)));
    return true;
  }
  // Where the ray first meets the sphere; the closest approach when it
  // grazes past by rounding.
  float entryDistance(const float3 &point, const float3 &direction) const
  {
    const float3 offset = m_center - point;
    const float along = dot(offset, direction);
    // radius^2 - (distance of the line from the center)^2, without the
    // cancellation of along^2 - |offset|^2 + radius^2.
    const float3 across = offset - direction * along;
    const float h2 = m_radius * m_radius - lengthSquared(across);
    return max(0.f, along - std::sqrt(max(0.f, h2)));
  }

  float3 m_center;
  float m_radius;
  float3 m_radiance; // W/sr/m^2, color included
  float3 m_power;
  float m_decay; // the falloff's exponent (2: inverse square)
};

} // namespace

Point::Point(DeviceState &device) : Light(device, "point") {}

void Point::commitParameters()
{
  Light::commitParameters();
  m_position = readFinite("position");
  m_radius = readNonNegative("radius");
  m_brightness = readBrightness({"intensity", "power", "radiance"});
  m_decay = lightParam<float>("decay");
}

void Point::finalize()
{
  const float value = m_brightness.value;
  switch (m_brightness.source) {
  case kPower:
    // Power is intensity integrated over all 4 pi steradians.
    m_intensity = value / (4.f * kPi);
    break;
  case kRadiance:
    // A sphere of uniform radiance L shows a disk of area pi r^2 from
    // every direction: I = L pi r^2, and nothing at radius 0 (spec).
    m_intensity = value * kPi * m_radius * m_radius;
    break;
  default:
    m_intensity = value;
  }
}

std::unique_ptr<PlacedLight> Point::place(const mat3x4 &worldFromObject) const
{
  if (!isValid())
    return nullptr;
  // Only the position moves: the spec keeps sizes (the radius) and
  // brightness independent of instance transforms.
  const float3 position = transformPoint(worldFromObject, m_position);
  const float3 intensity = m_color * m_intensity;
  std::unique_ptr<PlacedLight> placed;
  if (m_radius > 0.f) {
    const float3 radiance = intensity / (kPi * m_radius * m_radius);
    placed = std::make_unique<PlacedSphere>(
        position, m_radius, radiance, intensity * (4.f * kPi), m_decay);
  } else {
    placed = std::make_unique<PlacedPoint>(position, intensity, m_decay);
  }
  placeShared(*placed);
  return placed;
}

} // namespace prism::light
