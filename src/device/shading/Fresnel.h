// Fresnel reflectance: Schlick's approximation (what glTF's BRDF uses), the
// exact dielectric formula, and the thin-film interference Fresnel of
// KHR_materials_iridescence. Cosines are of the angle between the direction
// and the (micro)normal; RGB values are linear Rec.709.
#pragma once

#include "math/Vec.h"

#include <cmath>
#include <numbers>

namespace prism {

// (1 - cos)^5, the weight of f90 in Schlick's approximation.
inline float schlickWeight(float cosTheta)
{
  const float m = clamp(1.f - cosTheta, 0.f, 1.f);
  const float m2 = m * m;
  return m2 * m2 * m;
}

inline float fresnelSchlick(float f0, float f90, float cosTheta)
{
  return lerp(f0, f90, schlickWeight(cosTheta));
}
inline float3 fresnelSchlick(float3 f0, float3 f90, float cosTheta)
{
  return lerp(f0, f90, schlickWeight(cosTheta));
}

// Reflectance at normal incidence between indices `ior` and 1 (or any pair
// with ratio `ior`): ((1 - ior) / (1 + ior))^2.
inline float f0FromIor(float ior)
{
  const float r = (ior - 1.f) / (ior + 1.f);
  return r * r;
}

// Exact unpolarised reflectance of a smooth dielectric interface, light
// arriving at cosThetaI from the side of index n_i, eta = n_t / n_i.
// 1 under total internal reflection.
inline float fresnelDielectric(float cosThetaI, float eta)
{
  const float cosI = clamp(cosThetaI, 0.f, 1.f);
  const float sin2T = (1.f - cosI * cosI) / (eta * eta);
  if (sin2T >= 1.f)
    return 1.f;
  const float cosT = std::sqrt(1.f - sin2T);
  const float rs = (cosI - eta * cosT) / (cosI + eta * cosT);
  const float rp = (eta * cosI - cosT) / (eta * cosI + cosT);
  return 0.5f * (rs * rs + rp * rp);
}

namespace detail {

// Belcour & Barla's analytic spectral integration: the Fourier transform of
// the CIE XYZ matching functions fitted by Gaussians (their published
// coefficients), evaluated at optical path difference `opd` (nm) with
// per-channel phase `shift`, converted to linear Rec.709.
inline float3 thinFilmSensitivity(float opd, float3 shift)
{
  const float phase = 2.f * std::numbers::pi_v<float> * opd * 1e-9f;
  const float phase2 = phase * phase;
  constexpr float kTwoPi = 2.f * std::numbers::pi_v<float>;
  const float3 amplitude{5.4856e-13f, 4.4201e-13f, 5.2481e-13f};
  const float3 position{1.6810e+06f, 1.7953e+06f, 2.2084e+06f};
  const float3 variance{4.3278e+09f, 9.3046e+09f, 6.6121e+09f};
  float3 xyz;
  for (int c = 0; c < 3; c++) {
    xyz[c] = amplitude[c] * std::sqrt(kTwoPi * variance[c])
             * std::cos(position[c] * phase + shift[c])
             * std::exp(-phase2 * variance[c]);
  }
  // X has a second, short-wavelength lobe.
  xyz.x += 9.7470e-14f * std::sqrt(kTwoPi * 4.5282e+09f)
           * std::cos(2.2399e+06f * phase + shift.x)
           * std::exp(-4.5282e+09f * phase2);
  xyz = xyz * (1.f / 1.0685e-7f);
  return {3.2404542f * xyz.x - 1.5371385f * xyz.y - 0.4985314f * xyz.z,
      -0.9692660f * xyz.x + 1.8760108f * xyz.y + 0.0415560f * xyz.z,
      0.0556434f * xyz.x - 0.2040259f * xyz.y + 1.0572252f * xyz.z};
}

} // namespace detail

// KHR_materials_iridescence's Fresnel of a thin film (index `filmIor`,
// thickness in nanometres) in air over a base of reflectance `baseF0`,
// following Belcour & Barla 2017 with Schlick interfaces as the extension's
// implementation notes prescribe. A film much thinner than visible
// wavelengths has no optical effect, so below 30 nm the result fades to the
// base's own Schlick Fresnel (exactly that at thickness 0, the default).
inline float3 fresnelThinFilm(
    float cosTheta1, float filmIor, float filmThicknessNm, float3 baseF0)
{
  const float cos1 = clamp(cosTheta1, 0.f, 1.f);
  const float3 bare = fresnelSchlick(baseF0, float3{1.f, 1.f, 1.f}, cos1);
  const float t = clamp(filmThicknessNm / 30.f, 0.f, 1.f);
  const float fade = t * t * (3.f - 2.f * t);
  if (fade == 0.f)
    return bare;
  const float n2 = filmIor;
  // Air -> film.
  const float r12 = fresnelSchlick(f0FromIor(n2), 1.f, cos1);
  const float t121 = 1.f - r12;
  const float sin2Theta2 = (1.f - cos1 * cos1) / (n2 * n2);
  if (sin2Theta2 >= 1.f)
    return lerp(bare, float3{1.f, 1.f, 1.f}, fade);
  const float cos2 = std::sqrt(1.f - sin2Theta2);
  // Film -> base; the base index is inferred from F0 (exact for dielectrics,
  // an extinction-free approximation for metals).
  float3 r23{}, phi23{};
  for (int c = 0; c < 3; c++) {
    const float s = std::sqrt(clamp(baseF0[c], 0.f, 0.9999f));
    const float baseIor = (1.f + s) / (1.f - s);
    const float r = (baseIor - n2) / (baseIor + n2);
    r23[c] = fresnelSchlick(r * r, 1.f, cos2);
    // Reflection off a lower index shifts the phase by pi.
    phi23[c] = baseIor < n2 ? std::numbers::pi_v<float> : 0.f;
  }
  const float phi12 = n2 < 1.f ? std::numbers::pi_v<float> : 0.f;
  const float phi21 = std::numbers::pi_v<float> - phi12;
  const float3 phi = phi23 + phi21;
  const float opd = 2.f * n2 * max(filmThicknessNm, 0.f) * cos2;

  float3 result{};
  float3 r123{}, rs{}, cm{};
  for (int c = 0; c < 3; c++) {
    r123[c] = std::sqrt(clamp(r12 * r23[c], 1e-5f, 0.9999f));
    rs[c] = t121 * t121 * r23[c] / (1.f - r123[c] * r123[c]);
    result[c] = r12 + rs[c];
    cm[c] = rs[c] - t121;
  }
  // The first two interference orders carry nearly all of the energy.
  for (int m = 1; m <= 2; m++) {
    cm = cm * r123;
    const float3 sm =
        detail::thinFilmSensitivity(float(m) * opd, phi * float(m)) * 2.f;
    result = result + cm * sm;
  }
  return lerp(bare, clamp(result, 0.f, 1.f), fade);
}

} // namespace prism
