#include "Curve.h"

#include "../rt/Scene.h"

namespace prism {

void Curve::readShape()
{
  const bool indexed = readIndices(1, m_indices);
  const std::vector<float> radii = readFloats("vertex.radius");
  const float radius = read<float>("radius", ANARI_FLOAT32, 1.f);
  if (!readPositions(2))
    return;
  if (!indexed)
    generateIndices(m_indices, m_vertexCount - 1);
  // A segment uses its start and the next vertex.
  requireVertexIndicesBelow(m_vertexCount - 1, m_indices);
  if (!radii.empty() && radii.size() < m_vertexCount)
    invalidate("'vertex.radius' has %zu elements but there are %zu vertices",
        radii.size(),
        m_vertexCount);
  if (!isValid())
    return;
  // Embree's layout, the one conversion curves need.
  std::vector<float4>(m_vertexCount + 1).swap(m_positionRadius);
  for (size_t i = 0; i < m_vertexCount; i++) {
    const float3 &p = m_positions[i];
    m_positionRadius[i] =
        float4{p.x, p.y, p.z, radii.empty() ? radius : radii[i]};
  }
  setPrimitiveCount(uint32_t(m_indices.size()));
}

void Curve::addTo(rt::Scene &scene, uint32_t id) const
{
  scene.addRoundCurves(id,
      m_positionRadius.data(),
      m_vertexCount,
      m_indices.data(),
      primitiveCount());
}

size_t Curve::copiedBytes() const
{
  return Geometry::copiedBytes() + m_positionRadius.capacity() * sizeof(float4);
}

Geometry::Corners Curve::cornersAt(uint32_t primitive, float u, float) const
{
  const uint32_t start = m_indices[primitive];
  return {2, {start, start + 1}, {0, 1}, {1.f - u, u}};
}

} // namespace prism
