#include "LibraryLoader.h"

#include <dlfcn.h>

#include <cstdlib>
#include <string>

extern "C" __attribute__((visibility("default"))) int _anari_anchor(void);

namespace prism::frontend {
namespace {

void reportLoadError(StatusSink sink, const std::string &message)
{
  if (sink.callback) {
    sink.callback(sink.userPtr,
        nullptr,
        nullptr,
        ANARI_LIBRARY,
        ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_OPERATION,
        message.c_str());
  }
}

// The folder holding this libanari, found through a symbol of our own.
std::string frontEndDirectory()
{
  Dl_info info{};
  if (!dladdr((void *)&_anari_anchor, &info) || !info.dli_fname)
    return {};
  std::string path = info.dli_fname;
  auto slash = path.rfind('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

std::string withTrailingSlash(std::string dir)
{
  if (!dir.empty() && dir.back() != '/')
    dir += '/';
  return dir;
}

} // namespace

anari::LibraryImpl *loadLibrary(const char *name, StatusSink sink)
{
  if (!name || !*name) {
    reportLoadError(sink, "anariLoadLibrary: library name is NULL or empty");
    return nullptr;
  }
  std::string spec = name;
  if (spec == "environment") {
    const char *fromEnv = std::getenv("ANARI_LIBRARY");
    if (!fromEnv || !*fromEnv) {
      reportLoadError(sink,
          "anariLoadLibrary: library 'environment' requested but "
          "ANARI_LIBRARY is not set");
      return nullptr;
    }
    spec = fromEnv;
  }

  std::string libName = spec;
  std::string prefix;
  if (auto comma = spec.find(','); comma != std::string::npos) {
    libName = spec.substr(0, comma);
    prefix = withTrailingSlash(spec.substr(comma + 1));
  }
  const std::string fileName = "libanari_library_" + libName + ".so";

  // First the loader's own search (or the given folder), then ours.
  std::string errors;
  void *dlHandle = anari::loadANARILibrary(prefix + fileName);
  if (!dlHandle) {
    errors = dlerror();
    const std::string ownDir = frontEndDirectory();
    if (!ownDir.empty() && ownDir != prefix) {
      dlHandle = anari::loadANARILibrary(ownDir + fileName);
      if (!dlHandle)
        errors += std::string("; ") + dlerror();
    }
  }
  if (!dlHandle) {
    reportLoadError(sink,
        "anariLoadLibrary: could not load library '" + libName
            + "': " + errors);
    return nullptr;
  }

  using EntryPoint =
      ANARILibrary (*)(void *, ANARIStatusCallback, const void *);
  const std::string symbol = "anari_library_" + libName + "_new_library";
  auto entry = (EntryPoint)anari::getSymbolAddress(dlHandle, symbol);
  if (!entry) {
    reportLoadError(sink,
        "anariLoadLibrary: library '" + libName + "' has no entry point '"
            + symbol + "'");
    anari::freeLibrary(dlHandle);
    return nullptr;
  }

  auto *library =
      (anari::LibraryImpl *)entry(dlHandle, sink.callback, sink.userPtr);
  if (!library) {
    reportLoadError(sink,
        "anariLoadLibrary: library '" + libName
            + "' failed to initialise (its entry point returned NULL)");
    anari::freeLibrary(dlHandle);
    return nullptr;
  }
  HandleRegistry::instance().addLibrary(library, sink);
  return library;
}

} // namespace prism::frontend
