#include "Triangle.h"

#include "../rt/Scene.h"

namespace prism {

void Triangle::readShape()
{
  const bool indexed = readIndices(3, m_indices);
  if (!readDeformablePositions(3))
    return;
  if (!indexed) {
    generateIndices(m_indices, m_vertexCount / 3 * 3);
  }
  requireVertexIndicesBelow(m_vertexCount, m_indices);
  setPrimitiveCount(uint32_t(m_indices.size() / 3));
}

void Triangle::addTo(rt::Scene &scene, uint32_t id) const
{
  if (m_vertexMotion.isSet()) {
    scene.addTriangles(id,
        m_vertexMotion.positionKeys(),
        m_vertexCount,
        m_indices.data(),
        primitiveCount());
    return;
  }
  scene.addTriangles(id,
      m_positions.data(),
      m_vertexCount,
      m_indices.data(),
      primitiveCount());
}

Geometry::Corners Triangle::cornersAt(
    uint32_t primitive, float u, float v) const
{
  const uint32_t *tri = &m_indices[3 * size_t(primitive)];
  return {3, {tri[0], tri[1], tri[2]}, {0, 1, 2}, {1.f - u - v, u, v}};
}

void Triangle::appendEmitterShape(EmitterShape &shape) const
{
  if (!isValid() || m_vertexMotion.isSet())
    return;
  for (uint32_t index : m_indices)
    shape.triangles.push_back(m_positions[index]);
}

} // namespace prism
