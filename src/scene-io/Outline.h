// A scene's outline: a few of its surface points, enough to frame a camera
// on the shape itself rather than on its bounding box (whose corners, seen
// from an angle, reach far past a round model's silhouette: it filled about
// half of the frame).
#pragma once

#include "Math.h"

#include <vector>

namespace prism::scene_io {

// The most points an outline keeps per mesh (before placement).
constexpr size_t kOutlinePerMesh = 512;
// The most points a scene's outline holds; a scene with more placements of
// its meshes than fit frames on its bounds instead.
constexpr size_t kMaxOutline = 1 << 16;

// Adds to `outline` the points among `count` (x, y, z) triples at `xyz`
// that reach furthest along each of 26 directions (the cube's faces, edges
// and corners), plus an even sample of the rest, at most kOutlinePerMesh in
// all.
void sampleOutline(
    const float *xyz, size_t count, std::vector<scenes::Vec3> &outline);

} // namespace prism::scene_io
