// A square in the plane z = `z` from (x0, y0) with side `size`, split into
// side x side cells of two triangles each (lower right first): an emissive
// surface whose light tree has several levels.
#pragma once

#include "math/Vec.h"

#include <vector>

namespace prism::test {

inline std::vector<float3> squareOfCells(
    float x0, float y0, float size, float z, int side)
{
  std::vector<float3> corners;
  const float cell = size / float(side);
  for (int y = 0; y < side; y++)
    for (int x = 0; x < side; x++) {
      const float a = x0 + cell * float(x), b = a + cell;
      const float c = y0 + cell * float(y), d = c + cell;
      for (float3 corner : {float3{a, c, z},
               float3{b, c, z},
               float3{b, d, z},
               float3{a, c, z},
               float3{b, d, z},
               float3{a, d, z}})
        corners.push_back(corner);
    }
  return corners;
}

} // namespace prism::test
