#include "Directional.h"

#include "Sampling.h"

#include <cmath>
#include <limits>

namespace prism::light {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// angularDiameter 0: one direction, a delta light.
class PlacedParallel : public PlacedLight
{
 public:
  PlacedParallel(float3 towardsLight, float3 irradiance)
      : m_towardsLight(towardsLight), m_irradiance(irradiance)
  {}

  LightSample sample(const float3 &, const float2 &) const override
  {
    return {m_towardsLight, kInfinity, m_irradiance, 1.f, true};
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
  bool isInfinite() const override
  {
    return true;
  }
  float3 power() const override
  {
    return m_irradiance;
  }

 private:
  float3 m_towardsLight;
  float3 m_irradiance; // W/m^2, color included
};

// angularDiameter > 0: a disk of uniform radiance at infinity, sampled
// uniformly in its cone of directions.
class PlacedDisk : public PlacedLight
{
 public:
  PlacedDisk(
      float3 towardsLight, float capHeight, float3 radiance, float3 irradiance)
      : m_frame(LocalFrame::around(towardsLight)),
        m_capHeight(capHeight),
        m_pdf(uniformCapPdf(capHeight)),
        m_radiance(radiance),
        m_irradiance(irradiance)
  {}

  LightSample sample(const float3 &, const float2 &u) const override
  {
    const float3 direction =
        normalize(m_frame.toWorld(sampleUniformCap(u, m_capHeight)));
    return {direction, kInfinity, m_radiance, m_pdf, false};
  }
  float3 radianceAlong(const float3 &,
      const float3 &direction,
      float &distance,
      float &pdf) const override
  {
    distance = kInfinity;
    if (!insideCap(direction, m_frame.z, m_capHeight)) {
      pdf = 0.f;
      return {0.f, 0.f, 0.f};
    }
    pdf = m_pdf;
    return m_radiance;
  }
  bool isInfinite() const override
  {
    return true;
  }
  float3 power() const override
  {
    return m_irradiance;
  }

 private:
  LocalFrame m_frame; // z towards the light
  float m_capHeight;  // 1 - cos(angularDiameter / 2)
  float m_pdf;
  float3 m_radiance; // W/sr/m^2, color included
  float3 m_irradiance;
};

} // namespace

Directional::Directional(DeviceState &device) : Light(device, "directional") {}

void Directional::commitParameters()
{
  Light::commitParameters();
  m_direction = readDirection("direction");
  m_angularDiameter = readNonNegative("angularDiameter");
  if (m_angularDiameter > kPi) {
    // A disk wider than a hemisphere has no meaning as a distant source.
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'angularDiameter' (%g) is more than pi; using pi",
        m_angularDiameter);
    m_angularDiameter = kPi;
  }
  m_brightness = readBrightness({"irradiance", "radiance"});
}

void Directional::finalize()
{
  // A disk of angular radius a and radiance L gives a facing plane
  // E = integral of L cos over the cap = pi L sin^2(a), exactly.
  const float sinRadius = std::sin(0.5f * m_angularDiameter);
  const float cosineWeightedSolidAngle = kPi * sinRadius * sinRadius;
  if (m_brightness.source == 0) {
    m_irradiance = m_brightness.value;
    m_radiance =
        m_angularDiameter > 0.f ? m_irradiance / cosineWeightedSolidAngle : 0.f;
  } else {
    // Radiance of a zero-size disk emits nothing (spec 5.7.1 note).
    m_radiance = m_angularDiameter > 0.f ? m_brightness.value : 0.f;
    m_irradiance = m_radiance * cosineWeightedSolidAngle;
  }
}

std::unique_ptr<PlacedLight> Directional::place(
    const mat3x4 &worldFromObject) const
{
  if (!isValid())
    return nullptr;
  const float3 towardsLight = -transformUnit(worldFromObject, m_direction);
  std::unique_ptr<PlacedLight> placed;
  if (m_angularDiameter > 0.f) {
    placed = std::make_unique<PlacedDisk>(towardsLight,
        oneMinusCos(0.5f * m_angularDiameter),
        m_color * m_radiance,
        m_color * m_irradiance);
  } else {
    placed =
        std::make_unique<PlacedParallel>(towardsLight, m_color * m_irradiance);
  }
  placeShared(*placed);
  return placed;
}

} // namespace prism::light
