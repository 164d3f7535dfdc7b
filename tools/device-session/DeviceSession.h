// The ANARI library and device a tool (prism-render, prism-viewer) uses, and
// every object it creates: opened by name, released in reverse order however
// the run ends. Device messages go to the tool's message sink with their
// severity (warnings and worse always, the rest when verbose) and errors are
// counted, so a stage can tell whether the device refused what it was given.
#pragma once

#include <anari/anari.h>

#include <atomic>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace prism::tools {

// Which library and device to open.
struct DeviceChoice
{
  std::string library{"prism"};
  std::string deviceSubtype{"default"};
  uint32_t threads{0}; // numThreads, where the device takes it; 0: its choice
};

// Where device messages go (one line, without newline). NOTE: called from
// device threads.
using MessageSink = void (*)(const std::string &line);

class DeviceSession
{
 public:
  DeviceSession(bool verbose, MessageSink sink);
  ~DeviceSession();
  DeviceSession(const DeviceSession &) = delete;
  DeviceSession &operator=(const DeviceSession &) = delete;

  // Loads the library and creates the device `choice` names (and gives it
  // `threads` where it takes numThreads); the error says why not, with
  // `usage` true when the choice names something that does not exist.
  std::string open(const DeviceChoice &choice, bool &usage);

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
  void limitThreads(const DeviceChoice &choice);

  bool m_verbose;
  MessageSink m_sink;
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

} // namespace prism::tools
