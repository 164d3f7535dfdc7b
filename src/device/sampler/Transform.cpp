#include "Transform.h"

namespace prism {

Transform::Transform(DeviceState &device) : Sampler(device, "transform") {}

void Transform::commitParameters()
{
  Sampler::commitParameters();
  m_inAttribute = readInAttribute();
}

float4 Transform::sample(const AttributeValues &attributes) const
{
  return applyOutTransform(attributes[m_inAttribute]);
}

} // namespace prism
