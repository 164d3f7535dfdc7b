// Primitives Embree has no native form for (flat-capped cylinders and
// cones): the geometry supplies bounds and an exact intersection.
#pragma once

#include "../math/Vec.h"

#include <cstdint>

namespace prism::rt {

class UserGeometry
{
 public:
  virtual ~UserGeometry() = default;
  virtual box3 primitiveBounds(uint32_t primitive) const = 0;
  // The nearest hit with t in (tMin, tMax) of the ray on `primitive`: t,
  // u, v and the unnormalised geometric normal; false when there is none.
  // `reportedPrimitive` arrives as `primitive` and is the primitiveId the
  // hit reports: geometries whose Embree primitives are not the spec's
  // primitives (isosurface blocks) set it.
  virtual bool intersectPrimitive(uint32_t primitive,
      const float3 &origin,
      const float3 &direction,
      float tMin,
      float tMax,
      float &t,
      float &u,
      float &v,
      float3 &normal,
      uint32_t &reportedPrimitive) const = 0;
};

} // namespace prism::rt
