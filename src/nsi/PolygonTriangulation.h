// Triangles covering one planar polygon, convex or not, with or without
// holes, by ear clipping in the plane the polygon faces most (holes are
// first bridged into the outline). Triangles keep the outline's winding.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace prism::nsi {

using Corner = std::array<double, 3>;

// Corners index `corners`; degenerate polygons still get triangles (a fan),
// so a face never silently disappears.
std::vector<std::array<uint32_t, 3>> triangulatePolygon(
    const std::vector<Corner> &corners);

// `loops[0]` is the outline, the others holes in it. Corners are numbered
// through all loops in order (the outline's first, then each hole's).
std::vector<std::array<uint32_t, 3>> triangulatePolygonWithHoles(
    const std::vector<std::vector<Corner>> &loops);

} // namespace prism::nsi
