#include "TangentGeneration.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>

namespace prism::scene_io {
namespace {

using scenes::operator+;
using scenes::operator-;
using scenes::operator*;
using scenes::cross;
using scenes::dot;
using scenes::length;

// The direction along `v` in the plane perpendicular to unit `n`, or zero.
Vec3 inPlane(const Vec3 &v, const Vec3 &n)
{
  const Vec3 p = v - n * dot(n, v);
  const float l = length(p);
  return l > 0.f && std::isfinite(l) ? p * (1.f / l) : Vec3{0, 0, 0};
}

// Any unit vector perpendicular to `n` (for corners with no usable UVs).
Vec3 anyPerpendicular(const Vec3 &n)
{
  const Vec3 axis = std::abs(n[0]) < 0.9f ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  return inPlane(axis, n);
}

// Vertices are the same when position, normal and uv are bit-identical
// (MikkTSpace welds them, whatever their indices).
struct VertexKey
{
  float values[8];
  bool operator==(const VertexKey &o) const
  {
    return std::memcmp(values, o.values, sizeof(values)) == 0;
  }
};
struct VertexKeyHash
{
  size_t operator()(const VertexKey &k) const
  {
    size_t h = 1469598103934665603ull;
    for (float f : k.values) {
      uint32_t bits;
      std::memcpy(&bits, &f, sizeof(bits));
      h = (h ^ bits) * 1099511628211ull;
    }
    return h;
  }
};

} // namespace

std::vector<Vec4> generateTangents(const std::vector<Vec3> &positions,
    const std::vector<Vec3> &normals,
    const std::vector<Vec2> &uvs,
    const std::vector<std::array<uint32_t, 3>> &triangles)
{
  const size_t corners = triangles.size() * 3;
  std::vector<Vec4> out(corners, Vec4{1, 0, 0, 1});
  auto normalOf = [&](uint32_t v) {
    const Vec3 n = v < normals.size() ? normals[v] : Vec3{0, 0, 1};
    const float l = length(n);
    return l > 0.f && std::isfinite(l) ? n * (1.f / l) : Vec3{0, 0, 1};
  };

  // Welded vertex of every corner.
  std::unordered_map<VertexKey, uint32_t, VertexKeyHash> welded;
  std::vector<uint32_t> cornerVertex(corners);
  for (size_t c = 0; c < corners; c++) {
    const uint32_t v = triangles[c / 3][c % 3];
    const Vec3 n = normalOf(v);
    VertexKey key{};
    std::memcpy(key.values, positions[v].data(), sizeof(float) * 3);
    std::memcpy(key.values + 3, n.data(), sizeof(float) * 3);
    std::memcpy(key.values + 6, uvs[v].data(), sizeof(float) * 2);
    cornerVertex[c] =
        welded.emplace(key, uint32_t(welded.size())).first->second;
  }

  // Per triangle: the direction of increasing u in 3D (the tangent before
  // projection), and whether the UV mapping preserves orientation.
  struct Face
  {
    Vec3 tangent;
    bool preserving;
    bool usable;
  };
  std::vector<Face> faces(triangles.size());
  for (size_t f = 0; f < triangles.size(); f++) {
    const auto &t = triangles[f];
    const Vec3 e1 = positions[t[1]] - positions[t[0]];
    const Vec3 e2 = positions[t[2]] - positions[t[0]];
    const float du1 = uvs[t[1]][0] - uvs[t[0]][0];
    const float dv1 = uvs[t[1]][1] - uvs[t[0]][1];
    const float du2 = uvs[t[2]][0] - uvs[t[0]][0];
    const float dv2 = uvs[t[2]][1] - uvs[t[0]][1];
    const float area = du1 * dv2 - dv1 * du2; // twice the signed UV area
    const Vec3 s = e1 * dv2 - e2 * dv1;
    const float sign = area > 0.f ? 1.f : -1.f;
    const float l = length(s);
    faces[f].preserving = area > 0.f;
    faces[f].usable =
        area != 0.f && l > 0.f && std::isfinite(l) && std::isfinite(area);
    faces[f].tangent = faces[f].usable ? s * (sign / l) : Vec3{0, 0, 0};
  }

  // Accumulate per (welded vertex, orientation): angle-weighted tangents
  // projected into each corner's normal plane.
  auto groupOf = [&](size_t c) {
    return uint64_t(cornerVertex[c]) * 2 + (faces[c / 3].preserving ? 1 : 0);
  };
  std::unordered_map<uint64_t, Vec3> sums;
  for (size_t c = 0; c < corners; c++) {
    const Face &face = faces[c / 3];
    if (!face.usable)
      continue;
    const auto &t = triangles[c / 3];
    const uint32_t v = t[c % 3];
    const Vec3 n = normalOf(v);
    const Vec3 a = inPlane(positions[t[(c + 1) % 3]] - positions[v], n);
    const Vec3 b = inPlane(positions[t[(c + 2) % 3]] - positions[v], n);
    const float angle = std::acos(std::clamp(dot(a, b), -1.f, 1.f));
    Vec3 &sum = sums[groupOf(c)];
    sum = sum + inPlane(face.tangent, n) * angle;
  }

  for (size_t c = 0; c < corners; c++) {
    const Face &face = faces[c / 3];
    const uint32_t v = triangles[c / 3][c % 3];
    const Vec3 n = normalOf(v);
    // A corner of a degenerate triangle takes what its vertex has on
    // either side, else any perpendicular.
    auto it = sums.find(groupOf(c));
    if (it == sums.end() || length(it->second) == 0.f)
      it = sums.find(groupOf(c) ^ 1);
    Vec3 tangent = it != sums.end() ? inPlane(it->second, n) : Vec3{0, 0, 0};
    if (length(tangent) == 0.f)
      tangent = anyPerpendicular(n);
    // glTF's normal maps point +Y up the image, where its v decreases: w
    // turns cross(N, T) that way, as MikkTSpace gives it on the v-up
    // coordinates glTF exporters run it on (w is -1 where the mapping
    // preserves orientation in glTF's own v-down coordinates).
    out[c] = {tangent[0], tangent[1], tangent[2], face.preserving ? -1.f : 1.f};
  }
  return out;
}

} // namespace prism::scene_io
