// One attribute value as NSI passes it: a type, a count of items (each an
// array of `arraylength` values when flagged), the flags, and a copy of the
// data. Strings are kept as std::string.
#pragma once

#include "nsi.h"

#include <cstdint>
#include <string>
#include <vector>

namespace prism::nsi {

struct Value
{
  int type{NSITypeInvalid};
  int arraylength{0};
  size_t count{0};
  int flags{0};
  std::vector<unsigned char> bytes; // numbers, as the caller laid them out
  std::vector<std::string> strings; // NSITypeString only

  // Values per item: arraylength when NSIParamIsArray is set, else 1.
  size_t valuesPerItem() const;
  // Scalars in one value of `type` (3 for a color, 16 for a matrix...).
  static size_t componentsOf(int type);
  // True for the types whose values are 32-bit floats (float, color...).
  static bool storesFloats(int type);
  // Every number widened to double, in order (empty for strings/pointers).
  std::vector<double> numbers() const;
  // The first number, or `fallback` when there is none.
  double number(double fallback) const;
  std::string string(const std::string &fallback = {}) const;

  bool operator==(const Value &) const = default;
};

// A number for messages: "1e+300", "7", "nan".
std::string shortNumber(double number);

// Copies `param` into `value`; false with `error` when the parameter is not
// one NSI can carry (no name, unknown type, negative sizes, missing data).
bool valueFromParam(const NSIParam_t &param, Value &value, std::string &error);

} // namespace prism::nsi
