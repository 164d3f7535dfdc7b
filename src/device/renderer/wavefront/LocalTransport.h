// The transport of a single process: rays traced against one world.
#pragma once

#include "../../world/World.h"
#include "RayTransport.h"

namespace prism {

class LocalTransport final : public RayTransport
{
 public:
  explicit LocalTransport(const World &world) : m_world(world) {}

  void traceClosest(rt::RayQueue &queue) const override
  {
    m_world.intersect(queue);
  }
  void traceOcclusion(rt::RayQueue &queue) const override
  {
    m_world.occluded(queue);
  }

 private:
  const World &m_world;
};

} // namespace prism
