// A wavefront of rays in structure-of-arrays form, with room for what
// tracing them finds. Renderers fill it, a transport traces all of it at
// once (Embree's stream API locally; the data-parallel device forwards
// whole queues between ranks), renderers read the results back. Plain
// arrays of plain numbers, so a queue can be sent as it is.
#pragma once

#include "Hit.h"
#include "RayValidity.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace prism::rt {

class RayQueue
{
 public:
  size_t size() const
  {
    return m_size;
  }
  bool empty() const
  {
    return m_size == 0;
  }
  // Keeps the memory for the next rays; the queue is incoherent again.
  void clear()
  {
    m_size = 0;
    m_coherent = false;
  }
  void reserve(size_t capacity);
  // Appends `other`'s rays (not what tracing them found, but the
  // single-sided surfaces they were given as passed) after these.
  void append(const RayQueue &other);

  // Appends a ray; `tag` is the caller's (e.g. which path it extends) and
  // comes back unchanged. A ray that could not be traced (non-finite
  // numbers, tMax < tMin) is kept but finds nothing.
  size_t push(const float3 &origin,
      const float3 &direction,
      float tMin,
      float tMax,
      float time,
      uint32_t tag);

  uint32_t tag(size_t i) const
  {
    return m_tag[i];
  }
  float3 origin(size_t i) const
  {
    return {m_originX[i], m_originY[i], m_originZ[i]};
  }
  float3 direction(size_t i) const
  {
    return {m_directionX[i], m_directionY[i], m_directionZ[i]};
  }
  float time(size_t i) const
  {
    return m_time[i];
  }
  float tMin(size_t i) const
  {
    return m_tMin[i];
  }
  // The end of ray i (after an occlusion trace: of an unblocked ray).
  float tMax(size_t i) const
  {
    return m_tMax[i];
  }
  // After a closest-hit trace: whether ray i could not be traced (push()
  // turned it into an empty interval).
  bool untraceable(size_t i) const
  {
    return m_tMax[i] < m_tMin[i] && m_tMax[i] >= 0.f;
  }

  // After a closest-hit trace: what ray i found (Hit::found() false if
  // nothing).
  Hit hit(size_t i) const;
  // After an occlusion trace: whether something blocks ray i.
  bool occluded(size_t i) const
  {
    return m_tMax[i] < 0.f && m_tMin[i] >= 0.f;
  }
  // After a trace: the nearest distance along ray i at which it passed a
  // single-sided surface (Scene::cullBackFaces) by the trace's rule: a
  // closest-hit ray passes faces it meets from behind, an occlusion ray
  // those it meets from the front (light meets them from behind); +inf if
  // none. Where the two rules differ, a light seen by one kind of ray is
  // not by the other, which multiple importance sampling must know.
  float passedOneSidedAt(size_t i) const
  {
    return m_passedOneSided[i];
  }
  // Replaces it (with the nearest over every process's part of the world).
  void setPassedOneSidedAt(size_t i, float t)
  {
    m_passedOneSided[i] = t;
  }
  // After an occlusion trace: how much light gets through along ray i, per
  // color channel (0 or 1 past opaque surfaces; media between give what
  // they let through).
  const float3 &transmittance(size_t i) const
  {
    return m_transmittance[i];
  }
  // Multiplies ray i's transmittance (what a medium or a see-through
  // surface along it lets through).
  void attenuate(size_t i, const float3 &factor)
  {
    m_transmittance[i] = m_transmittance[i] * factor;
  }
  // Replaces ray i's transmittance (with what every process's part of the
  // world lets through).
  void setTransmittance(size_t i, const float3 &transmittance)
  {
    m_transmittance[i] = transmittance;
  }

  // A hint for the tracer: the rays start close together and point alike
  // (a tile's camera rays), so tracing them as packets pays.
  void setCoherent(bool coherent)
  {
    m_coherent = coherent;
  }
  bool coherent() const
  {
    return m_coherent;
  }

  // Names instance `instance` in every hit (for scenes traced without
  // their instance level).
  void assignInstance(uint32_t instance);

 private:
  friend class Scene; // passes the arrays to Embree as they are

  // Every array holds at least `capacity` elements (the first m_size used).
  void grow(size_t capacity);

  size_t m_size{0};
  bool m_coherent{false};
  // Ray (the layout of Embree's RTCRayNp members, one array each).
  std::vector<float> m_originX, m_originY, m_originZ, m_tMin;
  std::vector<float> m_directionX, m_directionY, m_directionZ, m_time;
  std::vector<float> m_tMax;
  std::vector<uint32_t> m_mask, m_tag, m_flags;
  // Hit (RTCHitNp).
  std::vector<float> m_normalX, m_normalY, m_normalZ, m_u, m_v;
  std::vector<uint32_t> m_primitiveId, m_geometryId, m_instanceId;
  // Occlusion (set by the trace, then attenuated).
  std::vector<float3> m_transmittance;
  // Single-sided surfaces passed (+inf from push(), or what the caller
  // set: a ray carried on past a see-through layer; lowered by the
  // trace's filters), and each ray's own index, which Embree carries as
  // the ray's id to the filters recording them.
  std::vector<float> m_passedOneSided;
  std::vector<uint32_t> m_index;
};

// Inline: the path tracer pushes a ray or two per path and bounce.
inline size_t RayQueue::push(const float3 &origin,
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
  m_passedOneSided[i] = std::numeric_limits<float>::infinity();
  return i;
}

} // namespace prism::rt
