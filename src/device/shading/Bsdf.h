// The path tracer's BSDF: the physicallyBased material (spec 5.11.2, glTF 2.0
// appendix B with KHR_materials_specular, ior, clearcoat, sheen,
// transmission, volume and iridescence) and matte (Lambert), evaluated in the
// local shading frame. Conventions, also in shading/README.md:
//  - Directions are unit vectors in the local frame (z = shading normal),
//    both pointing away from the surface: wo towards the viewer (the path's
//    previous vertex), wi towards the light.
//  - eval() returns f alone (units 1/sr); the integrator multiplies by
//    |wi.z|. pdf() is per unit solid angle of wi.
//  - Opaque and thin-walled surfaces are two-sided: wo.z < 0 mirrors the
//    whole BSDF. With a volume (transmission > 0, thickness > 0), wo.z < 0
//    means the viewer is inside the medium.
//  - wi.z with the sign of wo.z is reflection, the opposite sign
//    transmission.
#pragma once

#include "GgxLobe.h"
#include "math/Vec.h"

#include <cmath>
#include <cstdint>
#include <limits>

namespace prism {

// The BSDF's inputs at one hit, spelled as the physicallyBased parameters.
// Defaults are that material's defaults; values outside their ranges are
// clamped by Bsdf.
struct BsdfInputs
{
  float3 baseColor{1.f, 1.f, 1.f};
  float metallic{1.f};
  float roughness{1.f};
  // KHR_materials_specular's weight of the dielectric specular lobe. ANARI's
  // default is 0 (glTF's is 1): a dielectric is then purely diffuse.
  float specular{0.f};
  float3 specularColor{1.f, 1.f, 1.f};
  float ior{1.5f};
  float clearcoat{0.f};
  float clearcoatRoughness{0.f};
  // The clearcoat layer's own normal in the local frame (z = the base's
  // shading normal), e.g. from clearcoatNormal; seen from the back of a
  // thin surface the coat lies flat.
  float3 clearcoatNormal{0.f, 0.f, 1.f};
  float transmission{0.f};
  // Only its sign matters here: 0 is thin-walled, > 0 a volume boundary (the
  // integrator applies the attenuation inside).
  float thickness{0.f};
  float3 sheenColor{0.f, 0.f, 0.f};
  float sheenRoughness{0.f};
  float iridescence{0.f};
  float iridescenceIor{1.3f};
  float iridescenceThickness{0.f}; // nanometres
  // KHR_materials_anisotropy: the base layer's GGX lobe is widest along
  // anisotropyDirection (local frame, the integrator turns the material's
  // tangent-space direction into it) by strength `anisotropy` in [0, 1].
  float anisotropy{0.f};
  float2 anisotropyDirection{1.f, 0.f};
};

// matte (spec 5.11.1): Lambertian reflection of `color`.
inline BsdfInputs matteBsdfInputs(float3 color)
{
  BsdfInputs inputs;
  inputs.baseColor = color;
  inputs.metallic = 0.f;
  inputs.specular = 0.f;
  return inputs;
}

// PhysicallyBased::Values (or anything with its member names) to inputs; a
// template so this module need not include the device core. Not BSDF
// inputs, left to the integrator: opacity (stochastic pass-through), normal
// (the shading frame), emissive, occlusion (ambient light only),
// attenuationColor/attenuationDistance (the medium behind a volume boundary:
// volumeAttenuationCoefficient), clearcoatNormal (tangent space: the
// integrator turns it into BsdfInputs::clearcoatNormal in the local frame),
// the anisotropy's direction (tangent space, likewise).
template <typename Values>
BsdfInputs physicallyBasedBsdfInputs(const Values &values)
{
  BsdfInputs inputs;
  inputs.baseColor = values.baseColor;
  inputs.metallic = values.metallic;
  inputs.roughness = values.roughness;
  inputs.specular = values.specular;
  inputs.specularColor = values.specularColor;
  inputs.ior = values.ior;
  inputs.clearcoat = values.clearcoat;
  inputs.clearcoatRoughness = values.clearcoatRoughness;
  inputs.transmission = values.transmission;
  inputs.thickness = values.thickness;
  inputs.sheenColor = values.sheenColor;
  inputs.sheenRoughness = values.sheenRoughness;
  inputs.iridescence = values.iridescence;
  inputs.iridescenceIor = values.iridescenceIor;
  inputs.iridescenceThickness = values.iridescenceThickness;
  inputs.anisotropy = values.anisotropyStrength;
  return inputs;
}

// KHR_materials_volume's Beer-Lambert extinction per unit world length:
// white light turns `attenuationColor` after `attenuationDistance`, so the
// transmittance over distance d is exp(-coefficient * d).
inline float3 volumeAttenuationCoefficient(
    float3 attenuationColor, float attenuationDistance)
{
  float3 coefficient{0.f, 0.f, 0.f};
  if (!(attenuationDistance > 0.f)
      || attenuationDistance == std::numeric_limits<float>::infinity())
    return coefficient;
  for (int c = 0; c < 3; c++) {
    const float color = clamp(attenuationColor[c], 1e-6f, 1.f);
    coefficient[c] = -std::log(color) / attenuationDistance;
  }
  return coefficient;
}

enum BsdfFlags : uint32_t {
  kBsdfReflection = 1u << 0,
  kBsdfTransmission = 1u << 1,
  // wi is the only direction of its lobe: pdf is a probability, not a
  // density, eval() and pdf() return 0 for it, and no MIS applies.
  kBsdfDelta = 1u << 2,
};

// One sampled direction; flags == 0 means none (the path ends).
struct BsdfSample
{
  float3 wi{0.f, 0.f, 0.f}; // local frame
  // eval(wo, wi); for a delta sample, the lobe's reflectance / |wi.z|.
  float3 f{0.f, 0.f, 0.f};
  // pdf(wo, wi) per steradian; for a delta sample, the probability of its
  // lobe.
  float pdf{0.f};
  float3 weight{0.f, 0.f, 0.f}; // f |wi.z| / pdf, the throughput factor
  // Index on wi's side over index on wo's side (1 unless refracted): radiance
  // scales by 1 / relativeIor^2 across the boundary, already in `weight`.
  float relativeIor{1.f};
  uint32_t flags{0};

  bool valid() const
  {
    return flags != 0;
  }
  bool isDelta() const
  {
    return (flags & kBsdfDelta) != 0;
  }
  bool isTransmission() const
  {
    return (flags & kBsdfTransmission) != 0;
  }
};

// Built per hit (cheap: no allocation, no virtual calls); const methods are
// safe to call from any thread.
class Bsdf
{
 public:
  explicit Bsdf(const BsdfInputs &inputs);

  // f(wo, wi) summed over the non-delta lobes, in 1/sr, no cosine.
  float3 eval(float3 wo, float3 wi) const;
  // The density with which sample() returns wi from its non-delta lobes.
  float pdf(float3 wo, float3 wi) const;
  // Both at once (the work they share done once).
  void evalAndPdf(float3 wo, float3 wi, float3 &f, float &pdf) const;
  // A direction from one lobe chosen by uLobe; uDirection places it in the
  // lobe. Both in [0, 1).
  BsdfSample sample(float3 wo, float2 uDirection, float uLobe) const;

  // Whether sample() reads its lobe decision (false for Lambert alone).
  bool choosesLobes() const
  {
    return !m_lambertOnly;
  }
  // False when every lobe is delta: light sampling cannot contribute.
  bool hasNonDeltaLobes() const
  {
    return m_hasNonDeltaLobes;
  }
  bool hasTransmission() const
  {
    return m_transmissionWeight > 0.f;
  }
  // Transmission enters a medium (thickness > 0) rather than a thin sheet.
  bool isVolumeBoundary() const
  {
    return m_volume;
  }

 private:
  enum Lobe : int {
    kCoat,
    kSheen,
    kSpecular,
    kSpecularMulti,
    kDiffuse,
    kTransmission,
    kTransmissionMulti,
    kLobeCount
  };
  struct Context;

  Context prepare(float3 wo) const;
  void evaluate(const Context &c, float3 wi, float3 &f, float &pdf) const;
  void evaluateLambert(float3 wo, float3 wi, float3 &f, float &pdf) const;
  void evaluateInterior(
      const Context &c, float3 wi, float3 &f, float &pdf) const;
  BsdfSample sampleInterior(const Context &c, float2 u, float uLobe) const;
  BsdfSample sampleLambert(float3 wo, float2 u) const;
  int chooseLobe(const Context &c, float uLobe) const;
  bool sampleDirection(const Context &c,
      int lobe,
      float2 u,
      float3 &wi,
      BsdfSample &whole) const;
  bool sampleTransmission(
      const Context &c, float2 u, float3 &wi, BsdfSample &whole) const;
  BsdfSample sampleFromDirection(const Context &c, int lobe, float3 wi) const;

  struct Albedo
  {
    float total, schlick, meanCos;
  };
  Albedo specularAlbedo(float cosTheta) const;
  float dielectricAlbedo(const Albedo &albedo) const;
  float iridescentAlbedo(const Albedo &albedo) const;
  float coatAlbedo(float cosTheta) const;
  // A direction of our frame in the coat's frame, and back; the identity
  // unless the coat is tilted and seen from the front.
  float3 toCoat(const Context &c, float3 w) const;
  float3 fromCoat(const Context &c, float3 w) const;
  float sheenLayerAlbedo(float cosTheta) const;
  float3 specularFresnel(float cosTheta) const;
  float3 dielectricFresnel(float cosTheta) const;
  float3 interfaceFresnel(float cosTheta, float eta) const;

  // Base layer.
  float3 m_baseColor{0.f, 0.f, 0.f};
  float m_metallic{0.f};
  float m_roughness{1.f}, m_alpha{1.f};
  GgxLobe m_lobe; // the specular and transmission lobes' microfacets
  bool m_specularDelta{false};
  float3 m_dielectricF0{
      0.f, 0.f, 0.f}; // KHR_materials_specular's dielectric_f0
  float m_dielectricF90{0.f};
  float m_dielectricF0Max{0.f};
  float m_ior{1.5f};
  float m_transmissionWeight{0.f}; // (1 - metallic) * transmission
  bool m_volume{false};
  // Energy compensation (Kulla & Conty) and layering, per roughness.
  float m_ggxAverage{1.f};
  float3 m_multiFresnel{0.f, 0.f, 0.f};
  float m_dielectricMultiFresnel{0.f};
  float m_dielectricAlbedoAverage{0.f};
  // Iridescence.
  float m_iridescence{0.f};
  float m_filmIor{1.3f};
  float m_filmThickness{0.f};
  float m_filmNormalF0Max{0.f}; // thin-film reflectance at normal incidence
  // Sheen.
  float3 m_sheenColor{0.f, 0.f, 0.f};
  float m_sheenMax{0.f};
  float m_sheenRoughness{0.f}, m_sheenAlpha{1.f};
  // Clearcoat.
  float m_clearcoat{0.f};
  float m_coatRoughness{0.f}, m_coatAlpha{0.f};
  bool m_coatDelta{false};
  // The coat's frame when its normal differs from the base's.
  bool m_coatTilted{false};
  float3 m_coatX{1.f, 0.f, 0.f}, m_coatY{0.f, 1.f, 0.f}, m_coatZ{0.f, 0.f, 1.f};

  bool m_lambertOnly{true};
  bool m_hasNonDeltaLobes{true};
};

} // namespace prism
