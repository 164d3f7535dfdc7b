#include "Curve.h"

#include "../array/Array.h"
#include "../rt/Scene.h"

#include <cstring>

namespace prism {

void Curve::readShape()
{
  const bool indexed = readIndices(1, m_indices);
  m_positionRadius.clear();
  const bool packed = isSet("vertex.positionRadius");
  const std::vector<float> radii =
      packed ? std::vector<float>() : readFloats("vertex.radius");
  const float radius = packed ? 1.f : read<float>("radius", ANARI_FLOAT32, 1.f);
  if (packed ? !readPositionRadiusShape() : !readPositions(2))
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
  setPrimitiveCount(uint32_t(m_indices.size()));
  if (packed)
    return;
  // Embree's layout, the one conversion curves need.
  float4 *positionRadius = m_positionRadius.own(m_vertexCount, 1);
  for (size_t i = 0; i < m_vertexCount; i++) {
    const float3 &p = m_positions[i];
    positionRadius[i] =
        float4{p.x, p.y, p.z, radii.empty() ? radius : radii[i]};
  }
}

bool Curve::readPositionRadiusShape()
{
  const Array *packed = readPositionRadius(2);
  if (!packed)
    return false;
  const auto *given = (const float4 *)packed->begin();
  if (uintptr_t(given) % kEmbreeFloat4Alignment == 0
      && packed->readableAfterEnd(sizeof(float4))) {
    m_positionRadius.share(given, m_vertexCount);
  } else {
    float4 *copy = m_positionRadius.own(m_vertexCount, 1);
    std::memcpy(copy, given, m_vertexCount * sizeof(float4));
  }
  return true;
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
  return Geometry::copiedBytes() + m_positionRadius.copiedBytes();
}

Geometry::Corners Curve::cornersAt(uint32_t primitive, float u, float) const
{
  const uint32_t start = m_indices[primitive];
  return {2, {start, start + 1}, {0, 1}, {1.f - u, u}};
}

} // namespace prism
