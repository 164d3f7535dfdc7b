// The physicallyBased material (spec 5.11.2): glTF's metallic-roughness BRDF
// with the specular, clearcoat, transmission, volume, sheen and iridescence
// extensions, and prism's glTF extras: baseColorFactor
// (PRISM_MATERIAL_BASE_COLOR_FACTOR), unlit (PRISM_MATERIAL_UNLIT) and
// doubleSided (PRISM_MATERIAL_DOUBLE_SIDED, in Material). This object only
// resolves its parameters; a path tracer evaluates the lobes from inputs() or
// evaluate().
#pragma once

#include "MaterialInput.h"

#include <limits>

namespace prism {

class PhysicallyBased : public Material
{
 public:
  // Every parameter of khr_material_physically_based.json, at its default
  // until set. normal, clearcoatNormal and occlusion accept only samplers.
  struct Inputs
  {
    MaterialInput<float3> baseColor{float3{1.f, 1.f, 1.f}};
    // PRISM_MATERIAL_BASE_COLOR_FACTOR: multiplies baseColor (all four
    // components).
    MaterialInput<float3> baseColorFactor{float3{1.f, 1.f, 1.f}};
    MaterialInput<float> opacity{1.f};
    MaterialInput<float> metallic{1.f};
    MaterialInput<float> roughness{1.f};
    // Tangent space; (0, 0, 1) leaves the shading normal unchanged.
    MaterialInput<float3> normal{float3{0.f, 0.f, 1.f}};
    MaterialInput<float3> emissive{float3{0.f, 0.f, 0.f}};
    // 1 is unoccluded; applies to otherwise unoccluded ambient light only.
    MaterialInput<float> occlusion{1.f};
    MaterialInput<float> specular{0.f};
    MaterialInput<float3> specularColor{float3{1.f, 1.f, 1.f}};
    MaterialInput<float> clearcoat{0.f};
    MaterialInput<float> clearcoatRoughness{0.f};
    MaterialInput<float3> clearcoatNormal{float3{0.f, 0.f, 1.f}};
    MaterialInput<float> transmission{0.f};
    MaterialInput<float> ior{1.5f};
    MaterialInput<float> thickness{0.f}; // 0: thin-walled
    float attenuationDistance{std::numeric_limits<float>::infinity()};
    float3 attenuationColor{1.f, 1.f, 1.f};
    MaterialInput<float3> sheenColor{float3{0.f, 0.f, 0.f}};
    MaterialInput<float> sheenRoughness{0.f};
    MaterialInput<float> iridescence{0.f};
    float iridescenceIor{1.3f};
    MaterialInput<float> iridescenceThickness{0.f};
    // PRISM_MATERIAL_ANISOTROPY (KHR_materials_anisotropy): the specular
    // lobe is widest along anisotropyDirection.xy (tangent space) turned
    // by anisotropyRotation (radians, from the tangent towards the
    // bitangent), by anisotropyStrength times anisotropyDirection.z.
    MaterialInput<float> anisotropyStrength{0.f};
    MaterialInput<float> anisotropyRotation{0.f};
    MaterialInput<float3> anisotropyDirection{float3{1.f, 0.f, 1.f}};
    // PRISM_MATERIAL_UNLIT: the base color emitted over a black BSDF.
    bool unlit{false};
  };

  // The inputs resolved at one hit; opacity already includes baseColor's
  // fourth component where the spec asks for it (as baseColorAndOpacity).
  struct Values
  {
    float3 baseColor;
    float opacity;
    float metallic;
    float roughness;
    float3 normal;
    float3 emissive;
    float occlusion;
    float specular;
    float3 specularColor;
    float clearcoat;
    float clearcoatRoughness;
    float3 clearcoatNormal;
    float transmission;
    float ior;
    float thickness;
    float attenuationDistance;
    float3 attenuationColor;
    float3 sheenColor;
    float sheenRoughness;
    float iridescence;
    float iridescenceIor;
    float iridescenceThickness;
    // Strength (times the direction's z) and the turned direction.
    float anisotropyStrength;
    float2 anisotropyDirection;
  };

  explicit PhysicallyBased(DeviceState &device);

  // `emissive` as radiance: negative or non-finite components are 0.
  static float3 usableEmission(const float3 &emissive);

  float4 baseColorAndOpacity(const AttributeValues &attributes) const override;
  MaterialShading shade(const AttributeValues &attributes) const override;
  bool constantEmission(float3 &radiance) const override;
  Values evaluate(const AttributeValues &attributes) const;
  const Inputs &inputs() const
  {
    return m_inputs;
  }

  void dropReferences() override;

 protected:
  void commitParameters() override;

 private:
  MaterialShading shadeUnlit(const AttributeValues &attributes) const;
  // anisotropyStrength, Rotation and Direction resolved into the strength
  // and the tangent-space direction.
  void resolveAnisotropy(const AttributeValues &attributes,
      float &strength,
      float2 &direction) const;

  Inputs m_inputs;
};

} // namespace prism
