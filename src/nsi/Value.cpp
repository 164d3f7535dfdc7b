#include "Value.h"

#include "MachineLimits.h"

#include <cstdio>
#include <cstring>

namespace prism::nsi {

size_t Value::valuesPerItem() const
{
  return (flags & NSIParamIsArray) ? size_t(arraylength) : 1;
}

size_t Value::componentsOf(int type)
{
  switch (type) {
  case NSITypeColor:
  case NSITypePoint:
  case NSITypeVector:
  case NSITypeNormal:
    return 3;
  case NSITypeHPoint:
    return 4;
  case NSITypeMatrix:
  case NSITypeDoubleMatrix:
    return 16;
  default:
    return 1;
  }
}

bool Value::storesFloats(int type)
{
  switch (type) {
  case NSITypeFloat:
  case NSITypeColor:
  case NSITypePoint:
  case NSITypeVector:
  case NSITypeNormal:
  case NSITypeMatrix:
  case NSITypeHPoint:
    return true;
  default:
    return false;
  }
}

std::vector<double> Value::numbers() const
{
  std::vector<double> out;
  const size_t n = count * valuesPerItem() * componentsOf(type);
  out.reserve(n);
  for (size_t i = 0; i < n; ++i) {
    if (storesFloats(type)) {
      float f;
      std::memcpy(&f, bytes.data() + 4 * i, 4);
      out.push_back(f);
      continue;
    }
    switch (type) {
    case NSITypeInteger: {
      int32_t v;
      std::memcpy(&v, bytes.data() + 4 * i, 4);
      out.push_back(v);
      break;
    }
    case NSITypeDouble:
    case NSITypeDoubleMatrix: {
      double d;
      std::memcpy(&d, bytes.data() + 8 * i, 8);
      out.push_back(d);
      break;
    }
    case NSITypeInt64: {
      int64_t v;
      std::memcpy(&v, bytes.data() + 8 * i, 8);
      out.push_back(double(v));
      break;
    }
    default:
      return {};
    }
  }
  return out;
}

double Value::number(double fallback) const
{
  const auto all = numbers();
  return all.empty() ? fallback : all.front();
}

std::string Value::string(const std::string &fallback) const
{
  return strings.empty() ? fallback : strings.front();
}

std::string shortNumber(double number)
{
  char text[32];
  std::snprintf(text, sizeof text, "%g", number);
  return text;
}

bool valueFromParam(const NSIParam_t &param, Value &value, std::string &error)
{
  if (!param.name) {
    error = "parameter without a name";
    return false;
  }
  const size_t size = NSITypeSizeOf(unsigned(param.type));
  if (size == 0) {
    error = "parameter '" + std::string(param.name) + "' has unknown type "
            + std::to_string(param.type);
    return false;
  }
  if ((param.flags & NSIParamIsArray) && param.arraylength < 0) {
    error = "parameter '" + std::string(param.name)
            + "' has a negative arraylength";
    return false;
  }
  value = {};
  value.type = param.type;
  value.arraylength = param.arraylength;
  value.count = param.count;
  value.flags = param.flags;
  // Counts beyond what memory could hold are nonsense, not data to copy
  // (their product may even wrap around to a small number).
  const uint64_t counts[2] = {uint64_t(param.count), value.valuesPerItem()};
  uint64_t bytes = 0;
  if (!limits::checkedBytes(counts, 2, size, bytes)
      || !limits::fitsInMemory(bytes)) {
    error = "parameter '" + std::string(param.name) + "' has an absurd count ("
            + std::to_string(param.count) + " of "
            + std::to_string(value.valuesPerItem()) + " values, more than "
            + limits::memoryLimitText() + ")";
    return false;
  }
  const size_t items = param.count * value.valuesPerItem();
  if (items > 0 && !param.data) {
    error = "parameter '" + std::string(param.name) + "' has no data";
    return false;
  }
  if (param.type == NSITypeString) {
    const auto *texts = static_cast<const char *const *>(param.data);
    for (size_t i = 0; i < items; ++i)
      value.strings.emplace_back(texts[i] ? texts[i] : "");
  } else {
    value.bytes.resize(items * size);
    if (items)
      std::memcpy(value.bytes.data(), param.data, items * size);
  }
  return true;
}

} // namespace prism::nsi
