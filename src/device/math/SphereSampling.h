// Warps from the unit square to the disk, the hemisphere, the sphere and
// spherical caps, with their pdfs: the one home of the sampling math that
// BSDFs, lights and the ambient-occlusion renderer share. Directions are
// unit float3 in a local frame (z = the axis, LocalFrame.h); pdfs are per
// unit solid angle.
#pragma once

#include "Trig.h"
#include "Vec.h"

#include <cmath>
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

// A direction uniform in the cap around +z of height `capHeight` = 1 -
// cos(half angle) (a spherical light or the sun seen from a point). The
// cap height rather than the cosine, and sin^2 formed as h (2 - h), keep
// tiny cones from rounding to a single direction.
inline float3 sampleUniformCap(float2 u, float capHeight)
{
  const float h = u.x * capHeight;
  const float cosTheta = 1.f - h;
  const float sinTheta = std::sqrt(max(0.f, h * (2.f - h)));
  const float2 cs = cosSinTurn(u.y);
  return {cs.x * sinTheta, cs.y * sinTheta, cosTheta};
}
// Its pdf per steradian inside the cap.
inline float uniformCapPdf(float capHeight)
{
  return 1.f / (2.f * std::numbers::pi_v<float> * capHeight);
}

} // namespace prism
