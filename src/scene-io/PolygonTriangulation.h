// Polygons (an OBJ face's corners) to triangles in near-linear time:
// - convex polygons (the common case, at any size) become a fan, O(n);
// - concave polygons up to kMaxEarClippingCorners are ear-clipped in the
//   plane of their Newell normal, O(n * reflex corners);
// - bigger concave polygons become a fan too, flagged so the caller can warn
//   (a fan may cover area outside the polygon, but an n-corner face never
//   costs more than O(n)).
// Every polygon of n >= 3 corners gives exactly n - 2 triangles, degenerate
// ones included, so counts stay predictable.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace prism::scene_io {

// Concave polygons with more corners than this are fanned, not ear-clipped.
constexpr size_t kMaxEarClippingCorners = 4096;

struct PolygonTriangles
{
  // Corner indices (0 .. n-1) of each triangle, in the polygon's winding.
  std::vector<std::array<uint32_t, 3>> triangles;
  // True when a concave polygon was too big to ear-clip and was fanned.
  bool fannedConcave{false};
};

// `corners` are the polygon's positions in order (finite coordinates; the
// caller drops faces with others). Fewer than 3 corners give no triangles.
PolygonTriangles triangulatePolygon(
    const std::vector<std::array<float, 3>> &corners);

} // namespace prism::scene_io
