#include "ObjBatches.h"

#include "PolygonTriangulation.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace prism::scene_io {
namespace {

template <size_t N>
bool isFinite(const std::array<float, N> &v)
{
  return std::all_of(
      v.begin(), v.end(), [](float x) { return std::isfinite(x); });
}

} // namespace

ObjBatches buildObjBatches(
    const ObjParseResult &obj, const std::vector<int> &materialOf)
{
  ObjBatches out;
  out.hasColors = std::any_of(
      obj.colors.begin(), obj.colors.end(), [](const std::array<float, 3> &c) {
        return c[0] != 1.f || c[1] != 1.f || c[2] != 1.f;
      });
  // Merged vertices per batch: (position, normal, uv) -> vertex.
  std::map<int, std::map<std::tuple<uint32_t, int64_t, int64_t>, uint32_t>>
      vertexOf;
  std::vector<std::array<float, 3>> polygon;
  for (const ObjFace &face : obj.faces) {
    const ObjCorner *corners = obj.corners.data() + face.firstCorner;
    bool finite = true;
    for (size_t k = 0; k < face.cornerCount && finite; k++) {
      const ObjCorner &c = corners[k];
      finite = isFinite(obj.positions[c.position])
               && (obj.colors.empty() || isFinite(obj.colors[c.position]))
               && (c.normal < 0 || isFinite(obj.normals[size_t(c.normal)]))
               && (c.uv < 0 || isFinite(obj.uvs[size_t(c.uv)]));
    }
    if (!finite) {
      out.droppedFaces++;
      continue;
    }
    polygon.resize(face.cornerCount);
    for (size_t k = 0; k < face.cornerCount; k++)
      polygon[k] = obj.positions[corners[k].position];
    const PolygonTriangles triangulated = triangulatePolygon(polygon);
    if (triangulated.fannedConcave) {
      out.fannedConcave++;
      out.largestFannedCorners =
          std::max(out.largestFannedCorners, face.cornerCount);
    }

    const int material =
        face.material >= 0 && size_t(face.material) < materialOf.size()
            ? materialOf[size_t(face.material)]
            : -1;
    ObjBatch &batch = out.byMaterial[material + 1];
    auto &merged = vertexOf[material + 1];
    // The face's corners as batch vertices, made on first use.
    std::vector<uint32_t> vertex(face.cornerCount);
    for (size_t k = 0; k < face.cornerCount; k++) {
      const ObjCorner &c = corners[k];
      batch.allNormals = batch.allNormals && c.normal >= 0;
      batch.allUvs = batch.allUvs && c.uv >= 0;
      const auto key = std::make_tuple(c.position, c.normal, c.uv);
      auto found = merged.find(key);
      if (found == merged.end()) {
        batch.positions.push_back(obj.positions[c.position]);
        if (out.hasColors)
          batch.colors.push_back(obj.colors[c.position]);
        batch.normals.push_back(c.normal >= 0
                                    ? obj.normals[size_t(c.normal)]
                                    : std::array<float, 3>{0.f, 0.f, 0.f});
        batch.uvs.push_back(
            c.uv >= 0 ? obj.uvs[size_t(c.uv)] : std::array<float, 2>{0.f, 0.f});
        found = merged.emplace(key, uint32_t(batch.positions.size() - 1)).first;
      }
      vertex[k] = found->second;
    }
    for (const auto &t : triangulated.triangles)
      batch.triangles.push_back({vertex[t[0]], vertex[t[1]], vertex[t[2]]});
  }
  for (auto it = out.byMaterial.begin(); it != out.byMaterial.end();)
    it =
        it->second.triangles.empty() ? out.byMaterial.erase(it) : std::next(it);
  return out;
}

} // namespace prism::scene_io
