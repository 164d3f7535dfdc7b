// The transport of a single process: rays traced against one world, its
// surfaces by Embree, its volumes by ratio tracking.
#pragma once

#include "../../parallel/Blocks.h"
#include "../../world/World.h"
#include "../VolumeTracing.h"
#include "RayTransport.h"
#include "SeeThroughShadows.h"

#include <bit>

namespace prism {

class LocalTransport final : public RayTransport
{
 public:
  // `streamSalt`: see RayTransport::mediaStreamSalt().
  explicit LocalTransport(const World &world, uint32_t streamSalt = 0)
      : m_world(world), m_seeThrough(world), m_streamSalt(streamSalt)
  {}

  void traceClosest(rt::RayQueue &queue, const MediaEvents *) const override
  {
    m_world.intersect(queue);
  }
  void traceOcclusion(rt::RayQueue &queue) const override
  {
    m_world.occluded(queue, &m_seeThrough);
    if (m_world.volumes().empty())
      return;
    // Each ray on its own: a larger wavefront than a tile's in blocks on
    // several threads.
    forEachBlock(queue.size(), 1024, [&](size_t begin, size_t count) {
      for (size_t i = begin; i < begin + count; i++)
        attenuateInVolumes(queue, i);
    });
  }

 private:
  // A shadow ray's transmittance through the volumes (ratio tracking).
  void attenuateInVolumes(rt::RayQueue &queue, size_t i) const
  {
    if (queue.occluded(i) || queue.untraceable(i))
      return;
    const float3 origin = queue.origin(i), direction = queue.direction(i);
    // Each ray its own random numbers, the same on every run.
    HashedStream random(
        queue.tag(i) * 0x9e3779b9u ^ m_streamSalt
        ^ std::bit_cast<uint32_t>(origin.x)
        ^ mixBits(std::bit_cast<uint32_t>(origin.y)
                  ^ mixBits(std::bit_cast<uint32_t>(direction.z + origin.z))));
    const float t = trackTransmittance(
        m_world, origin, direction, queue.tMin(i), queue.tMax(i), random);
    queue.attenuate(i, {t, t, t});
  }

  const World &m_world;
  SeeThroughShadows m_seeThrough;
  uint32_t m_streamSalt;
};

} // namespace prism
