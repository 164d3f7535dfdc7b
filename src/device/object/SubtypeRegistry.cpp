#include "SubtypeRegistry.h"

namespace prism {

void SubtypeRegistry::add(ANARIDataType type, Factory factory)
{
  m_factories[type].push_back(std::move(factory));
}

bool SubtypeRegistry::creates(ANARIDataType type) const
{
  return m_factories.count(type) != 0;
}

Object *SubtypeRegistry::create(
    DeviceState &device, ANARIDataType type, const std::string &subtype) const
{
  auto it = m_factories.find(type);
  if (it == m_factories.end())
    return nullptr;
  for (auto factory = it->second.rbegin(); factory != it->second.rend();
       ++factory) {
    if (Object *object = (*factory)(device, subtype))
      return object;
  }
  return nullptr;
}

} // namespace prism
