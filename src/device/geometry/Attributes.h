// The surface attributes of spec 3.13 at one hit point, as renderers,
// samplers and materials read them.
#pragma once

#include "../math/Vec.h"

#include <cstdint>
#include <string>

namespace prism {

enum class Attribute : uint8_t {
  Color,
  Attribute0,
  Attribute1,
  Attribute2,
  Attribute3,
  WorldPosition,
  WorldNormal,
  ObjectPosition,
  ObjectNormal,
  PrimitiveId,
  None, // not an attribute name
};

constexpr int kAttributeCount = int(Attribute::None);

// "color", "attribute0", ..., "primitiveId" -> Attribute; None otherwise.
Attribute attributeFromName(const std::string &name);
const char *attributeName(Attribute attribute);

// Every attribute's value at one hit. Unset attributes are (0, 0, 0, 1)
// (spec 3.13: unspecified components are 0, the fourth 1), color included.
struct AttributeValues
{
  float4 values[kAttributeCount];
  uint32_t primitiveId{0};

  AttributeValues();
  const float4 &operator[](Attribute a) const
  {
    return values[int(a)];
  }
  float4 &operator[](Attribute a)
  {
    return values[int(a)];
  }
};

} // namespace prism
