#include "Sphere.h"

#include "../rt/Scene.h"

namespace prism {

void Sphere::readShape()
{
  const bool indexed = readIndices(1, m_vertexOf);
  const std::vector<float> radii = readFloats("vertex.radius");
  const float radius = read<float>("radius", ANARI_FLOAT32, 1.f);
  if (!readPositions(1))
    return;
  if (!indexed) {
    m_vertexOf.resize(m_vertexCount);
    for (size_t i = 0; i < m_vertexCount; i++)
      m_vertexOf[i] = uint32_t(i);
  }
  requireVertexIndicesBelow(m_vertexCount, m_vertexOf);
  if (!radii.empty() && radii.size() < m_vertexCount)
    invalidate("'vertex.radius' has %zu elements but there are %zu vertices",
        radii.size(),
        m_vertexCount);
  if (!isValid())
    return;
  m_centerRadius.resize(m_vertexOf.size());
  for (size_t i = 0; i < m_vertexOf.size(); i++) {
    const float3 &c = m_positions[m_vertexOf[i]];
    m_centerRadius[i] =
        float4{c.x, c.y, c.z, radii.empty() ? radius : radii[m_vertexOf[i]]};
  }
  setPrimitiveCount(uint32_t(m_vertexOf.size()));
}

void Sphere::addTo(rt::Scene &scene, uint32_t id) const
{
  scene.addSpheres(id, m_centerRadius.data(), primitiveCount());
}

Geometry::Corners Sphere::cornersAt(uint32_t primitive, float, float) const
{
  return {1, {m_vertexOf[primitive]}, {0}, {1.f}};
}

float3 Sphere::surfaceNormal(
    const rt::Hit &hit, const float3 &objectPosition) const
{
  const float4 &s = m_centerRadius[hit.primitiveId];
  return normalize(objectPosition - float3{s.x, s.y, s.z});
}

void Sphere::appendEmitterShape(EmitterShape &shape) const
{
  if (isValid())
    shape.spheres.insert(
        shape.spheres.end(), m_centerRadius.begin(), m_centerRadius.end());
}

} // namespace prism
