#include "Attributes.h"

namespace prism {
namespace {

const char *const kNames[kAttributeCount] = {"color",
    "attribute0",
    "attribute1",
    "attribute2",
    "attribute3",
    "worldPosition",
    "worldNormal",
    "objectPosition",
    "objectNormal",
    "primitiveId"};

} // namespace

Attribute attributeFromName(const std::string &name)
{
  for (int i = 0; i < kAttributeCount; i++) {
    if (name == kNames[i])
      return Attribute(i);
  }
  return Attribute::None;
}

const char *attributeName(Attribute attribute)
{
  return attribute == Attribute::None ? "none" : kNames[int(attribute)];
}

AttributeValues::AttributeValues()
{
  for (auto &v : values)
    v = float4{0, 0, 0, 1};
}

} // namespace prism
