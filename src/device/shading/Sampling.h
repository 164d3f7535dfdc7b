// What BSDF sampling adds to the shared warps and frames (math/): GGX
// visible normals and multiple importance sampling weights. Directions are
// unit float3 in the local shading frame (LocalFrame, z = normal) unless a
// function says otherwise; pdfs are per unit solid angle.
#pragma once

#include "math/LocalFrame.h"
#include "math/SphereSampling.h"
#include "math/Trig.h"
#include "math/Vec.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace prism {

// Visible normals of the GGX distribution seen from `wo` (wo.z > 0), after
// Heitz, "Sampling the GGX Distribution of Visible Normals" (JCGT 7(4),
// 2018): stretch to the alpha = 1 configuration, where visible normals are a
// projected hemisphere, sample that and unstretch. The pdf of the returned
// normal h is G1(wo) max(0, wo.h) D(h) / wo.z (ggxVisibleNormalPdf).
inline float3 sampleGgxVisibleNormal(
    float3 wo, float alphaX, float alphaY, float2 u)
{
  const float3 v = normalize(float3{alphaX * wo.x, alphaY * wo.y, wo.z});
  // Orthonormal basis around v; any tangent works at normal incidence.
  const float lengthSquared = v.x * v.x + v.y * v.y;
  const float3 t1 = lengthSquared > 0.f ? float3{-v.y, v.x, 0.f}
                                              * (1.f / std::sqrt(lengthSquared))
                                        : float3{1.f, 0.f, 0.f};
  const float3 t2 = cross(v, t1);
  // A disk point, squeezed onto the part of the disk that v can see.
  const float r = std::sqrt(u.x);
  const float2 cs = cosSinTurn(u.y);
  const float p1 = r * cs.x;
  const float s = 0.5f * (1.f + v.z);
  const float p2 =
      (1.f - s) * std::sqrt(max(0.f, 1.f - p1 * p1)) + s * r * cs.y;
  const float p3 = std::sqrt(max(0.f, 1.f - p1 * p1 - p2 * p2));
  const float3 n = t1 * p1 + t2 * p2 + v * p3;
  return normalize(float3{alphaX * n.x, alphaY * n.y, max(0.f, n.z)});
}

// Veach's MIS heuristics for `fCount` samples from f against `gCount` from
// g; a delta (infinite) pdf gets weight 1, a zero pdf weight 0.
inline float balanceHeuristic(int fCount, float fPdf, int gCount, float gPdf)
{
  const float f = float(fCount) * fPdf;
  const float g = float(gCount) * gPdf;
  if (std::isinf(f))
    return 1.f;
  return f > 0.f ? f / (f + g) : 0.f;
}
inline float powerHeuristic(int fCount, float fPdf, int gCount, float gPdf)
{
  const float f = float(fCount) * fPdf;
  const float g = float(gCount) * gPdf;
  if (std::isinf(f))
    return 1.f;
  if (!(f > 0.f))
    return 0.f;
  // Divide through by f so large pdfs cannot overflow when squared.
  const float ratio = g / f;
  return 1.f / (1.f + ratio * ratio);
}

} // namespace prism
