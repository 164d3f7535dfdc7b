#include "Findings.h"

#include "anari/frontend/type_utility.h"

#include <cctype>

namespace prism::debug {

std::string typeName(ANARIDataType type)
{
  std::string name = anari::toString(type);
  if (name.rfind("ANARI_", 0) == 0)
    name = name.substr(6);
  for (char &c : name)
    c = char(std::tolower((unsigned char)c));
  return name;
}

std::string describe(const ObjectRecord &record)
{
  std::string out = typeName(record.type);
  if (record.hasSubtype)
    out += " " + record.subtype;
  out += " #" + std::to_string(record.serial);
  if (!record.name.empty())
    out += " \"" + record.name + "\"";
  return out;
}

void Findings::about(const ObjectRecord *record, const char *parameter)
{
  // nullptr: the device itself.
  m_prefix = record ? describe(*record) : "device";
  m_source = record ? record->handle : nullptr;
  m_sourceType = record ? record->type : ANARI_DEVICE;
  if (parameter)
    m_prefix += " '" + std::string(parameter) + "'";
}

void Findings::add(
    ANARIStatusSeverity severity, ANARIStatusCode code, const std::string &text)
{
  Finding f;
  f.severity = severity;
  f.code = code;
  f.source = m_source;
  f.sourceType = m_sourceType;
  f.text = std::string(m_function) + "(" + m_prefix + "): " + text;
  m_list.push_back(std::move(f));
  ++m_found;
}

} // namespace prism::debug
