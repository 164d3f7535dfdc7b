// Where a wavefront's rays are traced. The integrator never calls Embree:
// it hands whole queues to a transport. Locally that is the world's BVH;
// the data-parallel device sends the queue around the ranks so each ray
// finds the closest hit (or any blocker) among all ranks' geometry.
#pragma once

#include "../../rt/RayQueue.h"

namespace prism {

class RayTransport
{
 public:
  virtual ~RayTransport() = default;
  // Fills in every ray's closest hit.
  virtual void traceClosest(rt::RayQueue &queue) const = 0;
  // Sets every ray's transmittance: what reaches its end (0 where an opaque
  // surface blocks it).
  virtual void traceOcclusion(rt::RayQueue &queue) const = 0;
};

} // namespace prism
