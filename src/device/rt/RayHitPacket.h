// Eight coherent rays and, after tracing, their closest hits, laid out
// exactly as Embree's RTCRayHit8 (checked in Scene.cpp): Scene traces the
// packet in place, so primary rays are written once and hits read straight
// from where Embree leaves them, with no repacking on either side.
#pragma once

#include <cstdint>

namespace prism::rt {

struct alignas(32) RayHitPacket
{
  static constexpr int kLanes = 8;

  // The rays; callers fill origin, direction, tMin, tMax and time.
  float originX[kLanes], originY[kLanes], originZ[kLanes];
  float tMin[kLanes];
  float directionX[kLanes], directionY[kLanes], directionZ[kLanes];
  float time[kLanes]; // within the shutter, [0, 1]
  float tMax[kLanes]; // after tracing: the hit distance where one was found
  uint32_t mask[kLanes], id[kLanes], flags[kLanes]; // set by Scene

  // The hits, valid where geometryId != kInvalidId; ids as in rt::Hit.
  float normalX[kLanes], normalY[kLanes], normalZ[kLanes]; // unnormalised
  float u[kLanes], v[kLanes];
  uint32_t primitiveId[kLanes];
  uint32_t geometryId[kLanes];
  uint32_t instanceId[kLanes];
};

} // namespace prism::rt
