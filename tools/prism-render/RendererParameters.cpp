#include "RendererParameters.h"

#include <anari/frontend/type_utility.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace prism::render {
namespace {

std::vector<std::string> splitCommas(const std::string &text)
{
  std::vector<std::string> items;
  size_t start = 0;
  while (true) {
    const size_t comma = text.find(',', start);
    items.push_back(text.substr(start, comma - start));
    if (comma == std::string::npos)
      return items;
    start = comma + 1;
  }
}

bool parseDouble(const std::string &text, double &value)
{
  if (text.empty())
    return false;
  errno = 0;
  char *end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return errno == 0 && *end == '\0' && std::isfinite(value);
}

bool parseInteger(const std::string &text, bool isSigned, long double &value)
{
  if (text.empty())
    return false;
  errno = 0;
  char *end = nullptr;
  if (isSigned) {
    value = (long double)std::strtoll(text.c_str(), &end, 10);
  } else {
    if (text[0] == '-')
      return false;
    value = (long double)std::strtoull(text.c_str(), &end, 10);
  }
  return errno == 0 && *end == '\0';
}

template <typename T>
bool storeInteger(long double value, unsigned char *out)
{
  if (value < (long double)std::numeric_limits<T>::min()
      || value > (long double)std::numeric_limits<T>::max())
    return false;
  const T v = T(value);
  std::memcpy(out, &v, sizeof(T));
  return true;
}

bool parseBool(const std::string &text, bool &value)
{
  for (const char *yes : {"true", "1", "on", "yes"})
    if (text == yes) {
      value = true;
      return true;
    }
  for (const char *no : {"false", "0", "off", "no"})
    if (text == no) {
      value = false;
      return true;
    }
  return false;
}

const ANARIParameter *parameterList(
    ANARIDevice device, const std::string &subtype)
{
  return (const ANARIParameter *)anariGetObjectInfo(device,
      ANARI_RENDERER,
      subtype.c_str(),
      "parameter",
      ANARI_PARAMETER_LIST);
}

// The type a value's spelling suggests, for devices without introspection.
ANARIDataType guessType(const std::string &text)
{
  bool flag = false;
  if (parseBool(text, flag) && text != "0" && text != "1")
    return ANARI_BOOL;
  const std::vector<std::string> items = splitCommas(text);
  bool numbers = items.size() <= 4, integers = true;
  for (const std::string &item : items) {
    double d = 0.0;
    numbers = numbers && parseDouble(item, d);
    integers = integers && item.find_first_of(".eE") == std::string::npos;
  }
  if (!numbers)
    return ANARI_STRING;
  const int n = int(items.size());
  if (integers)
    return ANARIDataType(ANARI_INT32 + n - 1);
  return ANARIDataType(ANARI_FLOAT32 + n - 1);
}

std::string typeName(ANARIDataType type)
{
  std::string name = anari::toString(type);
  return name.starts_with("ANARI_") ? name.substr(6) : name;
}

} // namespace

bool parseParameterValue(ANARIDataType type,
    const std::string &text,
    std::vector<unsigned char> &bytes)
{
  if (type == ANARI_STRING) {
    bytes.assign(text.begin(), text.end());
    bytes.push_back('\0');
    return true;
  }
  if (type == ANARI_BOOL) {
    bool value = false;
    if (!parseBool(text, value))
      return false;
    // Zero-filled so either width of ANARI_BOOL reads the same value.
    bytes.assign(std::max<size_t>(anari::sizeOf(type), 4), 0);
    bytes[0] = value ? 1 : 0;
    return true;
  }
  const int t = int(type);
  const bool isInteger = t >= ANARI_INT8 && t <= ANARI_UINT64_VEC4;
  const bool isFloat32 =
      (t >= ANARI_FLOAT32 && t <= ANARI_FLOAT32_VEC4)
      || (t >= ANARI_FLOAT32_BOX1 && t <= ANARI_FLOAT32_BOX4)
      || (t >= ANARI_FLOAT32_MAT2 && t <= ANARI_FLOAT32_QUAT_IJKW);
  const bool isFloat64 =
      (t >= ANARI_FLOAT64 && t <= ANARI_FLOAT64_VEC4)
      || (t >= ANARI_FLOAT64_BOX1 && t <= ANARI_FLOAT64_BOX4);
  if (!isInteger && !isFloat32 && !isFloat64)
    return false;
  const int components = anari::componentsOf(type);
  const std::vector<std::string> items = splitCommas(text);
  if (components <= 0 || int(items.size()) != components)
    return false;
  const size_t size = anari::sizeOf(type);
  bytes.assign(size, 0);
  const size_t componentSize = size / size_t(components);
  for (int i = 0; i < components; i++) {
    unsigned char *out = bytes.data() + size_t(i) * componentSize;
    if (isInteger) {
      // INT8, UINT8, INT16, ... in blocks of four (scalar, vec2-4).
      const int kind = (t - ANARI_INT8) / 4;
      long double value = 0;
      if (!parseInteger(items[i], kind % 2 == 0, value))
        return false;
      bool ok = false;
      switch (kind) {
      case 0:
        ok = storeInteger<int8_t>(value, out);
        break;
      case 1:
        ok = storeInteger<uint8_t>(value, out);
        break;
      case 2:
        ok = storeInteger<int16_t>(value, out);
        break;
      case 3:
        ok = storeInteger<uint16_t>(value, out);
        break;
      case 4:
        ok = storeInteger<int32_t>(value, out);
        break;
      case 5:
        ok = storeInteger<uint32_t>(value, out);
        break;
      case 6:
        ok = storeInteger<int64_t>(value, out);
        break;
      default:
        ok = storeInteger<uint64_t>(value, out);
        break;
      }
      if (!ok)
        return false;
    } else {
      double value = 0.0;
      if (!parseDouble(items[i], value))
        return false;
      if (isFloat32) {
        if (std::fabs(value) > std::numeric_limits<float>::max())
          return false;
        const float f = float(value);
        std::memcpy(out, &f, sizeof(f));
      } else {
        std::memcpy(out, &value, sizeof(value));
      }
    }
  }
  return true;
}

Declared rendererDeclares(
    ANARIDevice device, const std::string &subtype, const std::string &name)
{
  const ANARIParameter *list = parameterList(device, subtype);
  if (!list || !list->name)
    return Declared::Unknown;
  for (; list->name; ++list)
    if (name == list->name)
      return Declared::Yes;
  return Declared::No;
}

ParameterOutcome setRendererParameters(ANARIDevice device,
    ANARIRenderer renderer,
    const std::string &subtype,
    const std::vector<std::pair<std::string, std::string>> &parameters)
{
  ParameterOutcome outcome;
  const ANARIParameter *list = parameterList(device, subtype);
  const bool described = list && list->name;
  for (const auto &[name, text] : parameters) {
    const std::string what = "--param " + name + "=" + text;
    std::vector<ANARIDataType> types;
    for (const ANARIParameter *p = list; described && p->name; ++p)
      if (name == p->name)
        types.push_back(p->type);
    if (types.empty() && described) {
      // Typed by introspection only: a device that declares its renderer's
      // parameters reads nothing else, so an undeclared one is a mistake.
      std::string declared;
      for (const ANARIParameter *p = list; p->name; ++p)
        if (declared.find(std::string(" ") + p->name + ",")
            == std::string::npos)
          declared += std::string(" ") + p->name + ",";
      declared.pop_back();
      outcome.error = what + ": the '" + subtype
                      + "' renderer has no parameter '" + name
                      + "' (it declares:" + declared + ")";
      return outcome;
    }
    if (types.empty()) {
      // A device without introspection: the value's spelling decides.
      const ANARIDataType guess = guessType(text);
      types.push_back(guess);
      outcome.warnings.push_back("the device describes no parameters of the '"
                                 + subtype + "' renderer; " + what
                                 + " is sent as " + typeName(guess));
    }

    bool applied = false;
    std::string accepted;
    for (ANARIDataType type : types) {
      std::vector<unsigned char> bytes;
      accepted += std::string(accepted.empty() ? "" : " or ") + typeName(type);
      if (!parseParameterValue(type, text, bytes))
        continue;
      if (type == ANARI_STRING) {
        // Enumerated strings are checked against the declared values.
        const char **values = (const char **)anariGetParameterInfo(device,
            ANARI_RENDERER,
            subtype.c_str(),
            name.c_str(),
            type,
            "value",
            ANARI_STRING_LIST);
        if (values && *values) {
          std::string allowed;
          bool found = false;
          for (const char **v = values; *v; ++v) {
            found = found || text == *v;
            allowed += std::string(allowed.empty() ? "" : ", ") + *v;
          }
          if (!found) {
            outcome.error = what + ": '" + text + "' is not a value of '" + name
                            + "' (one of: " + allowed + ")";
            return outcome;
          }
        }
        anariSetParameter(device, renderer, name.c_str(), type, text.c_str());
      } else {
        anariSetParameter(device, renderer, name.c_str(), type, bytes.data());
      }
      applied = true;
      break;
    }
    if (!applied) {
      outcome.error = what + ": the value does not fit '" + name
                      + "', which is " + accepted
                      + " (numbers are comma-separated, e.g. 0.1,0.2,0.3)";
      return outcome;
    }
  }
  return outcome;
}

} // namespace prism::render
