#include "Primitive.h"

#include "../array/Array.h"

namespace prism {

Primitive::Primitive(DeviceState &device) : Sampler(device, "primitive") {}

void Primitive::commitParameters()
{
  Sampler::commitParameters();
  m_array = readColorArray("array", ANARI_ARRAY1D, isColorElementType);
  m_inOffset = param<uint64_t>("inOffset");
}

void Primitive::finalize()
{
  std::vector<float4>().swap(m_values);
  if (m_array)
    convertColors(*m_array.get(), m_values);
}

void Primitive::dropReferences()
{
  Sampler::dropReferences();
  m_array.reset();
}

float4 Primitive::sample(const AttributeValues &attributes) const
{
  const uint64_t size = m_values.size();
  const uint64_t id = attributes.primitiveId;
  // Compared without the sum, which could wrap for huge offsets.
  const bool inside = m_inOffset < size && id < size - m_inOffset;
  return applyOutTransform(
      inside ? m_values[id + m_inOffset] : float4{0.f, 0.f, 0.f, 1.f});
}

} // namespace prism
