#include "Curve.h"

#include "../rt/Scene.h"

namespace prism {

void Curve::readShape()
{
  const bool indexed = readIndices(1, m_segmentStarts);
  const std::vector<float> radii = readFloats("vertex.radius");
  const float radius = read<float>("radius", ANARI_FLOAT32, 1.f);
  if (!readPositions(2))
    return;
  if (!indexed) {
    m_segmentStarts.resize(m_vertexCount - 1);
    for (size_t i = 0; i + 1 < m_vertexCount; i++)
      m_segmentStarts[i] = uint32_t(i);
  }
  // A segment uses its start and the next vertex.
  requireVertexIndicesBelow(m_vertexCount - 1, m_segmentStarts);
  if (!radii.empty() && radii.size() < m_vertexCount)
    invalidate("'vertex.radius' has %zu elements but there are %zu vertices",
        radii.size(),
        m_vertexCount);
  if (!isValid())
    return;
  m_positionRadius.resize(m_vertexCount + 1);
  for (size_t i = 0; i < m_vertexCount; i++) {
    const float3 &p = m_positions[i];
    m_positionRadius[i] =
        float4{p.x, p.y, p.z, radii.empty() ? radius : radii[i]};
  }
  setPrimitiveCount(uint32_t(m_segmentStarts.size()));
}

void Curve::addTo(rt::Scene &scene, uint32_t id) const
{
  scene.addRoundCurves(id,
      m_positionRadius.data(),
      m_vertexCount,
      m_segmentStarts.data(),
      primitiveCount());
}

Geometry::Corners Curve::cornersAt(uint32_t primitive, float u, float) const
{
  const uint32_t start = m_segmentStarts[primitive];
  return {2, {start, start + 1}, {0, 1}, {1.f - u, u}};
}

} // namespace prism
