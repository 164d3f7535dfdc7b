// What a check found, collected while the layer's tables are locked and
// reported to the application after they are unlocked (its callback may
// call back into the device).
#pragma once

#include "ObjectRecord.h"

#include <functional>
#include <string>
#include <vector>

namespace prism::debug {

struct Finding
{
  ANARIStatusSeverity severity = ANARI_SEVERITY_ERROR;
  ANARIStatusCode code = ANARI_STATUS_INVALID_ARGUMENT;
  ANARIObject source = nullptr; // layer handle, nullptr: the device
  ANARIDataType sourceType = ANARI_DEVICE;
  std::string text;
};

// The findings of one API call, each message prefixed with the call:
// "anariSetParameter(world #2 'instance'): ...".
class Findings
{
 public:
  // `function` must outlive this (a string literal).
  explicit Findings(const char *function) : m_function(function) {}

  // Names the object (nullptr: the device) and parameter the call is about,
  // for later messages.
  void about(const ObjectRecord *record, const char *parameter = nullptr);
  void add(ANARIStatusSeverity severity,
      ANARIStatusCode code,
      const std::string &text);
  void error(const std::string &text,
      ANARIStatusCode code = ANARI_STATUS_INVALID_ARGUMENT)
  {
    add(ANARI_SEVERITY_ERROR, code, text);
  }
  void warning(const std::string &text,
      ANARIStatusCode code = ANARI_STATUS_INVALID_ARGUMENT)
  {
    add(ANARI_SEVERITY_WARNING, code, text);
  }
  std::vector<Finding> &list()
  {
    return m_list;
  }
  const char *function() const
  {
    return m_function;
  }
  bool empty() const
  {
    return m_list.empty();
  }
  // Whether anything was found, reported since or not.
  bool any() const
  {
    return m_found > 0;
  }

  // The trace's line for the call if the layer refuses it ("" for none;
  // DebugDevice::checked). Runs under the layer's lock.
  std::function<std::string()> refused;

 private:
  const char *m_function;
  std::string m_prefix;
  ANARIObject m_source = nullptr;
  ANARIDataType m_sourceType = ANARI_DEVICE;
  std::vector<Finding> m_list;
  size_t m_found = 0;
};

// "geometry", "spatial_field", "array1d": the ANARI type name, short.
std::string typeName(ANARIDataType type);
// `geometry triangle #3 "teapot"`: type, subtype, creation number, name.
std::string describe(const ObjectRecord &record);

} // namespace prism::debug
