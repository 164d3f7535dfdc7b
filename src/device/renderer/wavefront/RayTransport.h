// Where a wavefront's rays are traced. The integrator never calls Embree:
// it hands whole queues to a transport. Locally that is the world's BVH;
// the data-parallel device sends the queue around the ranks so each ray
// finds the closest hit (or any blocker) among all ranks' geometry.
#pragma once

#include "../../math/Vec.h"
#include "../../rt/RayQueue.h"
#include "PathState.h"

#include <cstdint>
#include <vector>

namespace prism {

// Collisions in participating media before a ray's closest hit, as the
// integrator samples them: across processes the nearest event of any
// process's surfaces and media decides which process shades a ray.
class MediaEvents
{
 public:
  virtual ~MediaEvents() = default;
  // The distance along ray `r` of the queue at which this process's media
  // stop it before `hitDistance`, or +inf.
  virtual float collisionBefore(size_t r, float hitDistance) const = 0;
};

// What a shadow ray brings if nothing blocks it: the light sample's
// `radiance` times its `weight` against the BSDF's sample of the same
// light, or its radiance alone where the ray passed a single-sided surface
// that a BSDF's ray would stop at (rt::RayQueue::passedOneSidedAt): there
// the light sample is the only way to the light.
struct ShadowContribution
{
  float3 radiance{0.f, 0.f, 0.f};
  float weight{1.f};
};

class RayTransport
{
 public:
  virtual ~RayTransport() = default;
  // Fills in every ray's closest hit. `media` (null without volumes) is
  // for a transport that decides who shades each ray: one process leaves
  // collisions to the integrator.
  virtual void traceClosest(
      rt::RayQueue &queue, const MediaEvents *media) const = 0;
  // Sets every ray's transmittance: what reaches its end (0 where an opaque
  // surface blocks it).
  virtual void traceOcclusion(rt::RayQueue &queue) const = 0;

  // Data-parallel path tracing: after traceClosest, which rays of the
  // queue this process shades (a flag a ray; across processes, the one
  // owning the hit), or null when it shades every ray. Asked once a
  // bounce, so the integrator's per-ray test is a load, not a call.
  virtual const uint8_t *shadedRays() const
  {
    return nullptr;
  }
  // Salts the random streams of this process's media, so processes
  // holding different volumes sample independent collisions (their
  // transmittances multiply). 0 in one process and on rank 0: a world
  // whose volumes all sit on rank 0 renders as in one process.
  virtual uint32_t mediaStreamSalt() const
  {
    return 0;
  }
  // After a bounce was shaded: makes every process hold the same path
  // states and the same next and shadow queues (with their contributions),
  // ordered by tag. Nothing to do in one process.
  virtual void shareBounce(std::vector<PathState> &paths,
      const rt::RayQueue &rays,
      rt::RayQueue &next,
      rt::RayQueue &shadows,
      std::vector<ShadowContribution> &contributions) const
  {}
};

} // namespace prism
