// A device library that another device library loads for itself, by the
// naming rules of anariLoadLibrary, to forward calls to one of its devices
// (the debug layer, and prism_mpi's wrappedLibrary). Compiled into those
// libraries, not into libanari, so they work under any front-end.
#pragma once

#include "anari/backend/LibraryImpl.h"

#include <memory>
#include <string>

namespace prism::frontend {

class LoadedLibrary
{
 public:
  // Loads "name" or "name,folder/" as anariLoadLibrary does (the loader's
  // search, then the folder of the library this code is linked into); the
  // library's default status callback is `callback`. `self` names the
  // calling library, which may not load itself. NULL and a reason on
  // failure.
  static std::shared_ptr<LoadedLibrary> load(const std::string &spec,
      ANARIStatusCallback callback,
      const void *userPtr,
      const std::string &self,
      std::string &error);
  ~LoadedLibrary();
  LoadedLibrary(const LoadedLibrary &) = delete;
  LoadedLibrary &operator=(const LoadedLibrary &) = delete;

  anari::LibraryImpl &library() const
  {
    return *m_library;
  }
  const std::string &name() const
  {
    return m_name;
  }

 private:
  LoadedLibrary() = default;
  std::string m_name;
  void *m_dlHandle{nullptr};
  anari::LibraryImpl *m_library{nullptr};
};

} // namespace prism::frontend
