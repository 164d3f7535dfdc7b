#include "Meshes.h"

#include "Objects.h"

#include <numbers>

namespace prism::scenes {

void TriangleMesh::addQuad(const Vec3 &corner,
    const Vec3 &edge1,
    const Vec3 &edge2,
    float uScale,
    float vScale)
{
  const uint32_t first = uint32_t(positions.size());
  const Vec3 normal = normalize(cross(edge1, edge2));
  const Vec3 tangent = normalize(edge1);
  const Vec3 corners[4] = {
      corner, corner + edge1, corner + edge1 + edge2, corner + edge2};
  const std::array<float, 2> uv[4] = {
      {0.f, 0.f}, {uScale, 0.f}, {uScale, vScale}, {0.f, vScale}};
  for (int i = 0; i < 4; i++) {
    positions.push_back(corners[i]);
    normals.push_back(normal);
    uvs.push_back(uv[i]);
    tangents.push_back({tangent[0], tangent[1], tangent[2], 1.f});
  }
  triangles.push_back({first, first + 1, first + 2});
  triangles.push_back({first, first + 2, first + 3});
}

void TriangleMesh::addBox(const Mat4 &objectToWorld)
{
  // Each face: a corner and two edges whose cross product points outwards.
  struct Face
  {
    Vec3 corner, edge1, edge2;
  };
  const Face faces[6] = {
      {{-0.5f, -0.5f, 0.5f}, {1, 0, 0}, {0, 1, 0}},  // +z
      {{0.5f, -0.5f, -0.5f}, {-1, 0, 0}, {0, 1, 0}}, // -z
      {{0.5f, -0.5f, 0.5f}, {0, 0, -1}, {0, 1, 0}},  // +x
      {{-0.5f, -0.5f, -0.5f}, {0, 0, 1}, {0, 1, 0}}, // -x
      {{-0.5f, 0.5f, 0.5f}, {1, 0, 0}, {0, 0, -1}},  // +y
      {{-0.5f, -0.5f, -0.5f}, {1, 0, 0}, {0, 0, 1}}, // -y
  };
  for (const Face &f : faces) {
    addQuad(transformPoint(objectToWorld, f.corner),
        transformDirection(objectToWorld, f.edge1),
        transformDirection(objectToWorld, f.edge2));
  }
}

void TriangleMesh::addUvSphere(
    const Vec3 &center, float radius, uint32_t segments, uint32_t rings)
{
  constexpr float kPi = std::numbers::pi_v<float>;
  const uint32_t first = uint32_t(positions.size());
  // (segments + 1) columns: the seam repeats so u runs 0..1 without a jump.
  for (uint32_t r = 0; r <= rings; r++) {
    const float v = float(r) / float(rings);
    const float theta = kPi * (1.f - v); // from the south pole up
    for (uint32_t s = 0; s <= segments; s++) {
      const float u = float(s) / float(segments);
      const float phi = 2.f * kPi * u;
      const Vec3 n{std::sin(theta) * std::sin(phi),
          std::cos(theta),
          std::sin(theta) * std::cos(phi)};
      positions.push_back(center + n * radius);
      normals.push_back(n);
      uvs.push_back({u, v});
      // d(position)/du, well defined away from the poles.
      const Vec3 t{std::cos(phi), 0.f, -std::sin(phi)};
      tangents.push_back({t[0], t[1], t[2], 1.f});
    }
  }
  const uint32_t columns = segments + 1;
  for (uint32_t r = 0; r < rings; r++) {
    for (uint32_t s = 0; s < segments; s++) {
      const uint32_t a = first + r * columns + s;
      const uint32_t b = a + 1;
      const uint32_t c = a + columns;
      const uint32_t d = c + 1;
      if (r > 0)
        triangles.push_back({a, b, d});
      if (r + 1 < rings)
        triangles.push_back({a, d, c});
    }
  }
}

Bounds TriangleMesh::bounds() const
{
  Bounds b;
  for (const Vec3 &p : positions)
    b.extend(p);
  return b;
}

ANARIGeometry newTriangleGeometry(ANARIDevice device, const TriangleMesh &mesh)
{
  ANARIGeometry geometry = anariNewGeometry(device, "triangle");
  setArray(
      device, geometry, "vertex.position", ANARI_FLOAT32_VEC3, mesh.positions);
  if (mesh.normals.size() == mesh.positions.size())
    setArray(
        device, geometry, "vertex.normal", ANARI_FLOAT32_VEC3, mesh.normals);
  if (mesh.uvs.size() == mesh.positions.size())
    setArray(
        device, geometry, "vertex.attribute0", ANARI_FLOAT32_VEC2, mesh.uvs);
  if (mesh.tangents.size() == mesh.positions.size())
    setArray(
        device, geometry, "vertex.tangent", ANARI_FLOAT32_VEC4, mesh.tangents);
  setArray(
      device, geometry, "primitive.index", ANARI_UINT32_VEC3, mesh.triangles);
  anariCommitParameters(device, geometry);
  return geometry;
}

} // namespace prism::scenes
