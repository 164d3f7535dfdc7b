// The transform sampler (spec 5.10.5): the input attribute itself through
// outTransform/outOffset, for swizzling or scaling attributes.
#pragma once

#include "Sampler.h"

namespace prism {

class Transform : public Sampler
{
 public:
  explicit Transform(DeviceState &device);

  float4 sample(const AttributeValues &attributes) const override;

 protected:
  void commitParameters() override;

 private:
  Attribute m_inAttribute{Attribute::Attribute0};
};

} // namespace prism
