// The device library the debug layer wraps, loaded by the layer itself (not
// through libanari) so the layer works under any front-end.
#pragma once

#include "anari/backend/LibraryImpl.h"

#include <memory>
#include <string>

namespace prism::debug {

class WrappedLibrary
{
 public:
  // Loads "name" or "name,folder/" as anariLoadLibrary does; the library's
  // default status callback is `callback`. NULL and a reason on failure.
  static std::shared_ptr<WrappedLibrary> load(const std::string &spec,
      ANARIStatusCallback callback,
      const void *userPtr,
      std::string &error);
  ~WrappedLibrary();
  WrappedLibrary(const WrappedLibrary &) = delete;
  WrappedLibrary &operator=(const WrappedLibrary &) = delete;

  anari::LibraryImpl &library() const
  {
    return *m_library;
  }
  const std::string &name() const
  {
    return m_name;
  }

 private:
  WrappedLibrary() = default;
  std::string m_name;
  void *m_dlHandle{nullptr};
  anari::LibraryImpl *m_library{nullptr};
};

// The library to wrap when nothing else says: ANARI_DEBUG_WRAPPED_LIBRARY,
// else "prism".
std::string defaultWrappedLibrary();
// The device subtype of the wrapped library to create when nothing else
// says: ANARI_DEBUG_WRAPPED_DEVICE, else the one the application asked the
// layer for (NULL: "default").
std::string defaultWrappedDevice(const char *requested);

} // namespace prism::debug
