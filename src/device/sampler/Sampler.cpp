#include "Sampler.h"

#include "../array/Array.h"
#include "../array/ElementConversion.h"

#include "anari/frontend/type_utility.h"

#include <exception>

namespace prism {

bool isColorElementType(ANARIDataType type)
{
  switch (int(type)) {
  case ANARI_UFIXED8:
  case ANARI_UFIXED8_VEC2:
  case ANARI_UFIXED8_VEC3:
  case ANARI_UFIXED8_VEC4:
  case ANARI_UFIXED8_R_SRGB:
  case ANARI_UFIXED8_RA_SRGB:
  case ANARI_UFIXED8_RGB_SRGB:
  case ANARI_UFIXED8_RGBA_SRGB:
  case ANARI_UFIXED16:
  case ANARI_UFIXED16_VEC2:
  case ANARI_UFIXED16_VEC3:
  case ANARI_UFIXED16_VEC4:
  case ANARI_UFIXED32:
  case ANARI_UFIXED32_VEC2:
  case ANARI_UFIXED32_VEC3:
  case ANARI_UFIXED32_VEC4:
  case ANARI_FLOAT32:
  case ANARI_FLOAT32_VEC2:
  case ANARI_FLOAT32_VEC3:
  case ANARI_FLOAT32_VEC4:
    return true;
  default:
    return false;
  }
}

void Sampler::commitParameters()
{
  if (declares("outTransform")) {
    m_outTransform = param<mat4>("outTransform");
    m_outOffset = param<float4>("outOffset");
    return;
  }
  // KHR_SAMPLER_PRIMITIVE declares no output transform; one set is applied.
  m_outTransform =
      read<mat4>("outTransform", ANARI_FLOAT32_MAT4, kIdentityMat4);
  m_outOffset =
      read<float4>("outOffset", ANARI_FLOAT32_VEC4, {0.f, 0.f, 0.f, 0.f});
}

Attribute Sampler::readInAttribute()
{
  const std::string name = param<std::string>("inAttribute");
  const Attribute attribute = attributeFromName(name);
  if (attribute != Attribute::None)
    return attribute;
  report(ANARI_SEVERITY_WARNING,
      ANARI_STATUS_INVALID_ARGUMENT,
      "'inAttribute' \"%s\" is not a surface attribute; using attribute0",
      name.c_str());
  return Attribute::Attribute0;
}

ObjectRef<Array> Sampler::readColorArray(
    const char *name, ANARIDataType arrayType, bool (*accepts)(ANARIDataType))
{
  const bool set = isSet(name);
  auto *array = static_cast<Array *>(readObject(name, {arrayType}));
  if (!array) {
    // A wrong handle type was already reported by readObject().
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        set ? "required parameter '%s' is not an %s; the sampler is invalid"
            : "required parameter '%s' (%s of colors) is not set; the sampler "
              "is invalid",
        name,
        anari::toString(arrayType));
    return {};
  }
  if (!accepts(array->elementType())) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'%s' has element type %s, which this sampler does not accept as a "
        "color; the sampler is invalid",
        name,
        anari::toString(array->elementType()));
    return {};
  }
  if (array->count() == 0) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'%s' has no elements; the sampler is invalid",
        name);
    return {};
  }
  return ObjectRef<Array>(array);
}

bool Sampler::convertColors(const Array &array, std::vector<float4> &out) const
{
  try {
    out.assign(array.count(), float4{0.f, 0.f, 0.f, 1.f});
  } catch (const std::exception &) {
    std::vector<float4>().swap(out);
    report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_OUT_OF_MEMORY,
        "out of memory converting %llu elements to float4; the sampler is "
        "invalid",
        (unsigned long long)array.count());
    return false;
  }
  convertToFloat4(
      array.elementType(), array.begin(), out.size(), 0, out.data());
  return true;
}

} // namespace prism
