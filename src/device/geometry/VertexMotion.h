// Deformation motion blur of meshes (KHR_GEOMETRY_TRIANGLE_MOTION_DEFORMATION,
// KHR_GEOMETRY_QUAD_MOTION_DEFORMATION): vertex positions and normals at
// keys uniformly distributed over the geometry's `time` box, each key an
// array of its own (motion.vertex.* are arrays of arrays).
#pragma once

#include "../math/KeyTimeline.h"
#include "../math/Vec.h"
#include "../rt/Scene.h"

#include <string>
#include <vector>

namespace prism {

class Array;

class VertexMotion
{
 public:
  // Reads motion.vertex.position: every key an array of FLOAT32_VEC3, all
  // of one length, at least `minimumCount`. Returns why the keys are
  // unusable (then isSet() is false), or an empty string.
  std::string readPositions(
      const Array &keys, float2 time, size_t minimumCount);
  // Reads motion.vertex.normal (FLOAT32_VEC3 or FIXED16_VEC3 keys covering
  // every vertex); returns why they are ignored, or an empty string.
  std::string readNormals(const Array &keys, float2 time);
  // motion.vertex.tangent is checked only (no renderer uses tangents yet).
  std::string checkTangents(const Array &keys) const;

  bool isSet() const
  {
    return !m_positions.empty();
  }
  size_t vertexCount() const
  {
    return m_vertexCount;
  }
  // Position keys as Embree shares them (each array padded for its reads).
  rt::VertexKeys positionKeys() const;
  const std::vector<float3> &firstPositions() const
  {
    return m_positions.front();
  }
  bool hasNormals() const
  {
    return !m_normals.empty();
  }
  float3 normal(uint32_t vertex, float time) const;

 private:
  size_t m_vertexCount{0};
  std::vector<std::vector<float3>> m_positions; // one padding element each
  KeyTimeline m_positionTimeline;
  std::vector<std::vector<float3>> m_normals;
  KeyTimeline m_normalTimeline;
};

} // namespace prism
