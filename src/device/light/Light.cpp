#include "Light.h"

#include "../object/FormatText.h"

#include "../array/Array.h"
#include "Sampling.h"

#include "anari/frontend/type_utility.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <exception>

namespace prism {
namespace {

bool isFinite(float3 v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace

Light::Light(DeviceState &device, const std::string &subtype)
    : Object(device, ANARI_LIGHT, subtype)
{}

void Light::commitParameters()
{
  m_valid = true;
  m_color = readColor();
  m_visible = param<bool>("visible");
}

float3 Light::readColor()
{
  float3 color;
  // Beyond the definition's bounds: the value set, unclamped, judged here.
  if (checkedParam("color", color).verdict != ParamVerdict::kAccepted)
    color = readAny("color")->as<float3>();
  if (!isFinite(color) || minComponent(color) < 0.f) {
    invalidate("'color' (%g, %g, %g) must be finite and >= 0",
        color.x,
        color.y,
        color.z);
  }
  return color;
}

Light::Brightness Light::readBrightness(
    std::initializer_list<const char *> precedence)
{
  Brightness result{0, 0.f};
  bool found = false;
  size_t index = 0;
  // Every name is read, so the ones the precedence overrides are not
  // reported as unknown; unset, the first one's default applies.
  for (const char *name : precedence) {
    const Parameter *p = readAny(name);
    const bool set = p && p->type() == ANARI_FLOAT32;
    const float value = lightParam<float>(name);
    if (index == 0)
      result.value = value;
    if (set && !found) {
      found = true;
      result = {index, value};
    }
    index++;
  }
  if (!(std::isfinite(result.value) && result.value >= 0.f)) {
    invalidate("'%s' (%g) must be finite and >= 0",
        precedence.begin()[result.source],
        result.value);
    result.value = 0.f;
  }
  return result;
}

float Light::readNonNegative(const char *name)
{
  const float value = lightParam<float>(name);
  if (std::isfinite(value) && value >= 0.f)
    return value;
  invalidate("'%s' (%g) must be finite and >= 0", name, value);
  return 0.f;
}

float3 Light::readFinite(const char *name)
{
  const float3 value = lightParam<float3>(name);
  if (isFinite(value))
    return value;
  invalidate("'%s' must be finite", name);
  return {0.f, 0.f, 0.f};
}

float3 Light::readDirection(const char *name)
{
  const float3 value = lightParam<float3>(name);
  const float length2 = lengthSquared(value);
  if (isFinite(value) && length2 > 0.f && std::isfinite(length2))
    return value / std::sqrt(length2);
  invalidate("'%s' (%g, %g, %g) must be a finite, non-zero vector",
      name,
      value.x,
      value.y,
      value.z);
  return {0.f, 0.f, 1.f}; // unused: the light is invalid
}

light::ConeFalloff Light::readConeFalloff()
{
  constexpr float kTwoPi = 2.f * light::kPi;
  float openingAngle = readNonNegative("openingAngle");
  if (openingAngle > kTwoPi) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'openingAngle' (%g) is more than 2 pi; using 2 pi",
        openingAngle);
    openingAngle = kTwoPi;
  }
  float falloffAngle = readNonNegative("falloffAngle");
  if (falloffAngle > 0.5f * openingAngle) {
    // The spec asks for less than half the opening angle; more would put
    // the core cone's edge past the axis.
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'falloffAngle' (%g) is more than half of 'openingAngle' (%g); "
        "using %g",
        falloffAngle,
        openingAngle,
        0.5f * openingAngle);
    falloffAngle = 0.5f * openingAngle;
  }
  return light::ConeFalloff(openingAngle, falloffAngle);
}

Array *Light::readIntensityDistribution()
{
  const bool set = isSet("intensityDistribution");
  auto *array = static_cast<Array *>(
      readObject("intensityDistribution", {ANARI_ARRAY1D, ANARI_ARRAY2D}));
  if (!array) {
    if (set) // the type was reported by readObject()
      invalidate("'intensityDistribution' is not an ARRAY1D or ARRAY2D");
    return nullptr;
  }
  if (array->elementType() != ANARI_FLOAT32) {
    invalidate("'intensityDistribution' has element type %s, not FLOAT32",
        anari::toString(array->elementType()));
    return nullptr;
  }
  return array;
}

std::shared_ptr<const light::IntensityDistribution>
Light::buildIntensityDistribution(const Array *array)
{
  if (!array)
    return nullptr;
  try {
    auto table = std::make_shared<light::IntensityDistribution>();
    const char *why = "";
    if (!table->assign(*array, why)) {
      invalidate("'intensityDistribution' %s", why);
      return nullptr;
    }
    return table;
  } catch (const std::exception &) {
    report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_OUT_OF_MEMORY,
        "out of memory reading 'intensityDistribution'; the light is invalid");
    m_valid = false;
    return nullptr;
  }
}

void Light::invalidate(const char *format, ...)
{
  va_list args;
  va_start(args, format);
  const std::string text = formatTextV(format, args);
  va_end(args);
  report(ANARI_SEVERITY_WARNING,
      ANARI_STATUS_INVALID_ARGUMENT,
      "%s; the light is invalid",
      text.c_str());
  m_valid = false;
}

} // namespace prism
