#include "Parameter.h"

#include "Object.h"

#include "anari/frontend/type_utility.h"

namespace prism {

Parameter::Parameter(const Parameter &other)
{
  *this = other;
}

Parameter &Parameter::operator=(const Parameter &other)
{
  if (this == &other)
    return *this;
  Object *previous = m_object;
  m_type = other.m_type;
  std::memcpy(m_bytes, other.m_bytes, sizeof(m_bytes));
  m_string = other.m_string;
  m_object = nullptr;
  adopt(other.m_object);
  if (previous)
    previous->releaseInternal();
  return *this;
}

Parameter::~Parameter()
{
  if (m_object)
    m_object->releaseInternal();
}

void Parameter::adopt(Object *object)
{
  m_object = object;
  if (m_object)
    m_object->retainInternal();
}

Parameter Parameter::make(ANARIDataType type, const void *mem, Object *object)
{
  Parameter p;
  p.m_type = type;
  if (type == ANARI_STRING) {
    p.m_string = mem ? (const char *)mem : "";
  } else if (type == ANARI_VOID_POINTER) {
    std::memcpy(p.m_bytes, &mem, sizeof(mem));
  } else if (anari::isObject(type)) {
    p.adopt(object);
  } else if (mem) {
    const size_t size = anari::sizeOf(type);
    if (size <= sizeof(p.m_bytes))
      std::memcpy(p.m_bytes, mem, size);
  }
  return p;
}

void ParameterStore::set(const std::string &name, Parameter value)
{
  m_values[name] = std::move(value);
}

void ParameterStore::unset(const std::string &name)
{
  m_values.erase(name);
}

void ParameterStore::unsetAll()
{
  m_values.clear();
}

const Parameter *ParameterStore::find(const std::string &name) const
{
  auto it = m_values.find(name);
  return it == m_values.end() ? nullptr : &it->second;
}

} // namespace prism
