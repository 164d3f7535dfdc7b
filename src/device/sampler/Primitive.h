// The primitive sampler (spec 5.10.4): element primitiveId + inOffset of an
// ARRAY1D of colors, like a per-primitive attribute owned by the material.
#pragma once

#include "Sampler.h"

#include <vector>

namespace prism {

class Primitive : public Sampler
{
 public:
  explicit Primitive(DeviceState &device);

  // Past the end of the array the value is an unset attribute, (0, 0, 0, 1).
  float4 sample(const AttributeValues &attributes) const override;

  void finalize() override;
  bool isValid() const override
  {
    return !m_values.empty();
  }
  void dropReferences() override;

 protected:
  void commitParameters() override;

 private:
  ObjectRef<Array> m_array;
  uint64_t m_inOffset{0};
  std::vector<float4> m_values; // built by finalize()
};

} // namespace prism
