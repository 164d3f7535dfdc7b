// A mesh's primitive variables (N, st, Cs) as one value per face vertex,
// however NSI gave them: through `<name>.indices` (an index per face
// corner), per point (shared like P through P.indices), per face vertex,
// per face or one for all. Meshes keep one vertex per face vertex, so this
// is face-varying data without welding. Bad data is reported and dropped.
#pragma once

#include "Graph.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace prism::nsi {

struct MeshLayout
{
  size_t pointCount{0};
  // The point of each face vertex (empty: face vertex k is point k).
  std::vector<int64_t> pointIndices;
  std::vector<uint32_t> faceOfVertex; // one per face vertex
  size_t faceCount{0};
};

// `components` floats per face vertex, or empty when `name` is absent or
// unusable (then reported through `report` with NSIErrWarning).
std::vector<float> faceVertexValues(const std::string &handle,
    const Node &mesh,
    const std::string &name,
    size_t components,
    const MeshLayout &layout,
    const std::function<void(int, const std::string &)> &report);

} // namespace prism::nsi
