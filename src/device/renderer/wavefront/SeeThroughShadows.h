// How shadow rays meet see-through surfaces (alphaMode mask or blend): a
// hit stops one with the probability the surface's coverage there gives
// (what camera and bounce rays see of it), decided by a hash of the ray and
// the hit. Bounce rays pass such a surface by a random number of their
// own, so light reaches a point through it by light samples as often as
// by bounce rays, which multiple importance sampling relies on.
#pragma once

#include "../../rt/ShadowStops.h"
#include "../../world/World.h"

namespace prism {

class SeeThroughShadows final : public rt::ShadowStops
{
 public:
  explicit SeeThroughShadows(const World &world) : m_world(world) {}

  bool at(const float3 &origin,
      const float3 &direction,
      float time,
      const rt::Hit &hit) const override;

 private:
  const World &m_world;
};

} // namespace prism
