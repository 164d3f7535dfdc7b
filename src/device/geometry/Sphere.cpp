#include "Sphere.h"

#include "../array/Array.h"
#include "../rt/Scene.h"

#include <cstring>

namespace prism {

void Sphere::readShape()
{
  const bool indexed = readIndices(1, m_indices);
  m_indexed = indexed;
  m_centerRadius.clear();
  if (isSet("vertex.positionRadius")) {
    readPositionRadiusShape();
    return;
  }
  const std::vector<float> radii = readFloats("vertex.radius");
  const float radius = read<float>("radius", ANARI_FLOAT32, 1.f);
  if (!readPositions(1))
    return;
  // Without indices, sphere i is vertex i (no index array is made).
  requireVertexIndicesBelow(m_vertexCount, m_indices);
  if (!radii.empty() && radii.size() < m_vertexCount)
    invalidate("'vertex.radius' has %zu elements but there are %zu vertices",
        radii.size(),
        m_vertexCount);
  if (!isValid())
    return;
  // Embree's layout, the one conversion spheres need.
  const size_t count = indexed ? m_indices.size() : m_vertexCount;
  float4 *centerRadius = m_centerRadius.own(count);
  for (size_t i = 0; i < count; i++) {
    const uint32_t v = vertexOf(uint32_t(i));
    const float3 &c = m_positions[v];
    centerRadius[i] = float4{c.x, c.y, c.z, radii.empty() ? radius : radii[v]};
  }
  setPrimitiveCount(uint32_t(count));
}

void Sphere::readPositionRadiusShape()
{
  const Array *packed = readPositionRadius(1);
  if (!packed)
    return;
  requireVertexIndicesBelow(m_vertexCount, m_indices);
  if (!isValid())
    return;
  const auto *given = (const float4 *)packed->begin();
  if (!m_indexed && uintptr_t(given) % kEmbreeFloat4Alignment == 0) {
    m_centerRadius.share(given, m_vertexCount); // Embree's layout already
  } else {
    // Indexed (Embree has no index buffer for spheres) or misaligned:
    // gathered into the device's own.
    const size_t count = m_indexed ? m_indices.size() : m_vertexCount;
    float4 *gathered = m_centerRadius.own(count);
    for (size_t i = 0; i < count; i++)
      std::memcpy(&gathered[i], &given[vertexOf(uint32_t(i))], sizeof(float4));
  }
  setPrimitiveCount(uint32_t(m_centerRadius.size()));
}

void Sphere::addTo(rt::Scene &scene, uint32_t id) const
{
  scene.addSpheres(id, m_centerRadius.data(), primitiveCount());
}

Geometry::Corners Sphere::cornersAt(uint32_t primitive, float, float) const
{
  return {1, {vertexOf(primitive)}, {0}, {1.f}};
}

float3 Sphere::surfaceNormal(
    const rt::Hit &hit, const float3 &objectPosition) const
{
  const float4 &s = m_centerRadius[hit.primitiveId];
  return normalize(objectPosition - float3{s.x, s.y, s.z});
}

size_t Sphere::copiedBytes() const
{
  return Geometry::copiedBytes() + m_centerRadius.copiedBytes();
}

void Sphere::appendEmitterShape(EmitterShape &shape) const
{
  if (isValid())
    shape.spheres.insert(
        shape.spheres.end(), m_centerRadius.begin(), m_centerRadius.end());
}

} // namespace prism
