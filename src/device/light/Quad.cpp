#include "Quad.h"

#include "Sampling.h"

#include <cmath>
#include <limits>

namespace prism::light {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
// Sampling by solid angle (uniform over the spherical quadrilateral the
// quad subtends) has no variance from the 1/d^2 and cosine at the light;
// outside these bounds its arithmetic degrades (a far speck or a point
// almost in the quad's plane) and sampling by area takes over. Float is
// enough: kMinSolidAngleSampling keeps the quads sampled this way large.
constexpr float kMinSphericalArea = 1e-5f;
constexpr float kMaxSphericalArea = 6.f;
// Below this solid angle (estimated from the centre) the 1/d^2 and cosine
// hardly vary over the quad, so sampling by area is as good and costs no
// trigonometry: solid-angle sampling is kept for close, large quads.
constexpr float kMinSolidAngleSampling = 0.3f;
// Keeps a photometric quad's radiance finite at grazing angles.
constexpr float kMinCosine = 1e-6f;

class PlacedQuad : public PlacedLight
{
 public:
  struct Emission
  {
    Quad::Side side;
    float3 radiance; // uniform, color included (no distribution)
    std::shared_ptr<const IntensityDistribution> distribution;
    float3 intensity; // scale of the distribution, color included
    float3 power;
  };

  PlacedQuad(float3 corner, float3 edge1, float3 edge2, Emission emission)
      : m_corner(corner),
        m_edge1(edge1),
        m_edge2(edge2),
        m_normal(cross(edge1, edge2)),
        m_area(length(m_normal)),
        // The spec's front side is edge2 x edge1; C0 lies along edge1.
        m_frame(LocalFrame::around(cross(edge2, edge1) / m_area, edge1)),
        m_emission(std::move(emission))
  {}

  LightSample sample(const float3 &point, const float2 &u) const override
  {
    LightSample s;
    if (!litSide(point))
      return s;
    const Subtended subtended = subtend(point);
    if (subtended.solidAngle > 0.f) {
      // Pick a triangle in proportion to its solid angle, reusing u.x: by
      // selects, as the choice is a coin toss a branch cannot predict.
      const float split = u.x * subtended.solidAngle;
      const float3 *v = subtended.vertices;
      const bool first = split < subtended.area[0];
      const float area = first ? subtended.area[0] : subtended.area[1];
      // At most 1 after rounding.
      const float2 uTriangle{
          min((first ? split : split - subtended.area[0]) / area, 1.f), u.y};
      const float3 direction = sampleSphericalTriangle(
          v[0], first ? v[1] : v[2], first ? v[2] : v[3], area, uTriangle);
      s.direction = normalize(direction);
      const float along = dot(s.direction, m_normal);
      s.distance = along != 0.f
                       ? max(0.f, dot(m_corner - point, m_normal) / along)
                       : 0.f;
      s.pdf = 1.f / subtended.solidAngle;
    } else {
      const float3 onQuad = m_corner + m_edge1 * u.x + m_edge2 * u.y;
      const float3 offset = onQuad - point;
      const float distance2 = lengthSquared(offset);
      if (!(distance2 > 0.f))
        return {};
      s.distance = std::sqrt(distance2);
      s.direction = offset * (1.f / s.distance);
      s.pdf = areaPdf(s.direction, s.distance);
      if (!(s.pdf > 0.f) || !std::isfinite(s.pdf))
        return {};
    }
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
    const float along = dot(direction, m_normal);
    if (along == 0.f)
      return {0.f, 0.f, 0.f};
    const float t = dot(m_corner - point, m_normal) / along;
    if (!(t > 0.f))
      return {0.f, 0.f, 0.f};
    // Parallelogram coordinates of the hit: offset = a edge1 + b edge2.
    const float3 offset = point + direction * t - m_corner;
    const float normal2 = m_area * m_area;
    const float a = dot(cross(offset, m_edge2), m_normal) / normal2;
    const float b = dot(cross(m_edge1, offset), m_normal) / normal2;
    // A rounding's worth of slack, growing with distance over size, so
    // sample()'s own directions at the edges still hit.
    const float slack = 1e-6f * (1.f + t / std::sqrt(m_area));
    if (a < -slack || a > 1.f + slack || b < -slack || b > 1.f + slack)
      return {0.f, 0.f, 0.f};
    distance = t;
    const Subtended subtended = subtend(point);
    pdf = subtended.solidAngle > 0.f ? 1.f / subtended.solidAngle
                                     : areaPdf(direction, t);
    return emitted(-direction);
  }

  float3 power() const override
  {
    return m_emission.power;
  }
  bool bounds(LightBounds &out) const override
  {
    out.center = m_corner + (m_edge1 + m_edge2) * 0.5f;
    // Half the longer diagonal.
    out.radius = 0.5f
                 * std::sqrt(std::max(lengthSquared(m_edge1 + m_edge2),
                     lengthSquared(m_edge1 - m_edge2)));
    return true;
  }

 private:
  // The quad's corners as unit vectors from a point, the solid angles of
  // triangles (0, 1, 2) and (0, 2, 3), and their sum; a sum of 0 means
  // sampling by area.
  struct Subtended
  {
    float3 vertices[4];
    float area[2];
    float solidAngle{0.f};
  };
  Subtended subtend(const float3 &point) const
  {
    Subtended result;
    const float3 toCenter = m_corner + (m_edge1 + m_edge2) * 0.5f - point;
    // The estimate |cos| area / d^2 below the bound, squared: no root.
    const float distance2 = lengthSquared(toCenter);
    const float along = dot(toCenter, m_normal);
    if (along * along < kMinSolidAngleSampling * kMinSolidAngleSampling
                            * distance2 * distance2 * distance2)
      return result; // sampling by area
    const float3 corners[4] = {m_corner - point,
        m_corner + m_edge1 - point,
        m_corner + m_edge1 + m_edge2 - point,
        m_corner + m_edge2 - point};
    for (int i = 0; i < 4; i++) {
      const float3 v = corners[i];
      const float length2 = lengthSquared(v);
      if (!(length2 > 0.f))
        return result;
      result.vertices[i] = v * (1.f / std::sqrt(length2));
    }
    const float3 *v = result.vertices;
    result.area[0] = sphericalTriangleArea(v[0], v[1], v[2]);
    result.area[1] = sphericalTriangleArea(v[0], v[2], v[3]);
    const float total = result.area[0] + result.area[1];
    if (total >= kMinSphericalArea && total <= kMaxSphericalArea)
      result.solidAngle = total;
    return result;
  }

  // Whether `point` is on a side the quad emits towards.
  bool litSide(const float3 &point) const
  {
    const float height = dot(point - m_corner, m_frame.z);
    switch (m_emission.side) {
    case Quad::Side::kFront:
      return height > 0.f;
    case Quad::Side::kBack:
      return height < 0.f;
    default:
      return true;
    }
  }

  // Area density converted to solid angle: d^2 / (area |cos|), where
  // area |cos| is |direction . (edge1 x edge2)|.
  float areaPdf(const float3 &direction, float distance) const
  {
    const float projectedArea = std::abs(dot(direction, m_normal));
    return projectedArea > 0.f ? distance * distance / projectedArea : 0.f;
  }

  // Radiance leaving the quad along the unit `out`.
  float3 emitted(const float3 &out) const
  {
    const float cosFront = dot(out, m_frame.z);
    const Quad::Side side = m_emission.side;
    if ((side == Quad::Side::kFront && !(cosFront > 0.f))
        || (side == Quad::Side::kBack && !(cosFront < 0.f)))
      return {0.f, 0.f, 0.f};
    if (!m_emission.distribution)
      return m_emission.radiance;
    // Intensity I(w) from area A: L = I(w) / (A |cos|), so the table holds
    // the whole angular shape, cosine included.
    const float value = (*m_emission.distribution)(m_frame.toLocal(out));
    return m_emission.intensity
           * (value / (m_area * max(std::abs(cosFront), kMinCosine)));
  }

  float3 m_corner;
  float3 m_edge1, m_edge2;
  float3 m_normal; // edge1 x edge2, unnormalised
  float m_area;
  LocalFrame m_frame; // z the front normal, x along edge1
  Emission m_emission;
};

} // namespace

Quad::Quad(DeviceState &device) : Light(device, "quad") {}

void Quad::commitParameters()
{
  Light::commitParameters();
  m_position = readFinite("position");
  m_edge1 = readFinite("edge1");
  m_edge2 = readFinite("edge2");
  if (lengthSquared(m_edge1) == 0.f || lengthSquared(m_edge2) == 0.f) {
    invalidate("'edge1' and 'edge2' must have non-zero length");
  } else if (!(lengthSquared(cross(m_edge1, m_edge2))
                 > 1e-12f * lengthSquared(m_edge1) * lengthSquared(m_edge2))) {
    invalidate("'edge1' and 'edge2' are parallel; the quad has no area");
  }
  const std::string side = param<std::string>("side");
  m_side = side == "back" ? Side::kBack
                          : (side == "both" ? Side::kBoth : Side::kFront);
  m_brightness = readBrightness({"intensity", "power", "radiance"});
  m_distributionArray = readIntensityDistribution();
}

void Quad::finalize()
{
  m_distribution = buildIntensityDistribution(m_distributionArray);
  m_distributionArray = nullptr;
  const double sides = m_side == Side::kBoth ? 2.0 : 1.0;
  if (!m_distribution) {
    // Lambertian: the integral of cos over a hemisphere is pi.
    m_emissionIntegral = kPiDouble * sides;
    return;
  }
  // The table's values towards the emitting sides only.
  const Side side = m_side;
  m_emissionIntegral = m_distribution->integral(
      [side](double gamma) {
        const bool front = gamma < 0.5 * kPiDouble;
        return side == Side::kBoth || (side == Side::kFront) == front ? 1.0
                                                                      : 0.0;
      },
      {0.5 * kPiDouble});
}

std::unique_ptr<PlacedLight> Quad::place(const mat3x4 &worldFromObject) const
{
  if (!isValid())
    return nullptr;
  // Edges are vectors: the transform's scale changes the area. Intensity
  // and power stay as given (spec 5.7); radiance then follows the area.
  const float3 corner = transformPoint(worldFromObject, m_position);
  const float3 edge1 = transformDirection(worldFromObject, m_edge1);
  const float3 edge2 = transformDirection(worldFromObject, m_edge2);
  const float area = length(cross(edge1, edge2));
  if (!(area > 0.f) || !std::isfinite(area))
    return nullptr;

  float intensity = m_brightness.value;
  if (m_brightness.source == 1)
    intensity = float(m_brightness.value / m_emissionIntegral);
  else if (m_brightness.source == 2)
    intensity = m_brightness.value * area; // radiance times area
  PlacedQuad::Emission emission;
  emission.side = m_side;
  emission.distribution = m_distribution;
  emission.intensity = m_color * intensity;
  emission.radiance =
      m_distribution ? float3{0.f, 0.f, 0.f} : emission.intensity / area;
  emission.power = emission.intensity * float(m_emissionIntegral);
  auto placed =
      std::make_unique<PlacedQuad>(corner, edge1, edge2, std::move(emission));
  placeShared(*placed);
  return placed;
}

} // namespace prism::light
