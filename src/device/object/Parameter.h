// One staged parameter value and the per-object store of them. Values are
// copied at anariSetParameter; object handles hold an internal reference.
#pragma once

#include "anari/anari.h"

#include <cstdint>
#include <cstring>
#include <map>
#include <string>

namespace prism {

class Object;

// A typed value as set by the application (up to a 4x4 matrix of floats,
// a string, or an object with an internal reference held on it).
class Parameter
{
 public:
  Parameter() = default;
  Parameter(const Parameter &other);
  Parameter &operator=(const Parameter &other);
  ~Parameter();

  // Copies `mem` (interpreted per the spec: STRING and VOID_POINTER by
  // value); `object` is the resolved handle for object types.
  static Parameter make(ANARIDataType type, const void *mem, Object *object);

  // The largest value held (larger ones are dropped at make()).
  static constexpr size_t kValueBytes = 128;

  ANARIDataType type() const
  {
    return m_type;
  }
  const void *data() const
  {
    return m_bytes;
  }
  const std::string &string() const
  {
    return m_string;
  }
  Object *object() const
  {
    return m_object;
  }
  template <typename T>
  T as() const
  {
    static_assert(sizeof(T) <= sizeof(m_bytes));
    T value;
    std::memcpy(&value, m_bytes, sizeof(T));
    return value;
  }

 private:
  void adopt(Object *object);

  ANARIDataType m_type{ANARI_UNKNOWN};
  alignas(16) unsigned char m_bytes[kValueBytes]{};
  std::string m_string;
  Object *m_object{nullptr};
};

// Staged parameters of one object; read only by the object's commit.
class ParameterStore
{
 public:
  void set(const std::string &name, Parameter value);
  void unset(const std::string &name);
  void unsetAll();
  const Parameter *find(const std::string &name) const;
  const std::map<std::string, Parameter> &all() const
  {
    return m_values;
  }

 private:
  std::map<std::string, Parameter> m_values;
};

} // namespace prism
