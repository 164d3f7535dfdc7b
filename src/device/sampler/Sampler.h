// ANARISampler: a function of a surface's attributes (spec 5.10). Each
// subtype reads its input attribute, transforms it and returns a float4.
#pragma once

#include "../geometry/Attributes.h"
#include "../math/Vec.h"
#include "../object/Object.h"
#include "../object/ObjectRef.h"

#include <vector>

namespace prism {

class Array;

// The element types of the spec's "ARRAY of Color" (the sampler JSON lists):
// UFIXED8/16/32 and FLOAT32 with 1-4 components and the UFIXED8 sRGB types.
bool isColorElementType(ANARIDataType type);

class Sampler : public Object
{
 public:
  Sampler(DeviceState &device, const std::string &subtype)
      : Object(device, ANARI_SAMPLER, subtype)
  {}

  // The sampled value at one hit (after outTransform/outOffset).
  virtual float4 sample(const AttributeValues &attributes) const = 0;

 protected:
  // Reads outTransform and outOffset, which spec Table 46 gives every
  // sampler; subtypes call it first from their own commitParameters().
  void commitParameters() override;

  // "inAttribute" (default attribute0); an unknown name warns and falls
  // back to attribute0.
  Attribute readInAttribute();
  // The array parameter `name` of `arrayType` whose element type passes
  // `accepts`, or an empty reference after reporting why it is unusable.
  ObjectRef<Array> readColorArray(const char *name,
      ANARIDataType arrayType,
      bool (*accepts)(ANARIDataType));
  // The elements in use of `array` decoded to linear float4 (sRGB and fixed
  // point included); false after reporting when memory runs out.
  bool convertColors(const Array &array, std::vector<float4> &out) const;

  float4 applyOutTransform(float4 value) const
  {
    return m_outTransform * value + m_outOffset;
  }

  mat4 m_outTransform{kIdentityMat4};
  float4 m_outOffset{0.f, 0.f, 0.f, 0.f};
};

// The sampler of `subtype`, or NULL if the device does not implement it.
Sampler *createSampler(DeviceState &device, const std::string &subtype);

} // namespace prism
