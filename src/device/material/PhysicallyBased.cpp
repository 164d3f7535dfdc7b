#include "PhysicallyBased.h"

#include <cmath>
#include <type_traits>

namespace prism {

PhysicallyBased::PhysicallyBased(DeviceState &device)
    : Material(device, "physicallyBased")
{}

void PhysicallyBased::commitParameters()
{
  Inputs in; // every field at its default
  auto input = [this](auto &field,
                   const char *name,
                   InputAccepts accepts = InputAccepts::Any) {
    using Input = std::decay_t<decltype(field)>;
    field = Input::read(*this, name, field.constant(), accepts);
  };
  input(in.baseColor, "baseColor");
  input(in.baseColorFactor, "baseColorFactor");
  input(in.opacity, "opacity");
  m_colorReadsAttributes = !in.baseColor.isConstant()
                           || !in.baseColorFactor.isConstant()
                           || !in.opacity.isConstant();
  input(in.metallic, "metallic");
  input(in.roughness, "roughness");
  input(in.normal, "normal", InputAccepts::SamplerOnly);
  input(in.emissive, "emissive");
  const float3 emission = in.emissive.constant();
  const float3 usable = usableEmission(emission);
  if (in.emissive.isConstant() && !(usable == emission))
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'emissive' has negative or non-finite components; they emit "
        "nothing");
  input(in.occlusion, "occlusion", InputAccepts::SamplerOnly);
  readAlphaMode();
  readDoubleSided();
  in.unlit = param<bool>("unlit");
  input(in.specular, "specular");
  input(in.specularColor, "specularColor");
  input(in.clearcoat, "clearcoat");
  input(in.clearcoatRoughness, "clearcoatRoughness");
  input(in.clearcoatNormal, "clearcoatNormal", InputAccepts::SamplerOnly);
  input(in.transmission, "transmission");
  // The JSON (unlike the spec's table) also lets ior vary over the surface.
  input(in.ior, "ior");
  input(in.thickness, "thickness");
  auto mayExceedZero = [](const MaterialInput<float> &input) {
    return !input.isConstant() || input.constant() > 0.f;
  };
  // Transmission with a thickness bounds a medium (KHR_materials_volume):
  // rays inside it must meet its back faces to get out.
  if (mayExceedZero(in.transmission) && mayExceedZero(in.thickness))
    keepBackFaces();
  in.attenuationDistance = param<float>("attenuationDistance");
  in.attenuationColor = param<float3>("attenuationColor");
  input(in.sheenColor, "sheenColor");
  input(in.sheenRoughness, "sheenRoughness");
  input(in.iridescence, "iridescence");
  in.iridescenceIor = param<float>("iridescenceIor");
  input(in.iridescenceThickness, "iridescenceThickness");
  input(in.anisotropyStrength, "anisotropyStrength");
  input(in.anisotropyRotation, "anisotropyRotation");
  input(in.anisotropyDirection, "anisotropyDirection");
  m_readsAttributes =
      m_colorReadsAttributes || !in.metallic.isConstant()
      || !in.roughness.isConstant() || !in.normal.isConstant()
      || !in.emissive.isConstant() || !in.occlusion.isConstant()
      || !in.specular.isConstant() || !in.specularColor.isConstant()
      || !in.clearcoat.isConstant() || !in.clearcoatRoughness.isConstant()
      || !in.clearcoatNormal.isConstant() || !in.transmission.isConstant()
      || !in.ior.isConstant() || !in.thickness.isConstant()
      || !in.sheenColor.isConstant() || !in.sheenRoughness.isConstant()
      || !in.iridescence.isConstant() || !in.iridescenceThickness.isConstant()
      || !in.anisotropyStrength.isConstant()
      || !in.anisotropyRotation.isConstant()
      || !in.anisotropyDirection.isConstant();
  m_inputs = std::move(in);
}

float4 PhysicallyBased::baseColorAndOpacity(
    const AttributeValues &attributes) const
{
  const float4 color = m_inputs.baseColor.evaluateFloat4(attributes)
                       * m_inputs.baseColorFactor.evaluateFloat4(attributes);
  float opacity = m_inputs.opacity.evaluate(attributes);
  // Spec 5.11.2: a sampled or attribute baseColor's fourth component scales
  // the opacity only when alphaMode is not opaque.
  if (m_alphaMode != AlphaMode::Opaque)
    opacity *= color.w;
  return makeVec4(xyz(color), opacity);
}

MaterialShading PhysicallyBased::shade(const AttributeValues &attributes) const
{
  if (m_inputs.unlit)
    return shadeUnlit(attributes);
  const Values values = evaluate(attributes);
  MaterialShading out;
  out.bsdf = physicallyBasedBsdfInputs(values);
  out.albedo = values.baseColor;
  out.emissive = values.emissive;
  out.occlusion = clamp(values.occlusion, 0.f, 1.f);
  out.hasCoatNormalMap = values.clearcoat > 0.f
                         && m_inputs.clearcoatNormal.source()
                                != MaterialInput<float3>::Source::Constant;
  out.coatNormalMap = values.clearcoatNormal;
  out.hasNormalMap =
      m_inputs.normal.source() != MaterialInput<float3>::Source::Constant;
  out.normalMap = values.normal;
  out.anisotropyDirection = values.anisotropyDirection;
  if (values.transmission > 0.f && values.thickness > 0.f)
    out.attenuation = volumeAttenuationCoefficient(
        values.attenuationColor, values.attenuationDistance);
  out.opacity = coverage(values.opacity);
  return out;
}

MaterialShading PhysicallyBased::shadeUnlit(
    const AttributeValues &attributes) const
{
  // The base color seen as is: emitted over a BSDF that reflects nothing,
  // so lights change nothing on it; it is also what the albedo shows, so
  // the denoiser keeps its texture.
  const float4 base = baseColorAndOpacity(attributes);
  MaterialShading out;
  out.bsdf.baseColor = {0.f, 0.f, 0.f};
  out.bsdf.metallic = 0.f;
  out.bsdf.specular = 0.f;
  out.emissive = usableEmission(xyz(base));
  out.albedo = xyz(base);
  out.opacity = coverage(base.w);
  return out;
}

bool PhysicallyBased::constantEmission(float3 &radiance) const
{
  // Unlit surfaces are seen, not sampled as lights: they would take light
  // samples from the scene's real lights.
  if (m_inputs.unlit)
    return false;
  // Textured emission varies over the surface: rays find it alone.
  if (m_inputs.emissive.source() != MaterialInput<float3>::Source::Constant)
    return false;
  radiance = usableEmission(m_inputs.emissive.constant());
  return std::max(radiance.x, std::max(radiance.y, radiance.z)) > 0.f;
}

float3 PhysicallyBased::usableEmission(const float3 &emissive)
{
  auto usable = [](float v) {
    return std::isfinite(v) && v > 0.f ? v : 0.f;
  };
  return {usable(emissive.x), usable(emissive.y), usable(emissive.z)};
}

void PhysicallyBased::resolveAnisotropy(
    const AttributeValues &attributes, float &strength, float2 &direction) const
{
  const Inputs &in = m_inputs;
  const float3 texel = in.anisotropyDirection.evaluate(attributes);
  strength = in.anisotropyStrength.evaluate(attributes) * texel.z;
  const float rotation = in.anisotropyRotation.evaluate(attributes);
  const float c = std::cos(rotation), s = std::sin(rotation);
  direction = {c * texel.x - s * texel.y, s * texel.x + c * texel.y};
}

PhysicallyBased::Values PhysicallyBased::evaluate(
    const AttributeValues &attributes) const
{
  const Inputs &in = m_inputs;
  const float4 base = baseColorAndOpacity(attributes);
  float anisotropy = 0.f;
  float2 anisotropyDirection{1.f, 0.f};
  resolveAnisotropy(attributes, anisotropy, anisotropyDirection);
  return {xyz(base),
      base.w,
      in.metallic.evaluate(attributes),
      in.roughness.evaluate(attributes),
      in.normal.evaluate(attributes),
      usableEmission(in.emissive.evaluate(attributes)),
      in.occlusion.evaluate(attributes),
      in.specular.evaluate(attributes),
      in.specularColor.evaluate(attributes),
      in.clearcoat.evaluate(attributes),
      in.clearcoatRoughness.evaluate(attributes),
      in.clearcoatNormal.evaluate(attributes),
      in.transmission.evaluate(attributes),
      in.ior.evaluate(attributes),
      in.thickness.evaluate(attributes),
      in.attenuationDistance,
      in.attenuationColor,
      in.sheenColor.evaluate(attributes),
      in.sheenRoughness.evaluate(attributes),
      in.iridescence.evaluate(attributes),
      in.iridescenceIor,
      in.iridescenceThickness.evaluate(attributes),
      anisotropy,
      anisotropyDirection};
}

void PhysicallyBased::dropReferences()
{
  Material::dropReferences();
  m_inputs = Inputs{};
}

} // namespace prism
