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
  m_passedOneSided.resize(capacity);
  const size_t indexed = m_index.size();
  m_index.resize(capacity);
  for (size_t i = indexed; i < capacity; i++)
    m_index[i] = uint32_t(i);
  // Every ray is of every mask and flagless; tracing never changes either.
  m_mask.resize(capacity, ~0u);
  m_flags.resize(capacity, 0u);
}

void RayQueue::reserve(size_t capacity)
{
  if (capacity > m_originX.size())
    grow(capacity);
}

void RayQueue::append(const RayQueue &other)
{
  reserve(m_size + other.m_size);
  // push() keeps what it stored the first time (a traceable ray as it is,
  // an untraceable one as its empty interval).
  for (size_t i = 0; i < other.m_size; i++) {
    const size_t at = push(other.origin(i),
        other.direction(i),
        other.m_tMin[i],
        other.m_tMax[i],
        other.m_time[i],
        other.m_tag[i]);
    m_passedOneSided[at] = other.m_passedOneSided[i];
  }
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
