// Embree (built with assertions on Debian) aborts on rays it considers
// invalid; Prism never passes it one: such rays simply find nothing.
#pragma once

#include "../math/Vec.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace prism::rt {

// Coordinates beyond this make Embree's internal arithmetic overflow.
constexpr float kLargestCoordinate = 1.8e18f;

// Finite origin and direction within Embree's range (or a scene's smaller
// one, see worldRayRange()), 0 <= tMin <= tMax, tMin finite. Every ray
// passes here: comparisons (false for NaN) joined without branches.
inline bool isTraceable(const float3 &origin,
    const float3 &direction,
    float tMin,
    float tMax,
    float k = kLargestCoordinate)
{
  return (std::abs(origin.x) <= k) & (std::abs(origin.y) <= k)
         & (std::abs(origin.z) <= k) & (std::abs(direction.x) <= k)
         & (std::abs(direction.y) <= k) & (std::abs(direction.z) <= k)
         & (tMin >= 0.f) & (tMin <= FLT_MAX) & (tMax >= tMin);
}

// Embree moves rays into an instance's space itself, where they must be in
// its range too: the largest coordinate a world-space ray may have so that
// `objectFromWorld` keeps it there (0 or less: no ray can be traced).
inline float worldRayRange(const mat3x4 &objectFromWorld)
{
  const float3 *c = objectFromWorld.col;
  // The linear part's infinity norm (largest row sum) and the translation.
  const float norm =
      std::max(std::abs(c[0].x) + std::abs(c[1].x) + std::abs(c[2].x),
          std::max(std::abs(c[0].y) + std::abs(c[1].y) + std::abs(c[2].y),
              std::abs(c[0].z) + std::abs(c[1].z) + std::abs(c[2].z)));
  const float shift =
      std::max(std::abs(c[3].x), std::max(std::abs(c[3].y), std::abs(c[3].z)));
  if (!(norm <= FLT_MAX) || !(shift <= FLT_MAX))
    return 0.f;
  const float range = (kLargestCoordinate - shift) / std::max(norm, FLT_MIN);
  return std::min(range, kLargestCoordinate);
}

} // namespace prism::rt
