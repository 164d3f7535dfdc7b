// A geometry's surface as next-event estimation samples it when its
// material glows: triangles (quads split in two) and spheres, in the
// geometry's object space.
#pragma once

#include "../math/Vec.h"

#include <vector>

namespace prism {

struct EmitterShape
{
  std::vector<float3> triangles; // three corners each
  std::vector<float4> spheres;   // center and radius
};

} // namespace prism
