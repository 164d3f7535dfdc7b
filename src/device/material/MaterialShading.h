// What a material gives an integrator at a hit, in one call
// (Material::shade): the BSDF's inputs and everything the BSDF does not
// cover. The integrator never asks which material it has.
#pragma once

#include "../math/Vec.h"
#include "../shading/Bsdf.h"

namespace prism {

struct MaterialShading
{
  BsdfInputs bsdf;
  // How much of the surface rays see (alphaMode applied).
  float opacity{1.f};
  float3 emissive{0.f, 0.f, 0.f}; // radiance, W/sr/m^2
  // What the albedo channel (and the denoiser's guide) shows: the BSDF's
  // base color, or the color an unlit surface shows (PRISM_MATERIAL_UNLIT).
  float3 albedo{1.f, 1.f, 1.f};
  float occlusion{1.f}; // of ambient light only
  // Tangent-space normal maps, when the material has them.
  bool hasNormalMap{false};
  float3 normalMap{0.f, 0.f, 1.f};
  // KHR_materials_anisotropy's direction in tangent space (x along the
  // tangent), when bsdf.anisotropy > 0: the integrator turns it into
  // bsdf.anisotropyDirection in its local frame.
  float2 anisotropyDirection{1.f, 0.f};
  bool hasCoatNormalMap{false};
  float3 coatNormalMap{0.f, 0.f, 1.f};
  // Absorption per unit length inside, behind a volume boundary.
  float3 attenuation{0.f, 0.f, 0.f};
};

} // namespace prism
