#include "WrappedLibrary.h"

#include <dlfcn.h>

#include <cstdlib>

namespace prism::debug {
namespace {

// The folder holding the debug layer: device libraries usually sit beside it.
std::string layerDirectory()
{
  Dl_info info{};
  if (!dladdr((void *)&layerDirectory, &info) || !info.dli_fname)
    return {};
  std::string path = info.dli_fname;
  auto slash = path.rfind('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

} // namespace

std::string defaultWrappedLibrary()
{
  const char *name = std::getenv("ANARI_DEBUG_WRAPPED_LIBRARY");
  return name && *name ? name : "prism";
}

std::string defaultWrappedDevice(const char *requested)
{
  const char *subtype = std::getenv("ANARI_DEBUG_WRAPPED_DEVICE");
  if (subtype && *subtype)
    return subtype;
  return requested ? requested : "default";
}

std::shared_ptr<WrappedLibrary> WrappedLibrary::load(const std::string &spec,
    ANARIStatusCallback callback,
    const void *userPtr,
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
  if (name.empty() || name == "debug") {
    // Wrapping the layer in itself would recurse without end.
    error = "cannot wrap library '" + name + "'";
    return nullptr;
  }
  const std::string file = "libanari_library_" + name + ".so";
  void *dlHandle = anari::loadANARILibrary(folder + file);
  if (!dlHandle) {
    error = dlerror();
    const std::string own = layerDirectory();
    if (!own.empty() && own != folder)
      dlHandle = anari::loadANARILibrary(own + file);
    if (!dlHandle) {
      error += std::string("; ") + dlerror();
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
  std::shared_ptr<WrappedLibrary> out(new WrappedLibrary);
  out->m_name = name;
  out->m_dlHandle = dlHandle;
  out->m_library = library;
  return out;
}

WrappedLibrary::~WrappedLibrary()
{
  delete m_library;
  // NOTE: closing before the delete would unmap the destructor's code.
  anari::freeLibrary(m_dlHandle);
}

} // namespace prism::debug
