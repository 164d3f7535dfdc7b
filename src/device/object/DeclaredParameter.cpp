#include "DeclaredParameter.h"

#include "anari/frontend/type_utility.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace prism {
namespace {

enum class Scalar {
  kNone,
  kFloat,
  kInt32,
  kUint32,
  kUint64,
};

// The scalar every component of `type` is, for the types whose values
// have bounds.
Scalar scalarOf(ANARIDataType type)
{
  const int t = int(type);
  if ((t >= ANARI_FLOAT32 && t <= ANARI_FLOAT32_VEC4)
      || (t >= ANARI_FLOAT32_BOX1 && t <= ANARI_FLOAT32_BOX4)
      || t == ANARI_FLOAT32_MAT4)
    return Scalar::kFloat;
  if (t >= ANARI_INT32 && t <= ANARI_INT32_VEC4)
    return Scalar::kInt32;
  if (t >= ANARI_UINT32 && t <= ANARI_UINT32_VEC4)
    return Scalar::kUint32;
  if (t == ANARI_UINT64)
    return Scalar::kUint64;
  return Scalar::kNone;
}

template <typename T>
double load(const void *bytes, int i)
{
  T v;
  std::memcpy(&v, (const char *)bytes + i * sizeof(v), sizeof(v));
  return double(v);
}

double component(Scalar scalar, const void *bytes, int i)
{
  switch (scalar) {
  case Scalar::kFloat:
    return load<float>(bytes, i);
  case Scalar::kInt32:
    return load<int32_t>(bytes, i);
  case Scalar::kUint32:
    return load<uint32_t>(bytes, i);
  case Scalar::kUint64:
    return load<uint64_t>(bytes, i);
  default:
    return 0.0;
  }
}

template <typename T>
void storeComponent(void *bytes, int i, double v)
{
  const T t = T(v);
  std::memcpy((char *)bytes + i * sizeof(t), &t, sizeof(t));
}

void setComponent(Scalar scalar, void *bytes, int i, double v)
{
  switch (scalar) {
  case Scalar::kFloat:
    return storeComponent<float>(bytes, i, v);
  case Scalar::kInt32:
    return storeComponent<int32_t>(bytes, i, v);
  case Scalar::kUint32:
    return storeComponent<uint32_t>(bytes, i, v);
  case Scalar::kUint64:
    return storeComponent<uint64_t>(bytes, i, v);
  default:
    return;
  }
}

std::string number(double v)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%g", v);
  return text;
}

} // namespace

std::string valueText(ANARIDataType type, const void *bytes)
{
  if (int(type) == int(ANARI_BOOL))
    return *(const uint8_t *)bytes ? "true" : "false";
  if (int(type) == int(ANARI_STRING))
    return std::string("\"") + (const char *)bytes + "\"";
  const Scalar scalar = scalarOf(type);
  if (scalar == Scalar::kNone)
    return anari::toString(type);
  const int count = anari::componentsOf(type);
  std::string text = count > 1 ? "(" : "";
  for (int i = 0; i < count; i++)
    text += (i ? ", " : "") + number(component(scalar, bytes, i));
  return text + (count > 1 ? ")" : "");
}

ParamVerdict checkBounds(const introspection::ParameterDefinition &definition,
    ANARIDataType type,
    const void *bytes,
    std::string &problem)
{
  const Scalar scalar = scalarOf(type);
  if (scalar == Scalar::kNone)
    return ParamVerdict::kAccepted;
  const bool bounded = int(definition.valueType) == int(type);
  const void *minimum = bounded ? definition.minimum : nullptr;
  const void *maximum = bounded ? definition.maximum : nullptr;
  bool below = false, above = false;
  for (int i = 0; i < anari::componentsOf(type); i++) {
    const double v = component(scalar, bytes, i);
    if (std::isnan(v)) {
      problem = "is not a number";
      return ParamVerdict::kRejected;
    }
    below |= minimum && v < component(scalar, minimum, i);
    above |= maximum && v > component(scalar, maximum, i);
  }
  if (!below && !above)
    return ParamVerdict::kAccepted;
  if (minimum && maximum) {
    problem = "must be in [" + valueText(type, minimum) + ", "
              + valueText(type, maximum) + "]";
  } else {
    problem = minimum ? "must be >= " + valueText(type, minimum)
                      : "must be <= " + valueText(type, maximum);
  }
  return below ? ParamVerdict::kBelowMinimum : ParamVerdict::kAboveMaximum;
}

void clampToBounds(const introspection::ParameterDefinition &definition,
    ANARIDataType type,
    void *bytes)
{
  const Scalar scalar = scalarOf(type);
  if (scalar == Scalar::kNone || int(definition.valueType) != int(type))
    return;
  for (int i = 0; i < anari::componentsOf(type); i++) {
    double v = component(scalar, bytes, i);
    if (definition.minimum)
      v = std::max(v, component(scalar, definition.minimum, i));
    if (definition.maximum)
      v = std::min(v, component(scalar, definition.maximum, i));
    setComponent(scalar, bytes, i, v);
  }
}

std::string valueProblem(const introspection::ParameterDefinition &definition,
    const std::string &text)
{
  if (!definition.values || definition.attribute)
    return {};
  std::string list;
  for (size_t i = 0; i < definition.valueCount; i++) {
    if (text == definition.values[i])
      return {};
    list += std::string(i ? ", " : "") + definition.values[i];
  }
  return "must be one of: " + list;
}

} // namespace prism
