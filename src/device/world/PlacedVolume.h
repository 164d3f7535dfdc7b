// One placement of a volume in the world: the volume, how the placement
// maps world to the volume's object space, and the world-space box it
// covers. Rays keep their parameter t across the mapping (it is affine),
// so distances along a ray are world-space distances.
#pragma once

#include "../math/RayBox.h"
#include "../volume/Volume.h"

#include <cstdint>

namespace prism {

struct PlacedVolume
{
  const Volume *volume;
  mat3x4 objectFromWorld;
  box3 worldBounds;
  uint32_t instanceId; // the user's id of the instance (~0u when unset)

  // The entry and exit distances of the world-space ray within the
  // volume's object-space bounds, clipped to [tMin, tMax]; false if the
  // ray misses it there. Also the ray in object space.
  bool clip(const float3 &origin,
      const float3 &direction,
      float tMin,
      float tMax,
      float &t0,
      float &t1,
      float3 &objectOrigin,
      float3 &objectDirection) const
  {
    objectOrigin = transformPoint(objectFromWorld, origin);
    objectDirection = transformDirection(objectFromWorld, direction);
    t0 = tMin;
    t1 = tMax;
    return clipRayToBox(volume->bounds(), objectOrigin, objectDirection, t0, t1)
           && t0 < t1;
  }
};

} // namespace prism
