// The matte material (spec 5.11.1): Lambertian reflection of `color` with
// optional cut-out transparency.
#pragma once

#include "MaterialInput.h"

namespace prism {

class Matte : public Material
{
 public:
  explicit Matte(DeviceState &device);

  float4 baseColorAndOpacity(const AttributeValues &attributes) const override;
  MaterialShading shade(const AttributeValues &attributes) const override;

  const MaterialInput<float3> &color() const
  {
    return m_color;
  }
  const MaterialInput<float> &opacity() const
  {
    return m_opacity;
  }

  void dropReferences() override;

 protected:
  void commitParameters() override;

 private:
  MaterialInput<float3> m_color{kDefaultColor};
  MaterialInput<float> m_opacity{1.f};

  static constexpr float3 kDefaultColor{0.8f, 0.8f, 0.8f};
};

} // namespace prism
