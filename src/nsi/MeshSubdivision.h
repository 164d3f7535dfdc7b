// A mesh's `subdivision.*` attributes read for SubdivisionSurface: which
// level to refine to, and its creases and corners. Bad values are reported
// and left out; they never stop the mesh from rendering.
#pragma once

#include "Graph.h"
#include "SubdivisionSurface.h"

#include <functional>
#include <string>

namespace prism::nsi {

// How many times to refine the mesh: 0 renders the cage (no
// `subdivision.scheme`, another scheme than catmull-clark, holes: the last
// two reported). The level is the mesh's `subdivision.level`, else
// `fallback` (`.global`'s, else kDefaultSubdivisionLevel), at most
// kMaxSubdivisionLevel.
int subdivisionLevelOf(const std::string &handle,
    const Node &mesh,
    int fallback,
    bool hasHoles,
    const std::function<void(int, const std::string &)> &report);

// subdivision.creasevertices/creasesharpness and cornervertices/
// cornersharpness (also spelt cornerssharpness) into `cage`, for a mesh of
// `pointCount` points.
void readCreasesAndCorners(const std::string &handle,
    const Node &mesh,
    size_t pointCount,
    const std::function<void(int, const std::string &)> &report,
    SubdivisionCage &cage);

} // namespace prism::nsi
