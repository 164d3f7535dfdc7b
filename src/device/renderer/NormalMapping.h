// Normal maps: the shading normal bent by a material's tangent-space
// normal map, one definition for every renderer that shows it.
#pragma once

#include "SurfaceHit.h"

namespace prism {

// The tangent frame around `normal` (world space): the geometry's tangent
// made orthogonal to it and the bitangent from the tangent's sign, or any
// frame around it without tangents. False when the tangent is parallel to
// the normal.
bool tangentFrame(const SurfaceHit &surface,
    const rt::Hit &hit,
    const float3 &normal,
    float3 &tangent,
    float3 &bitangent);

// `normal` (the geometry's own shading normal at the hit, world space)
// bent by a tangent-space normal map value; `normal` itself where the map
// gives nothing usable or would turn the surface away from the viewer.
float3 normalMapped(const SurfaceHit &surface,
    const rt::Hit &hit,
    const float3 &normal,
    const float3 &mapped,
    const float3 &towardsViewer);

// The shading normal with the material's normal map applied (unchanged
// for materials without one), facing the viewer as the hit's does.
float3 shadingNormalWithMap(
    const SurfaceHit &surface, const rt::Hit &hit, const float3 &towardsViewer);

} // namespace prism
