// The ANARI library and device a prism-render run uses, and every object it
// creates: opened from the options, released in reverse order however the
// run ends. Device messages go to stderr with their severity (warnings and
// worse always, the rest with --verbose) and errors are counted, so a stage
// can tell whether the device refused what it was given.
#pragma once

#include "Options.h"

#include <anari/anari.h>

#include <atomic>
#include <set>
#include <string>
#include <vector>

namespace prism::render {

class DeviceSession
{
 public:
  explicit DeviceSession(bool verbose);
  ~DeviceSession();
  DeviceSession(const DeviceSession &) = delete;
  DeviceSession &operator=(const DeviceSession &) = delete;

  // Loads the library and creates the device the options name (and gives
  // it --threads where it takes numThreads); the error says why not, with
  // `usage` true when the options name something that does not exist.
  std::string open(const Options &options, bool &usage);

  ANARIDevice device() const
  {
    return m_device;
  }
  bool has(const char *extension) const
  {
    return m_extensions.count(extension) > 0;
  }
  // Device errors reported so far.
  int errors() const
  {
    return m_errors.load();
  }
  // Takes over the reference to `object`, released with the session.
  template <typename T>
  T keep(T object)
  {
    m_objects.push_back(object);
    return object;
  }

 private:
  static void onStatus(const void *self,
      ANARIDevice,
      ANARIObject,
      ANARIDataType,
      ANARIStatusSeverity severity,
      ANARIStatusCode,
      const char *message);
  void limitThreads(const Options &options);

  bool m_verbose;
  std::atomic<int> m_errors{0};
  ANARILibrary m_library{nullptr};
  ANARIDevice m_device{nullptr};
  std::set<std::string> m_extensions;
  std::vector<ANARIObject> m_objects;
};

// "a, b, c" of a NULL-terminated list, or "none".
std::string joinList(const char **list);
// Whether the NULL-terminated `list` holds `name`.
bool contains(const char **list, const std::string &name);

} // namespace prism::render
