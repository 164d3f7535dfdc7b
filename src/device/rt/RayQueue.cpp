#include "RayQueue.h"

#include "RayValidity.h"

#include <algorithm>
#include <cmath>

namespace prism::rt {

void RayQueue::grow(size_t capacity)
{
  for (auto *v : {&m_originX,
           &m_originY,
           &m_originZ,
           &m_tMin,
           &m_directionX,
           &m_directionY,
           &m_directionZ,
           &m_time,
           &m_tMax,
           &m_normalX,
           &m_normalY,
           &m_normalZ,
           &m_u,
           &m_v})
    v->resize(capacity);
  for (auto *v : {&m_tag, &m_primitiveId, &m_geometryId, &m_instanceId})
    v->resize(capacity);
  m_transmittance.resize(capacity);
  // Every ray is of every mask and flagless; tracing never changes either.
  m_mask.resize(capacity, ~0u);
  m_flags.resize(capacity, 0u);
}

void RayQueue::reserve(size_t capacity)
{
  if (capacity > m_originX.size())
    grow(capacity);
}

size_t RayQueue::push(const float3 &origin,
    const float3 &direction,
    float tMin,
    float tMax,
    float time,
    uint32_t tag)
{
  if (m_size == m_originX.size())
    grow(std::max<size_t>(64, 2 * m_size));
  const size_t i = m_size++;
  // An untraceable ray becomes an inactive one (tMin > tMax), which Embree
  // skips and which therefore finds nothing.
  const bool valid = isTraceable(origin, direction, tMin, tMax);
  const float3 o = valid ? origin : float3{0.f, 0.f, 0.f};
  const float3 d = valid ? direction : float3{0.f, 0.f, 1.f};
  m_originX[i] = o.x;
  m_originY[i] = o.y;
  m_originZ[i] = o.z;
  m_tMin[i] = valid ? tMin : 1.f;
  m_directionX[i] = d.x;
  m_directionY[i] = d.y;
  m_directionZ[i] = d.z;
  // Embree traces times in [0, 1]; anything else at the shutter midpoint.
  m_time[i] = time >= 0.f && time <= 1.f ? time : 0.5f;
  m_tMax[i] = valid ? tMax : 0.f;
  m_tag[i] = tag;
  m_geometryId[i] = kInvalidId;
  m_instanceId[i] = kInvalidId;
  m_transmittance[i] = float3{1.f, 1.f, 1.f}; // until traced
  return i;
}

Hit RayQueue::hit(size_t i) const
{
  Hit hit;
  if (m_geometryId[i] == kInvalidId)
    return hit;
  hit.t = m_tMax[i];
  hit.u = m_u[i];
  hit.v = m_v[i];
  hit.geometricNormal = {m_normalX[i], m_normalY[i], m_normalZ[i]};
  hit.primitiveId = m_primitiveId[i];
  hit.geometryId = m_geometryId[i];
  hit.instanceId = m_instanceId[i];
  return hit;
}

void RayQueue::assignInstance(uint32_t instance)
{
  for (size_t i = 0; i < m_size; i++) {
    if (m_geometryId[i] != kInvalidId)
      m_instanceId[i] = instance;
  }
}

} // namespace prism::rt
