// Procedural triangle meshes (quads, boxes, spheres) the demo scenes are made
// of, and their conversion to ANARI triangle geometries.
#pragma once

#include "Math.h"

#include <anari/anari.h>

#include <cstdint>
#include <vector>

namespace prism::scenes {

struct TriangleMesh
{
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;
  std::vector<std::array<float, 2>> uvs; // texture coordinates, attribute0
  std::vector<Vec4> tangents;            // xyz along +u, w the bitangent sign
  std::vector<std::array<uint32_t, 3>> triangles;

  // Appends the parallelogram corner, corner + edge1, corner + edge1 +
  // edge2, corner + edge2, facing along cross(edge1, edge2); uv (0, 0) at
  // `corner` and (uScale, vScale) opposite it.
  void addQuad(const Vec3 &corner,
      const Vec3 &edge1,
      const Vec3 &edge2,
      float uScale = 1.f,
      float vScale = 1.f);
  // Appends the box [-0.5, 0.5]^3 transformed by `objectToWorld` (an
  // affine map without shear), with outward faces.
  void addBox(const Mat4 &objectToWorld);
  // Appends a sphere of `radius` around `center` as `rings` bands of
  // `segments` quads; u runs around +y, v from the south to the north pole.
  void addUvSphere(
      const Vec3 &center, float radius, uint32_t segments, uint32_t rings);

  Bounds bounds() const;
};

// A committed `triangle` geometry with vertex.position, vertex.normal and,
// when the mesh has them, vertex.attribute0 (uv) and vertex.tangent.
ANARIGeometry newTriangleGeometry(ANARIDevice device, const TriangleMesh &mesh);

} // namespace prism::scenes
