#include "Matte.h"

namespace prism {

Matte::Matte(DeviceState &device) : Material(device, "matte") {}

void Matte::commitParameters()
{
  m_color = MaterialInput<float3>::read(*this, "color", kDefaultColor);
  m_opacity = MaterialInput<float>::read(*this, "opacity", 1.f);
  m_colorReadsAttributes = !m_color.isConstant() || !m_opacity.isConstant();
  m_readsAttributes = m_colorReadsAttributes;
  readAlphaMode();
}

float4 Matte::baseColorAndOpacity(const AttributeValues &attributes) const
{
  const float4 color = m_color.evaluateFloat4(attributes);
  // Spec 5.11.1: a sampled or attribute color's fourth component scales the
  // opacity (a constant color's is 1).
  return makeVec4(xyz(color), m_opacity.evaluate(attributes) * color.w);
}

MaterialShading Matte::shade(const AttributeValues &attributes) const
{
  const float4 base = baseColorAndOpacity(attributes);
  MaterialShading out;
  out.bsdf = matteBsdfInputs(xyz(base));
  out.opacity = coverage(base.w);
  return out;
}

void Matte::dropReferences()
{
  Material::dropReferences();
  m_color = MaterialInput<float3>(kDefaultColor);
  m_opacity = MaterialInput<float>(1.f);
}

} // namespace prism
