// ANARIMaterial: the appearance of a surface (spec 5.11). Every renderer
// asks a material for its base color and opacity at a hit; physically based
// shading (path tracer) adds its own queries in the subtypes.
#pragma once

#include "../geometry/Attributes.h"
#include "../object/Object.h"
#include "MaterialShading.h"

#include <optional>

namespace prism {

template <typename T>
class MaterialInput;

// What a material whose inputs read no surface attributes looks like at
// every hit, and the BSDF that makes of it.
struct ConstantShading
{
  MaterialShading shading;
  Bsdf bsdf;
};

enum class AlphaMode : uint8_t {
  Opaque,
  Blend,
  Mask,
};

class Material : public Object
{
 public:
  Material(DeviceState &device, const std::string &subtype)
      : Object(device, ANARI_MATERIAL, subtype)
  {}

  // Linear base color (rgb) and opacity (a) at a hit, before alphaMode
  // (what the preview renderers need).
  virtual float4 baseColorAndOpacity(
      const AttributeValues &attributes) const = 0;
  // Everything physically based shading needs at a hit.
  virtual MaterialShading shade(const AttributeValues &attributes) const = 0;
  // The radiance the material emits everywhere, when it is constant and
  // positive (such surfaces are sampled as lights); false otherwise.
  virtual bool constantEmission(float3 &radiance) const
  {
    (void)radiance;
    return false;
  }

  // How much of the surface a ray sees: 1 for opaque, 0 or 1 for mask
  // (opacity >= alphaCutoff), the opacity for blend.
  float coverage(float opacity) const
  {
    switch (m_alphaMode) {
    case AlphaMode::Opaque:
      return 1.f;
    case AlphaMode::Mask:
      return opacity >= m_alphaCutoff ? 1.f : 0.f;
    default:
      return opacity;
    }
  }
  AlphaMode alphaMode() const
  {
    return m_alphaMode;
  }
  // Whether baseColorAndOpacity() reads surface attributes (a sampler or an
  // attribute input); when not, renderers skip interpolating them.
  bool colorReadsAttributes() const
  {
    return m_colorReadsAttributes;
  }
  // Whether any of the material's inputs reads surface attributes.
  bool readsAttributes() const
  {
    return m_readsAttributes;
  }
  // shade() and its BSDF, built once per commit, when they are the same at
  // every hit (no input reads attributes, no normal map bends the frame);
  // NULL otherwise. Spares the path tracer shading such hits one by one.
  const ConstantShading *constantShading() const
  {
    return m_constantShading ? &*m_constantShading : nullptr;
  }
  // Builds constantShading(); final, so no subtype can leave it stale.
  void finalize() final
  {
    m_constantShading.reset();
    if (m_readsAttributes)
      return;
    const MaterialShading shading = shade(AttributeValues{});
    // The maps and the anisotropy's direction need the hit's tangents.
    if (!shading.hasNormalMap && !shading.hasCoatNormalMap
        && !(shading.bsdf.anisotropy > 0.f))
      m_constantShading.emplace(ConstantShading{shading, Bsdf(shading.bsdf)});
  }
  float alphaCutoff() const
  {
    return m_alphaCutoff;
  }
  // PRISM_MATERIAL_DOUBLE_SIDED: false when back faces must be invisible to
  // every ray (glTF's doubleSided: false).
  bool doubleSided() const
  {
    return m_doubleSided;
  }

 protected:
  // Reads alphaMode and alphaCutoff, which every subtype understands; an
  // unknown mode warns and falls back to opaque (its definition's default).
  void readAlphaMode()
  {
    const std::string mode = param<std::string>("alphaMode");
    m_alphaMode = mode == "blend"  ? AlphaMode::Blend
                  : mode == "mask" ? AlphaMode::Mask
                                   : AlphaMode::Opaque;
    m_alphaCutoff = param<float>("alphaCutoff");
  }
  // Reads doubleSided (PRISM_MATERIAL_DOUBLE_SIDED), which every subtype
  // understands.
  void readDoubleSided()
  {
    m_doubleSided = param<bool>("doubleSided");
  }
  // Keeps back faces whatever doubleSided says: a volume's back faces are
  // where rays inside it leave, and culling them would trap those rays.
  void keepBackFaces()
  {
    m_doubleSided = true;
  }

  // MaterialInput::read() uses the protected parameter readers.
  template <typename T>
  friend class MaterialInput;

  bool m_colorReadsAttributes{false};
  bool m_readsAttributes{false};
  AlphaMode m_alphaMode{AlphaMode::Opaque};
  float m_alphaCutoff{0.5f};
  bool m_doubleSided{true};
  std::optional<ConstantShading> m_constantShading;
};

// The material of `subtype`, or NULL if the device does not implement it.
Material *createMaterial(DeviceState &device, const std::string &subtype);

} // namespace prism
