// Where a ray crosses an axis-aligned box: the slab test.
#pragma once

#include "Vec.h"

#include <utility>

namespace prism {

// Narrows [t0, t1] to where origin + t * direction lies in `box` (faces
// included); false if nothing of it does. A direction component of 0
// keeps the interval when the origin lies within that slab.
inline bool clipRayToBox(const box3 &box,
    const float3 &origin,
    const float3 &direction,
    float &t0,
    float &t1)
{
  const float o[3] = {origin.x, origin.y, origin.z};
  const float d[3] = {direction.x, direction.y, direction.z};
  const float lo[3] = {box.lower.x, box.lower.y, box.lower.z};
  const float hi[3] = {box.upper.x, box.upper.y, box.upper.z};
  for (int a = 0; a < 3; a++) {
    if (d[a] == 0.f) {
      if (o[a] < lo[a] || o[a] > hi[a])
        return false;
      continue;
    }
    const float inverse = 1.f / d[a];
    float near = (lo[a] - o[a]) * inverse, far = (hi[a] - o[a]) * inverse;
    if (near > far)
      std::swap(near, far);
    t0 = near > t0 ? near : t0;
    t1 = far < t1 ? far : t1;
  }
  return t0 <= t1;
}

} // namespace prism
