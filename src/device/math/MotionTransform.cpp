#include "MotionTransform.h"

#include <cmath>

namespace prism {
namespace {

// Rotation matrix of a unit quaternion (i, j, k, w).
mat3x4 rotation(float4 q)
{
  const float x = q.x, y = q.y, z = q.z, w = q.w;
  return {{{1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w)},
      {2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w)},
      {2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y)},
      {0, 0, 0}}};
}

mat3x4 lerp(const mat3x4 &a, const mat3x4 &b, float t)
{
  mat3x4 out;
  for (int c = 0; c < 4; c++)
    out.col[c] = a.col[c] * (1.f - t) + b.col[c] * t;
  return out;
}

} // namespace

MotionTransform::MotionTransform(
    std::vector<mat3x4> keys, float begin, float end)
    : m_timeline{uint32_t(keys.size()), begin, end}, m_matrices(std::move(keys))
{}

MotionTransform::MotionTransform(
    std::vector<Decomposed> keys, float begin, float end)
    : m_timeline{uint32_t(keys.size()), begin, end},
      m_decomposed(std::move(keys))
{
  for (size_t k = 1; k < m_decomposed.size(); k++) {
    if (dot(m_decomposed[k - 1].rotation, m_decomposed[k].rotation) < 0.f)
      m_decomposed[k].rotation = m_decomposed[k].rotation * -1.f;
  }
}

mat3x4 MotionTransform::at(float time) const
{
  if (isDecomposed())
    return compose(decomposedAt(time));
  if (m_matrices.size() < 2)
    return m_matrices.empty() ? kIdentityMat3x4 : m_matrices[0];
  const KeyTimeline::Position p = m_timeline.locate(time);
  return lerp(m_matrices[p.index], m_matrices[p.index + 1], p.fraction);
}

MotionTransform::Decomposed MotionTransform::decomposedAt(float time) const
{
  if (m_decomposed.size() < 2)
    return m_decomposed.empty() ? Decomposed{} : m_decomposed[0];
  const KeyTimeline::Position p = m_timeline.locate(time);
  return interpolate(
      m_decomposed[p.index], m_decomposed[p.index + 1], p.fraction);
}

mat3x4 MotionTransform::key(uint32_t index) const
{
  return isDecomposed() ? compose(m_decomposed[index]) : m_matrices[index];
}

mat3x4 MotionTransform::compose(const Decomposed &components)
{
  mat3x4 m = rotation(components.rotation);
  m.col[0] = m.col[0] * components.scale.x;
  m.col[1] = m.col[1] * components.scale.y;
  m.col[2] = m.col[2] * components.scale.z;
  m.col[3] = components.translation;
  return m;
}

MotionTransform::Decomposed MotionTransform::interpolate(
    const Decomposed &a, const Decomposed &b, float fraction)
{
  return {a.scale * (1.f - fraction) + b.scale * fraction,
      slerp(a.rotation, b.rotation, fraction),
      a.translation * (1.f - fraction) + b.translation * fraction};
}

float4 MotionTransform::slerp(float4 a, float4 b, float fraction)
{
  float cosine = dot(a, b);
  if (cosine < 0.f) { // the shorter way round
    b = b * -1.f;
    cosine = -cosine;
  }
  if (cosine > 0.9995f)
    return normalize(a * (1.f - fraction) + b * fraction);
  const float angle = std::acos(cosine);
  return (a * std::sin((1.f - fraction) * angle)
             + b * std::sin(fraction * angle))
         / std::sin(angle);
}

} // namespace prism
