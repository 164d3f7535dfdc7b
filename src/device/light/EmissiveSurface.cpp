#include "EmissiveSurface.h"

#include "Sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace prism {
namespace {

// Solid-angle sampling pays where 1/d^2 and the emitter's cosine vary over
// the triangle: when its solid angle, estimated from its centroid as
// |cos| area / d^2, is at least this (as for quad lights); smaller or
// farther triangles are sampled by area, which costs no trigonometry.
constexpr float kMinSolidAngleSampling = 0.3f;
// Exact solid angles outside these bounds lose precision in Arvo's
// formulas; such triangles are sampled by area as well.
constexpr float kMinSphericalArea = 1e-5f;
constexpr float kMaxSphericalArea = 6.f;

float triangleArea(const float3 &a, const float3 &b, const float3 &c)
{
  return 0.5f * length(cross(b - a, c - a));
}

float finiteOrZero(float value)
{
  return std::isfinite(value) ? value : 0.f;
}

// How far `p` lies outside triangle t (0 inside, in units of the
// triangle's size): its distance from the plane and beyond the edges.
float outsideTriangle(const float3 *t, const float3 &p)
{
  const float3 e1 = t[1] - t[0], e2 = t[2] - t[0], d = p - t[0];
  const float3 n = cross(e1, e2);
  const float n2 = lengthSquared(n);
  if (!(n2 > 0.f))
    return std::numeric_limits<float>::infinity();
  const float b1 = dot(cross(d, e2), n) / n2;
  const float b2 = dot(cross(e1, d), n) / n2;
  const float plane = std::abs(dot(d, n)) / n2; // distance / (2 area)
  return plane + std::max({0.f, -b1, -b2, b1 + b2 - 1.f});
}

} // namespace

EmissiveSurface::EmissiveSurface(EmitterShape shape, const float3 &radiance)
    : m_shape(std::move(shape)), m_radiance(radiance)
{
  double sum = 0.0;
  const size_t triangles = m_shape.triangles.size() / 3;
  std::vector<light::TreeEmitter> emitters;
  emitters.reserve(triangles + m_shape.spheres.size());
  for (size_t i = 0; i < triangles; i++) {
    const float3 *t = &m_shape.triangles[3 * i];
    light::TreeEmitter e;
    e.power = finiteOrZero(triangleArea(t[0], t[1], t[2]));
    e.lower = min(t[0], min(t[1], t[2]));
    e.upper = max(t[0], max(t[1], t[2]));
    e.normal = e.power > 0.f ? normalize(cross(t[1] - t[0], t[2] - t[0]))
                             : float3{0.f, 0.f, 1.f};
    emitters.push_back(e);
  }
  for (const float4 &s : m_shape.spheres) {
    light::TreeEmitter e;
    e.power = finiteOrZero(4.f * light::kPi * s.w * s.w);
    const float3 centre{s.x, s.y, s.z}, reach{s.w, s.w, s.w};
    e.lower = centre - reach;
    e.upper = centre + reach;
    e.omnidirectional = true;
    emitters.push_back(e);
  }
  for (const light::TreeEmitter &e : emitters) {
    m_primitiveArea.push_back(e.power);
    sum += e.power;
  }
  m_area = float(sum);
  if (m_area > 0.f && std::isfinite(m_area))
    m_tree.build(emitters); // radiance is uniform: power goes with area
  else
    m_area = 0.f;
}

float EmissiveSurface::sampledSolidAngle(
    const float3 &point, size_t index) const
{
  const float3 *t = &m_shape.triangles[3 * index];
  const float3 toCentroid = (t[0] + t[1] + t[2]) * (1.f / 3.f) - point;
  const float distance2 = lengthSquared(toCentroid);
  // |cos| area / d^2 = |n . c| / (2 d^3) against the bound, squared.
  const float along = 0.5f * dot(cross(t[1] - t[0], t[2] - t[0]), toCentroid);
  if (!(along * along >= kMinSolidAngleSampling * kMinSolidAngleSampling
                             * distance2 * distance2 * distance2))
    return 0.f;
  float3 v[3];
  for (int i = 0; i < 3; i++) {
    const float3 d = t[i] - point;
    const float length2 = lengthSquared(d);
    if (!(length2 > 0.f))
      return 0.f;
    v[i] = d * (1.f / std::sqrt(length2));
  }
  const float area = light::sphericalTriangleArea(v[0], v[1], v[2]);
  return area >= kMinSphericalArea && area <= kMaxSphericalArea ? area : 0.f;
}

LightSample EmissiveSurface::sample(const float3 &point, const float2 &u) const
{
  return sampleFacing(point, float3{0.f, 0.f, 0.f}, u);
}

LightSample EmissiveSurface::sampleFacing(
    const float3 &point, const float3 &receiverNormal, const float2 &u) const
{
  LightSample out;
  if (isEmpty())
    return out;
  // The tree consumes u.x and leaves a fresh uniform number in it.
  float u0 = u.x, chosen = 0.f;
  const size_t index = m_tree.pick(point, receiverNormal, u0, chosen);
  const size_t triangles = m_shape.triangles.size() / 3;
  float3 position, normal;
  if (index < triangles) {
    const float3 *t = &m_shape.triangles[3 * index];
    normal = normalize(cross(t[1] - t[0], t[2] - t[0]));
    const float solidAngle = sampledSolidAngle(point, index);
    if (solidAngle > 0.f) {
      float3 v[3];
      for (int i = 0; i < 3; i++)
        v[i] = normalize(t[i] - point);
      out.direction = normalize(light::sampleSphericalTriangle(
          v[0], v[1], v[2], solidAngle, float2{u0, u.y}));
      const float along = dot(out.direction, normal);
      out.distance =
          along != 0.f ? std::max(0.f, dot(t[0] - point, normal) / along) : 0.f;
      out.pdf = chosen / solidAngle;
      if (!(out.distance > 0.f) || !(out.pdf > 0.f) || !std::isfinite(out.pdf))
        return {};
      out.radiance = m_radiance;
      return out;
    }
    // Uniform on the triangle: the square root warp of (u0, u.y).
    const float s = std::sqrt(u0);
    const float b0 = 1.f - s, b1 = u.y * s;
    position = t[0] * b0 + t[1] * b1 + t[2] * (1.f - b0 - b1);
  } else {
    const float4 &sphere = m_shape.spheres[index - triangles];
    const float z = 1.f - 2.f * u0;
    const float r = std::sqrt(std::max(0.f, 1.f - z * z));
    const float phi = 2.f * light::kPi * u.y;
    normal = {r * std::cos(phi), r * std::sin(phi), z};
    position = float3{sphere.x, sphere.y, sphere.z} + normal * sphere.w;
  }
  const float3 toLight = position - point;
  const float distance2 = dot(toLight, toLight);
  if (!(distance2 > 0.f))
    return out;
  const float distance = std::sqrt(distance2);
  out.direction = toLight / distance;
  out.distance = distance;
  const float cosine = std::abs(dot(normal, out.direction));
  const float area = m_primitiveArea[index];
  out.pdf = cosine > 1e-7f ? chosen * distance2 / (cosine * area) : 0.f;
  if (!(out.pdf > 0.f) || !std::isfinite(out.pdf)) {
    out.pdf = 0.f;
    return out;
  }
  out.radiance = m_radiance;
  return out;
}

float3 EmissiveSurface::radianceAlong(
    const float3 &, const float3 &, float &distance, float &pdf) const
{
  distance = std::numeric_limits<float>::infinity();
  pdf = 0.f;
  return {0.f, 0.f, 0.f};
}

float3 EmissiveSurface::power() const
{
  // Lambertian emission from both sides: pi L per side and unit area.
  return m_radiance * (2.f * light::kPi * m_area);
}

size_t EmissiveSurface::emitterOfHit(
    const float3 &position, uint32_t primitiveId) const
{
  const size_t triangles = m_shape.triangles.size() / 3;
  if (triangles == 0)
    return primitiveId; // a sphere geometry's spheres
  // A triangle geometry's triangles, or a quad geometry's halves: the one
  // the point lies on.
  size_t best = primitiveId;
  float bestOutside = std::numeric_limits<float>::infinity();
  for (size_t candidate : {size_t(primitiveId),
           2 * size_t(primitiveId),
           2 * size_t(primitiveId) + 1}) {
    if (candidate >= triangles)
      continue;
    const float outside =
        outsideTriangle(&m_shape.triangles[3 * candidate], position);
    if (outside < bestOutside) {
      bestOutside = outside;
      best = candidate;
    }
  }
  return best;
}

float EmissiveSurface::pdfOfPoint(const float3 &origin,
    const float3 &normal,
    size_t index,
    float distance,
    float cosine) const
{
  const float chosen = m_tree.probability(origin, normal, uint32_t(index));
  if (!(chosen > 0.f))
    return 0.f;
  if (index < m_shape.triangles.size() / 3) {
    const float solidAngle = sampledSolidAngle(origin, index);
    if (solidAngle > 0.f)
      return chosen / solidAngle;
  }
  if (!(cosine > 1e-7f))
    return 0.f;
  return chosen * distance * distance / (cosine * m_primitiveArea[index]);
}

float EmissiveSurface::pdfOfHit(const float3 &origin,
    const float3 &normal,
    const float3 &direction,
    uint32_t primitiveId,
    float distance,
    float cosine) const
{
  if (isEmpty())
    return 0.f;
  const size_t index = emitterOfHit(origin + direction * distance, primitiveId);
  if (index >= m_primitiveArea.size())
    return 0.f;
  return pdfOfPoint(origin, normal, index, distance, cosine);
}

} // namespace prism
