// Wavefront OBJ + MTL (via tinyobjloader) to an ANARI world: one triangle
// geometry and physicallyBased material per MTL material, polygons
// triangulated, corners sharing (position, normal, uv) merged into vertices.
#pragma once

#include "LoadResult.h"

#include <anari/anari.h>

#include <string>

namespace prism::render {

LoadResult loadObj(ANARIDevice device, const std::string &path);

} // namespace prism::render
