// Triangles covering one planar polygon, convex or not, by ear clipping in
// the plane the polygon faces most. Triangles keep the polygon's winding.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace prism::nsi {

// Corners index `corners`; degenerate polygons still get triangles (a fan),
// so a face never silently disappears.
std::vector<std::array<uint32_t, 3>> triangulatePolygon(
    const std::vector<std::array<double, 3>> &corners);

} // namespace prism::nsi
