#include "LoadedLibrary.h"

#include <dlfcn.h>

namespace prism::frontend {
namespace {

// The folder holding the library this code is linked into: device
// libraries usually sit beside it.
std::string ownDirectory()
{
  Dl_info info{};
  if (!dladdr((void *)&ownDirectory, &info) || !info.dli_fname)
    return {};
  std::string path = info.dli_fname;
  auto slash = path.rfind('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

} // namespace

std::shared_ptr<LoadedLibrary> LoadedLibrary::load(const std::string &spec,
    ANARIStatusCallback callback,
    const void *userPtr,
    const std::string &self,
    std::string &error)
{
  std::string name = spec;
  std::string folder;
  if (auto comma = spec.find(','); comma != std::string::npos) {
    name = spec.substr(0, comma);
    folder = spec.substr(comma + 1);
    if (!folder.empty() && folder.back() != '/')
      folder += '/';
  }
  if (name.empty() || name == self) {
    // A library loading itself would recurse without end.
    error = "cannot wrap library '" + name + "'";
    return nullptr;
  }
  const std::string file = "libanari_library_" + name + ".so";
  void *dlHandle = anari::loadANARILibrary(folder + file);
  if (!dlHandle) {
    const char *reason = dlerror();
    error = reason ? reason : "not found";
    const std::string own = ownDirectory();
    if (!own.empty() && own != folder)
      dlHandle = anari::loadANARILibrary(own + file);
    if (!dlHandle) {
      reason = dlerror();
      error += std::string("; ") + (reason ? reason : "not found");
      return nullptr;
    }
  }
  using EntryPoint =
      ANARILibrary (*)(void *, ANARIStatusCallback, const void *);
  const std::string symbol = "anari_library_" + name + "_new_library";
  auto entry = (EntryPoint)anari::getSymbolAddress(dlHandle, symbol);
  auto *library = entry
                      ? (anari::LibraryImpl *)entry(dlHandle, callback, userPtr)
                      : nullptr;
  if (!library) {
    error =
        entry ? "its entry point returned NULL" : "no entry point " + symbol;
    anari::freeLibrary(dlHandle);
    return nullptr;
  }
  std::shared_ptr<LoadedLibrary> out(new LoadedLibrary);
  out->m_name = name;
  out->m_dlHandle = dlHandle;
  out->m_library = library;
  return out;
}

LoadedLibrary::~LoadedLibrary()
{
  delete m_library;
  // NOTE: closing before the delete would unmap the destructor's code.
  anari::freeLibrary(m_dlHandle);
}

} // namespace prism::frontend
