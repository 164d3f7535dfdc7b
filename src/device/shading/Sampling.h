// Warps from the unit square to directions, multiple importance sampling
// weights and the local shading frame. Directions are unit float3 in the
// local frame (z = normal) unless a function says otherwise; pdfs are per
// unit solid angle.
#pragma once

#include "math/Trig.h"
#include "math/Vec.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace prism {

// Shirley & Chiu's concentric map: keeps strata compact, unlike the polar map.
inline float2 sampleConcentricDisk(float2 u)
{
  constexpr float kQuarterPi = std::numbers::pi_v<float> / 4.f;
  const float a = 2.f * u.x - 1.f;
  const float b = 2.f * u.y - 1.f;
  if (a == 0.f && b == 0.f)
    return {0.f, 0.f};
  // Selects rather than branches: which side wins is a coin toss per
  // sample, which a branch predictor cannot learn. In the narrow case the
  // angle is pi/2 - theta: cosine and sine swap.
  const bool wide = std::abs(a) > std::abs(b);
  const float radius = wide ? a : b;
  const float2 cs = cosSinQuarter(kQuarterPi * ((wide ? b : a) / radius));
  return {radius * (wide ? cs.x : cs.y), radius * (wide ? cs.y : cs.x)};
}

// Malley's method: project the disk up to the hemisphere; pdf cos(theta)/pi.
inline float3 sampleCosineHemisphere(float2 u)
{
  const float2 d = sampleConcentricDisk(u);
  const float z = std::sqrt(max(0.f, 1.f - d.x * d.x - d.y * d.y));
  return {d.x, d.y, z};
}
inline float cosineHemispherePdf(float cosTheta)
{
  return cosTheta > 0.f ? cosTheta * std::numbers::inv_pi_v<float> : 0.f;
}

inline float3 sampleUniformHemisphere(float2 u)
{
  const float z = u.x;
  const float r = std::sqrt(max(0.f, 1.f - z * z));
  const float2 cs = cosSinTurn(u.y);
  return {r * cs.x, r * cs.y, z};
}
inline float uniformHemispherePdf()
{
  return 0.5f * std::numbers::inv_pi_v<float>;
}

inline float3 sampleUniformSphere(float2 u)
{
  const float z = 1.f - 2.f * u.x;
  const float r = std::sqrt(max(0.f, 1.f - z * z));
  const float2 cs = cosSinTurn(u.y);
  return {r * cs.x, r * cs.y, z};
}
inline float uniformSpherePdf()
{
  return 0.25f * std::numbers::inv_pi_v<float>;
}

// Directions within `cosThetaMax` of +z (e.g. a spherical light seen from a
// point); sin^2 is formed as (1 - cos)(1 + cos) so tiny cones stay accurate.
inline float3 sampleUniformCone(float2 u, float cosThetaMax)
{
  const float oneMinusCos = u.x * (1.f - cosThetaMax);
  const float z = 1.f - oneMinusCos;
  const float r = std::sqrt(max(0.f, oneMinusCos * (2.f - oneMinusCos)));
  const float2 cs = cosSinTurn(u.y);
  return {r * cs.x, r * cs.y, z};
}
inline float uniformConePdf(float cosThetaMax)
{
  return 1.f / (2.f * std::numbers::pi_v<float> * (1.f - cosThetaMax));
}

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

// The local shading frame of a hit: world space <-> local space, z = normal.
struct ShadingFrame
{
  float3 tangent, bitangent, normal;

  // Any tangent: right for isotropic BSDFs, which are all Prism has.
  static ShadingFrame fromNormal(float3 normal)
  {
    ShadingFrame frame;
    frame.normal = normal;
    orthonormalBasis(normal, frame.tangent, frame.bitangent);
    return frame;
  }
  // Keeps `tangent`'s direction (e.g. from UVs) after Gram-Schmidt; falls
  // back to fromNormal when it is parallel to the normal.
  static ShadingFrame fromNormalTangent(float3 normal, float3 tangent)
  {
    const float3 t = tangent - normal * dot(normal, tangent);
    const float lengthSquared = dot(t, t);
    if (!(lengthSquared > 1e-12f))
      return fromNormal(normal);
    ShadingFrame frame;
    frame.normal = normal;
    frame.tangent = t * (1.f / std::sqrt(lengthSquared));
    frame.bitangent = cross(normal, frame.tangent);
    return frame;
  }

  float3 toLocal(float3 world) const
  {
    return {dot(world, tangent), dot(world, bitangent), dot(world, normal)};
  }
  float3 toWorld(float3 local) const
  {
    return tangent * local.x + bitangent * local.y + normal * local.z;
  }
};

} // namespace prism
