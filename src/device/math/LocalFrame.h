// The one orthonormal frame construction of the device: a BSDF's shading
// frame, a light's frame, the ambient-occlusion renderer's hemisphere all
// turn local directions (z = the axis) into world space with it.
#pragma once

#include "Vec.h"

#include <cmath>

namespace prism {

// Two unit vectors completing unit `n` to a right-handed orthonormal basis,
// by Duff et al., "Building an Orthonormal Basis, Revisited" (JCGT 6(1),
// 2017): branch-free apart from the sign, continuous except at n.z = 0's
// sign flip, and accurate for n near -z where Frisvad's version fails.
inline void orthonormalBasis(float3 n, float3 &b1, float3 &b2)
{
  const float sign = std::copysign(1.f, n.z);
  const float a = -1.f / (sign + n.z);
  const float b = n.x * n.y * a;
  b1 = {1.f + sign * n.x * n.x * a, sign * b, -sign * n.x};
  b2 = {b, sign + n.y * n.y * a, -n.y};
}

// Three orthonormal axes, `z` given; world = x * l.x + y * l.y + z * l.z.
struct LocalFrame
{
  float3 x, y, z;

  // A frame around the unit `z`; any x: right for what is symmetric about
  // z (isotropic BSDFs, cones, hemispheres).
  static LocalFrame around(float3 z)
  {
    LocalFrame frame;
    frame.z = z;
    orthonormalBasis(z, frame.x, frame.y);
    return frame;
  }
  // A frame around the unit `z` whose x axis is `xHint` made orthogonal to
  // z (a quad's edge, a light's C0 direction); around(z) when the hint is
  // (nearly) parallel to z.
  static LocalFrame around(float3 z, float3 xHint)
  {
    const float3 x = xHint - z * dot(xHint, z);
    const float length2 = lengthSquared(x);
    if (!(length2 > 1e-12f * max(lengthSquared(xHint), 1e-30f)))
      return around(z);
    const float3 xUnit = x / std::sqrt(length2);
    return {xUnit, cross(z, xUnit), z};
  }

  float3 toWorld(float3 local) const
  {
    return x * local.x + y * local.y + z * local.z;
  }
  float3 toLocal(float3 world) const
  {
    return {dot(world, x), dot(world, y), dot(world, z)};
  }
};

} // namespace prism
