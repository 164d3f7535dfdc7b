// Which library and device handles the front-end has handed out and are
// still alive, so a NULL, stale or foreign handle is reported instead of
// being dereferenced (the Khronos SDK's front-end trusts every handle).
#pragma once

#include "anari/backend/DeviceImpl.h"

#include <mutex>
#include <unordered_map>

namespace prism::frontend {

// Where to report a problem: a status callback and its user pointer.
struct StatusSink
{
  ANARIStatusCallback callback{nullptr};
  const void *userPtr{nullptr};
};

class HandleRegistry
{
 public:
  static HandleRegistry &instance();

  void addLibrary(anari::LibraryImpl *library, StatusSink sink);
  bool hasLibrary(ANARILibrary handle) const;
  // Forgets `library`; returns the dlopen handle to close now, or NULL when
  // devices created from it are still alive (closed with the last one).
  void *removeLibrary(anari::LibraryImpl *library);

  void addDevice(anari::DeviceImpl *device, anari::LibraryImpl *library);
  bool hasDevice(ANARIDevice handle) const;
  // Mirrors anariRetain/anariRelease on the device itself.
  void retainDevice(anari::DeviceImpl *device);
  // Returns the dlopen handle to close once the last public reference of
  // the last device of an already unloaded library is gone, else NULL.
  void *releaseDevice(anari::DeviceImpl *device);

  // Where to report about a handle we do not know: the status callback of
  // the most recently loaded library that is still loaded.
  StatusSink fallbackSink() const;
  // The status callback of the library a device came from.
  StatusSink sinkOf(ANARIDevice handle) const;

 private:
  struct LibraryRecord
  {
    StatusSink sink;
    void *dlHandle{nullptr};
    int liveDevices{0};
    bool unloaded{false};
    unsigned long loadOrder{0};
  };
  struct DeviceRecord
  {
    anari::LibraryImpl *library{nullptr};
    long publicRefs{1};
  };

  mutable std::mutex m_mutex;
  std::unordered_map<anari::LibraryImpl *, LibraryRecord> m_libraries;
  std::unordered_map<anari::DeviceImpl *, DeviceRecord> m_devices;
  unsigned long m_loadCounter{0};
};

} // namespace prism::frontend
