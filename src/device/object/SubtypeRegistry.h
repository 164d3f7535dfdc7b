// Which objects anariNew* creates: per object type, factories that know
// their subtypes. The categories provide the factories; the device (above
// them all) fills its registry at start, and a device built on this one
// (data-parallel, validating) may add subtypes or replace existing ones.
#pragma once

#include "Object.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace prism {

class SubtypeRegistry
{
 public:
  // A new object of the subtype, or NULL when the factory does not know it.
  using Factory =
      std::function<Object *(DeviceState &device, const std::string &subtype)>;

  // The newest factory of a type is asked first, so later additions
  // override earlier ones.
  void add(ANARIDataType type, Factory factory);
  // Whether any factory creates objects of `type`.
  bool creates(ANARIDataType type) const;
  // A new object, or NULL when no factory knows the subtype.
  Object *create(DeviceState &device,
      ANARIDataType type,
      const std::string &subtype) const;

 private:
  std::map<ANARIDataType, std::vector<Factory>> m_factories;
};

} // namespace prism
