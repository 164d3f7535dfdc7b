// A parsed OBJ's faces as ANARI triangle geometries: one batch per material,
// polygons triangulated (PolygonTriangulation.h), corners sharing (position,
// normal, uv) merged into indexed vertices. Faces using a value that is not a
// finite number are dropped here, so none reaches the device.
#pragma once

#include "ObjParser.h"

#include <array>
#include <cstdint>
#include <map>
#include <vector>

namespace prism::scene_io {

struct ObjBatch
{
  std::vector<std::array<float, 3>> positions;
  std::vector<std::array<float, 3>> normals; // zero where a corner has none
  std::vector<std::array<float, 2>> uvs;     // zero where a corner has none
  std::vector<std::array<float, 3>> colors;  // empty without vertex colors
  std::vector<std::array<uint32_t, 3>> triangles;
  bool allNormals{true}; // every corner had a normal
  bool allUvs{true};     // every corner had a texture coordinate
};

struct ObjBatches
{
  // By MTL material index + 1 (0: faces without a known material); only
  // batches with triangles.
  std::map<int, ObjBatch> byMaterial;
  bool hasColors{false};   // some vertex has a color other than white
  size_t droppedFaces{0};  // faces using a non-finite value
  size_t fannedConcave{0}; // concave faces too big to ear-clip
  size_t largestFannedCorners{0};
};

// `materialOf[i]` is the MTL material index for obj.materialNames[i], or -1.
ObjBatches buildObjBatches(
    const ObjParseResult &obj, const std::vector<int> &materialOf);

} // namespace prism::scene_io
