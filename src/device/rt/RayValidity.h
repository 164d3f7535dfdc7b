// Embree (built with assertions on Debian) aborts on rays it considers
// invalid; Prism never passes it one: such rays simply find nothing.
#pragma once

#include "../math/Vec.h"

namespace prism::rt {

// Coordinates beyond this make Embree's internal arithmetic overflow.
constexpr float kLargestCoordinate = 1.8e18f;

// Finite origin and direction within Embree's range, 0 <= tMin <= tMax.
bool isTraceable(
    const float3 &origin, const float3 &direction, float tMin, float tMax);

} // namespace prism::rt
