// Directional albedos of the microfacet lobes, which the BSDF needs to put
// back the energy single scattering loses (Kulla & Conty 2017) and to layer
// lobes without creating energy. Generated once per process on first use
// (about 50 ms, deterministic); lookups are bilinear in (sqrt(cos theta),
// roughness) and thread-safe.
#pragma once

namespace prism {

// Albedos of a GGX reflection lobe D G2 / (4 cos_o cos_i) at one roughness.
// With Schlick's Fresnel the lobe's albedo is linear in f0 and f90:
//   E_F(mu) = f0 (total - schlick) + f90 schlick.
struct GgxAlbedo
{
  // E(mu): the albedo with F = 1, short of 1 by what single scattering loses.
  float total;
  float schlick;        // the part weighted by (1 - wo.h)^5
  float average;        // 2 * integral of total(mu) mu dmu over [0, 1]
  float schlickAverage; // 2 * integral of schlick(mu) mu dmu over [0, 1]
  // Albedo-weighted mean of cos(wo, h): where to evaluate a Fresnel curve
  // that is not Schlick's (the thin film) to estimate its lobe average.
  float meanCos;
};

// `cosTheta` of the direction from the normal; glTF's alpha = roughness^2.
// The averages are exact integrals of the interpolated curve, so terms built
// from them (the multiple-scattering lobe) integrate to exactly 1 - total.
GgxAlbedo ggxAlbedo(float cosTheta, float roughness);

// The same for a perfect mirror (roughness 0): total 1, schlick (1 - mu)^5.
GgxAlbedo mirrorAlbedo(float cosTheta);

// Albedo of the Charlie sheen lobe with sheenColor 1 (KHR_materials_sheen).
// Can exceed 1 at grazing angles for sheenRoughness below ~0.25: the
// published Lambda fit is not energy conserving there.
float sheenAlbedo(float cosTheta, float sheenRoughness);

} // namespace prism
