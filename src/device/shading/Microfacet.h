// Microfacet distributions in the local frame (z = normal), as glTF 2.0
// appendix B and KHR_materials_sheen define them: GGX / Trowbridge-Reitz with
// Smith height-correlated masking-shadowing, and the "Charlie" sheen of
// Estevez & Kulla 2017. `alpha` is the width (roughness squared); directions
// are unit vectors; D is per unit solid angle of the microfacet normal.
#pragma once

#include "math/Vec.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace prism {

// GGX normal distribution D(h). The denominator uses h.x^2 + h.y^2 rather
// than 1 - cos^2 so that near-mirror lobes (alpha ~ 1e-4) keep full precision.
inline float ggxD(float3 h, float alpha)
{
  if (h.z <= 0.f)
    return 0.f;
  const float a2 = alpha * alpha;
  const float s = h.x * h.x + h.y * h.y + a2 * h.z * h.z;
  return a2 / (std::numbers::pi_v<float> * s * s);
}

// Anisotropic GGX D(h) with widths alphaX along the frame's x axis and
// alphaY along y: 1 / (pi ax ay (hx^2/ax^2 + hy^2/ay^2 + hz^2)^2).
inline float ggxD(float3 h, float alphaX, float alphaY)
{
  if (h.z <= 0.f)
    return 0.f;
  const float x = h.x / alphaX, y = h.y / alphaY;
  const float s = x * x + y * y + h.z * h.z;
  return 1.f / (std::numbers::pi_v<float> * alphaX * alphaY * s * s);
}

// Anisotropic Smith Lambda: the isotropic one at the width w's azimuth
// sees, sqrt(ax^2 cos^2 phi + ay^2 sin^2 phi).
inline float ggxLambda(float3 w, float alphaX, float alphaY)
{
  const float z2 = w.z * w.z;
  if (z2 == 0.f)
    return std::numeric_limits<float>::infinity();
  const float x = alphaX * w.x, y = alphaY * w.y;
  return 0.5f * (std::sqrt(1.f + (x * x + y * y) / z2) - 1.f);
}

// Smith's Lambda for GGX; symmetric in the sign of w.z.
inline float ggxLambda(float3 w, float alpha)
{
  const float z2 = w.z * w.z;
  if (z2 == 0.f)
    return std::numeric_limits<float>::infinity();
  const float tan2 = (w.x * w.x + w.y * w.y) / z2;
  return 0.5f * (std::sqrt(1.f + alpha * alpha * tan2) - 1.f);
}

// Masking of one direction: the fraction of visible microfacets.
inline float ggxG1(float3 w, float alpha)
{
  return 1.f / (1.f + ggxLambda(w, alpha));
}

// Height-correlated masking-shadowing (Heitz 2014), the glTF choice.
inline float ggxG2(float3 wo, float3 wi, float alpha)
{
  return 1.f / (1.f + ggxLambda(wo, alpha) + ggxLambda(wi, alpha));
}

// Density of the normals visible from wo (wo.z > 0): the pdf of
// sampleGgxVisibleNormal.
inline float ggxVisibleNormalPdf(float3 wo, float3 h, float alpha)
{
  const float cosOH = dot(wo, h);
  if (cosOH <= 0.f || wo.z <= 0.f)
    return 0.f;
  return ggxG1(wo, alpha) * cosOH * ggxD(h, alpha) / wo.z;
}

// Charlie width from sheenRoughness (alpha = r^2 as glTF maps it). Roughness
// is clamped at 0.05: below it the lobe hugs the horizon so tightly that no
// float evaluation or table resolves it, and it reflects almost nothing.
inline float charlieAlpha(float sheenRoughness)
{
  const float r = clamp(sheenRoughness, 0.05f, 1.f);
  return r * r;
}

// Charlie sheen distribution: (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi).
inline float charlieD(float3 h, float alpha)
{
  const float inverseAlpha = 1.f / alpha;
  const float sin2 = min(1.f, h.x * h.x + h.y * h.y);
  return (2.f + inverseAlpha) * std::pow(sin2, 0.5f * inverseAlpha)
         * (0.5f * std::numbers::inv_pi_v<float>);
}

// Estevez & Kulla's fit of the Charlie Lambda, through the curve
// L(x) = a / (1 + b x^c) + d x + e whose coefficients blend between the
// published fits for alpha = 0 and alpha = 1 by (1 - alpha)^2.
inline float charlieL(float x, float alpha)
{
  const float t = (1.f - alpha) * (1.f - alpha);
  const float a = lerp(21.5473f, 25.3245f, t);
  const float b = lerp(3.82987f, 3.32435f, t);
  const float c = lerp(0.19823f, 0.16801f, t);
  const float d = lerp(-1.97760f, -1.27393f, t);
  const float e = lerp(-4.32054f, -4.85967f, t);
  return a / (1.f + b * std::pow(x, c)) + d * x + e;
}
inline float charlieLambda(float cosTheta, float alpha)
{
  const float c = min(std::abs(cosTheta), 1.f);
  // The fit is only good below 0.5; mirror it about 0.5 above.
  return c < 0.5f
             ? std::exp(charlieL(c, alpha))
             : std::exp(2.f * charlieL(0.5f, alpha) - charlieL(1.f - c, alpha));
}

// The sheen BRDF's visibility G / (4 |cos_o| |cos_i|), height-correlated.
inline float charlieVisibility(float cosO, float cosI, float alpha)
{
  const float g =
      1.f / (1.f + charlieLambda(cosO, alpha) + charlieLambda(cosI, alpha));
  return g / (4.f * std::abs(cosO) * std::abs(cosI));
}

// Mirror reflection of w about the unit normal n (both pointing away).
inline float3 reflectDirection(float3 w, float3 n)
{
  return n * (2.f * dot(w, n)) - w;
}

// Refraction of w (pointing away, on n's side) into the other side, with
// eta = index on w's side / index on the far side (Snell: sin_t = eta sin_i).
// False under total internal reflection.
inline bool refractDirection(float3 w, float3 n, float eta, float3 &refracted)
{
  const float cosI = dot(w, n);
  const float sin2T = eta * eta * max(0.f, 1.f - cosI * cosI);
  if (sin2T >= 1.f)
    return false;
  const float cosT = std::sqrt(1.f - sin2T);
  refracted = w * -eta + n * (eta * cosI - cosT);
  return true;
}

} // namespace prism
