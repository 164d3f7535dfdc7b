// A material parameter that is a constant, a sampler or the name of a
// surface attribute (spec 5.11: "most material parameters can be set to a
// constant, ANARISampler or string value").
#pragma once

#include "Material.h"

#include "../sampler/Sampler.h"

#include <type_traits>
#include <vector>

namespace prism {

// Whether a material parameter takes every form or only a sampler (the
// normal and occlusion maps).
enum class InputAccepts : uint8_t {
  Any,
  SamplerOnly,
};

// T is float (FLOAT32 parameters) or float3 (FLOAT32_VEC3 parameters).
template <typename T>
class MaterialInput
{
  static_assert(std::is_same_v<T, float> || std::is_same_v<T, float3>);

 public:
  enum class Source : uint8_t {
    Constant,
    Sampler,
    Attribute,
  };

  static constexpr ANARIDataType kConstantType =
      std::is_same_v<T, float> ? ANARI_FLOAT32 : ANARI_FLOAT32_VEC3;

  MaterialInput() = default;
  explicit MaterialInput(T constant) : m_constant(constant) {}

  // Reads parameter `name` from `material`'s commitParameters(); anything
  // unusable is reported and gives `fallback`.
  static MaterialInput read(Material &material,
      const char *name,
      T fallback,
      InputAccepts accepts = InputAccepts::Any)
  {
    MaterialInput input(fallback);
    const Parameter *p = material.readAny(name);
    if (!p)
      return input;
    const bool any = accepts == InputAccepts::Any;
    if (any && p->type() == kConstantType) {
      // Declared bounds clamp the constant, with a warning; what is not a
      // number stays for the material, which treats it component-wise.
      T bounded;
      const ParamCheck check = material.checkedParam(name, bounded);
      const bool clamped = check.verdict == ParamVerdict::kBelowMinimum
                           || check.verdict == ParamVerdict::kAboveMaximum;
      input.m_constant = clamped ? bounded : p->template as<T>();
      if (clamped)
        material.reportRejected(check);
    } else if (p->type() == ANARI_SAMPLER) {
      // Samplers of an unknown subtype are inert objects, not Samplers.
      auto *sampler = dynamic_cast<prism::Sampler *>(p->object());
      if (sampler) {
        input.m_source = Source::Sampler;
        input.m_sampler = ObjectRef<prism::Sampler>(sampler);
        // Lets refresh() reach the sampler (and its image) at frame start.
        material.dependOn(sampler);
      } else {
        material.report(ANARI_SEVERITY_WARNING,
            ANARI_STATUS_INVALID_ARGUMENT,
            "'%s' is a sampler of an unknown subtype; using the default",
            name);
      }
    } else if (any && p->type() == ANARI_STRING) {
      const prism::Attribute attribute = attributeFromName(p->string());
      if (attribute != prism::Attribute::None) {
        input.m_source = Source::Attribute;
        input.m_attribute = attribute;
      } else {
        material.report(ANARI_SEVERITY_WARNING,
            ANARI_STATUS_INVALID_ARGUMENT,
            "'%s' names \"%s\", which is not a surface attribute; using the "
            "default",
            name,
            p->string().c_str());
      }
    } else if (any) {
      material.wrongType(
          name, p->type(), {kConstantType, ANARI_SAMPLER, ANARI_STRING});
    } else {
      material.wrongType(name, p->type(), {ANARI_SAMPLER});
    }
    return input;
  }

  Source source() const
  {
    return m_source;
  }
  // The constant (for samplers and attributes: the parameter's default).
  T constant() const
  {
    return m_constant;
  }
  const prism::Sampler *sampler() const
  {
    return m_sampler.get();
  }
  prism::Attribute attribute() const
  {
    return m_attribute;
  }
  // Whether the value varies over a surface.
  bool isConstant() const
  {
    return m_source == Source::Constant;
  }

  // All four components at a hit; a constant (or an invalid sampler's
  // default) is completed like an attribute: (c, 1) or (c, 0, 0, 1).
  float4 evaluateFloat4(const AttributeValues &attributes) const
  {
    switch (m_source) {
    case Source::Sampler:
      if (m_sampler->isValid())
        return m_sampler->sample(attributes);
      break;
    case Source::Attribute:
      return attributes[m_attribute];
    default:
      break;
    }
    return complete(m_constant);
  }
  T evaluate(const AttributeValues &attributes) const
  {
    const float4 value = evaluateFloat4(attributes);
    if constexpr (std::is_same_v<T, float>)
      return value.x;
    else
      return xyz(value);
  }

 private:
  static float4 complete(T value)
  {
    if constexpr (std::is_same_v<T, float>)
      return {value, 0.f, 0.f, 1.f};
    else
      return makeVec4(value, 1.f);
  }

  Source m_source{Source::Constant};
  T m_constant{};
  ObjectRef<prism::Sampler> m_sampler;
  prism::Attribute m_attribute{prism::Attribute::None};
};

} // namespace prism
