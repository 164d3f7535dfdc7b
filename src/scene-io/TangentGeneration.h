// Tangents for normal maps when a glTF primitive has none: glTF asks for
// the MikkTSpace method, which is what baking tools assume, so bumps look
// as their authors saw them. Our implementation of the published method.
#pragma once

#include "Math.h"

#include <array>
#include <cstdint>
#include <vector>

namespace prism::scene_io {

using scenes::Vec3;
using scenes::Vec4;
using Vec2 = std::array<float, 2>;

// One tangent per triangle corner (3 per triangle, in order): xyz in the
// surface plane, w = +1 or -1 the handedness (bitangent = cross(normal,
// tangent) * w). Corners that share a vertex (same position, normal and
// uv) and a UV orientation share one tangent, averaged over their
// triangles weighted by the corner angles; where orientation flips
// (mirrored UVs), the vertex gets one tangent per side.
std::vector<Vec4> generateTangents(const std::vector<Vec3> &positions,
    const std::vector<Vec3> &normals,
    const std::vector<Vec2> &uvs,
    const std::vector<std::array<uint32_t, 3>> &triangles);

} // namespace prism::scene_io
