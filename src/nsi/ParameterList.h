// The parameters of one NSI call, copied out of the caller's NSIParam_t
// array; bad parameters are reported and left out.
#pragma once

#include "Value.h"

#include <deque>
#include <functional>
#include <string>
#include <vector>

namespace prism::nsi {

struct NamedValue
{
  std::string name;
  Value value;

  bool operator==(const NamedValue &) const = default;
};

class ParameterList
{
 public:
  ParameterList() = default;
  // `call` names the API call in messages.
  ParameterList(int nparams,
      const NSIParam_t *params,
      const char *call,
      const std::function<void(int, const std::string &)> &report);

  const Value *find(const std::string &name) const;
  std::string string(
      const std::string &name, const std::string &fallback) const;
  double number(const std::string &name, double fallback) const;
  // A pointer parameter's value (the address NSIParam_t.data points at).
  void *pointer(const std::string &name) const;

  std::vector<NamedValue> values;
};

// Values laid out again as an NSIParam_t array, to pass them on to a C
// call; valid while this object and the values live.
class ParamArray
{
 public:
  ParamArray() = default;
  explicit ParamArray(const ParameterList &params);
  void add(const std::string &name, const Value &value);
  int size() const
  {
    return int(m_params.size());
  }
  const NSIParam_t *data() const
  {
    return m_params.data();
  }

 private:
  std::deque<std::vector<const char *>> m_strings; // stable addresses
  std::vector<NSIParam_t> m_params;
};

} // namespace prism::nsi
