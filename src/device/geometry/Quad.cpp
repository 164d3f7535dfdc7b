#include "Quad.h"

#include "../rt/Scene.h"

namespace prism {

void Quad::readShape()
{
  const bool indexed = readIndices(4, m_indices);
  if (!readDeformablePositions(4))
    return;
  if (!indexed) {
    generateIndices(m_indices, m_vertexCount / 4 * 4);
  }
  requireVertexIndicesBelow(m_vertexCount, m_indices);
  setPrimitiveCount(uint32_t(m_indices.size() / 4));
}

void Quad::addTo(rt::Scene &scene, uint32_t id) const
{
  if (m_vertexMotion.isSet()) {
    scene.addQuads(id,
        m_vertexMotion.positionKeys(),
        m_vertexCount,
        m_indices.data(),
        primitiveCount());
    return;
  }
  scene.addQuads(id,
      m_positions.data(),
      m_vertexCount,
      m_indices.data(),
      primitiveCount());
}

Geometry::Corners Quad::cornersAt(uint32_t primitive, float u, float v) const
{
  // Embree splits a quad into triangles (v0, v1, v3) and (v2, v3, v1) and
  // reports (u, v) over the whole quad; interpolate exactly as it traced.
  const uint32_t *q = &m_indices[4 * size_t(primitive)];
  if (u + v <= 1.f)
    return {3, {q[0], q[1], q[3]}, {0, 1, 3}, {1.f - u - v, u, v}};
  return {3, {q[2], q[3], q[1]}, {2, 3, 1}, {u + v - 1.f, 1.f - u, 1.f - v}};
}

void Quad::appendEmitterShape(EmitterShape &shape) const
{
  if (!isValid() || m_vertexMotion.isSet())
    return;
  for (size_t q = 0; q + 3 < m_indices.size(); q += 4) {
    // The two triangles Embree splits the quad into.
    for (int corner : {0, 1, 3, 2, 3, 1})
      shape.triangles.push_back(m_positions[m_indices[q + corner]]);
  }
}

} // namespace prism
