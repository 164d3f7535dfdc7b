#include "EmissiveSurface.h"

#include "Sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace prism {
namespace {

float triangleArea(const float3 &a, const float3 &b, const float3 &c)
{
  return 0.5f * length(cross(b - a, c - a));
}

} // namespace

EmissiveSurface::EmissiveSurface(EmitterShape shape, const float3 &radiance)
    : m_shape(std::move(shape)), m_radiance(radiance)
{
  double sum = 0.0;
  const size_t triangles = m_shape.triangles.size() / 3;
  m_cdf.reserve(triangles + m_shape.spheres.size());
  for (size_t i = 0; i < triangles; i++) {
    const float3 *t = &m_shape.triangles[3 * i];
    const float area = triangleArea(t[0], t[1], t[2]);
    sum += std::isfinite(area) ? area : 0.f;
    m_cdf.push_back(float(sum));
  }
  for (const float4 &s : m_shape.spheres) {
    const float area = 4.f * light::kPi * s.w * s.w;
    sum += std::isfinite(area) ? area : 0.f;
    m_cdf.push_back(float(sum));
  }
  m_area = float(sum);
  if (m_area > 0.f) {
    for (float &c : m_cdf)
      c /= m_area;
    m_cdf.back() = 1.f;
  }
}

LightSample EmissiveSurface::sample(const float3 &point, const float2 &u) const
{
  LightSample out;
  if (isEmpty())
    return out;
  // Pick a primitive by area with u.x, then reuse u.x's position within
  // that primitive's share as a fresh uniform number.
  const size_t index = std::min(
      size_t(std::upper_bound(m_cdf.begin(), m_cdf.end(), u.x) - m_cdf.begin()),
      m_cdf.size() - 1);
  const float low = index > 0 ? m_cdf[index - 1] : 0.f;
  const float share = m_cdf[index] - low;
  const float u0 =
      share > 0.f ? std::clamp((u.x - low) / share, 0.f, 0.99999994f) : 0.5f;
  float3 position, normal;
  const size_t triangles = m_shape.triangles.size() / 3;
  if (index < triangles) {
    const float3 *t = &m_shape.triangles[3 * index];
    // Uniform on the triangle: the square root warp of (u0, u.y).
    const float s = std::sqrt(u0);
    const float b0 = 1.f - s, b1 = u.y * s;
    position = t[0] * b0 + t[1] * b1 + t[2] * (1.f - b0 - b1);
    normal = normalize(cross(t[1] - t[0], t[2] - t[0]));
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
  out.pdf = pdfOfHit(distance, cosine);
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

float EmissiveSurface::pdfOfHit(float distance, float cosine) const
{
  if (isEmpty() || !(cosine > 1e-7f))
    return 0.f;
  return distance * distance / (cosine * m_area);
}

} // namespace prism
