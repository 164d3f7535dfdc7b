// Whether a shadow ray stops at a hit on a see-through surface
// (Scene::letShadowsThrough): the renderer knows the surface's opacity
// there, the scene only where the ray met it.
#pragma once

#include "Hit.h"

namespace prism::rt {

class ShadowStops
{
 public:
  virtual ~ShadowStops() = default;
  // At `hit` (its instanceId as the traced scene has it: kInvalidId in a
  // group's scene traced directly) of the ray from `origin` along
  // `direction` at `time`. Embree may offer the same hit more than once:
  // the answer must be the same each time.
  virtual bool at(const float3 &origin,
      const float3 &direction,
      float time,
      const Hit &hit) const = 0;
};

} // namespace prism::rt
