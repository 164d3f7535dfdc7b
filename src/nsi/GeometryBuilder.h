// NSI `mesh` and `particles` nodes to triangles and spheres. Bad data (index
// out of range, counts that disagree) is reported and the geometry dropped
// or the face skipped; it never reads past an array.
#pragma once

#include "Graph.h"
#include "ResolvedScene.h"

#include <functional>
#include <optional>

namespace prism::nsi {

using ReportFunction = std::function<void(int level, const std::string &)>;

// Polygons (nvertices, nholes, P, P.indices) with their N, st and Cs,
// ear-clipped, so concave ones are right too. With two or more shutter
// `times`, P and N time samples become position and normal keys at those
// times (triangulated at the first); P samples of different lengths are
// reported (NSIErrError) and the first sample is rendered. A mesh with
// subdivision.scheme "catmull-clark" is refined to its subdivision.level,
// else `subdivisionLevel` (see MeshSubdivision.h), and its limit surface
// rendered.
std::optional<GeometryData> buildMesh(const std::string &handle,
    const Node &mesh,
    const ReportFunction &report,
    const std::vector<double> &times = {},
    int subdivisionLevel = kDefaultSubdivisionLevel);

// P and width (one per particle, or one for all; default 1).
std::optional<GeometryData> buildParticles(const std::string &handle,
    const Node &particles,
    const ReportFunction &report);

} // namespace prism::nsi
