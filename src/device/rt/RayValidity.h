// Embree (built with assertions on Debian) aborts on rays it considers
// invalid; Prism never passes it one: such rays simply find nothing.
#pragma once

#include "../math/Vec.h"

#include <cfloat>
#include <cmath>

namespace prism::rt {

// Coordinates beyond this make Embree's internal arithmetic overflow.
constexpr float kLargestCoordinate = 1.8e18f;

// Finite origin and direction within Embree's range, 0 <= tMin <= tMax,
// tMin finite. Every ray passes here: comparisons (false for NaN) joined
// without branches.
inline bool isTraceable(
    const float3 &origin, const float3 &direction, float tMin, float tMax)
{
  constexpr float k = kLargestCoordinate;
  return (std::abs(origin.x) <= k) & (std::abs(origin.y) <= k)
         & (std::abs(origin.z) <= k) & (std::abs(direction.x) <= k)
         & (std::abs(direction.y) <= k) & (std::abs(direction.z) <= k)
         & (tMin >= 0.f) & (tMin <= FLT_MAX) & (tMax >= tMin);
}

} // namespace prism::rt
