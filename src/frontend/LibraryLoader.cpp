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

// Whether ANARI_DEBUG_LAYER asks for every library to be wrapped in the
// debug layer ("debug" library), so an application needs no change.
bool debugLayerRequested()
{
  const char *value = std::getenv("ANARI_DEBUG_LAYER");
  return value && *value && std::string(value) != "0";
}

// Opens libanari_library_<libName>.so and runs its entry point; NULL (and
// a report) on failure.
anari::LibraryImpl *openLibrary(
    const std::string &libName, const std::string &prefix, StatusSink sink)
{
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
  return library;
}

int isLiveDevice(ANARIDevice device)
{
  return HandleRegistry::instance().hasDevice(device) ? 1 : 0;
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

  anari::LibraryImpl *library = nullptr;
  if (debugLayerRequested() && libName != "debug") {
    // The debug layer in place of the library, told which one to wrap.
    library = openLibrary("debug", "", sink);
    if (!library)
      return nullptr;
    using Hook = void (*)(ANARILibrary, const char *);
    auto hook = (Hook)anari::getSymbolAddress(
        library->libraryHandle(), "prism_debug_set_wrapped_library");
    if (hook) {
      hook((ANARILibrary)library, spec.c_str());
    } else {
      reportLoadError(sink,
          "anariLoadLibrary: ANARI_DEBUG_LAYER is set but library 'debug' "
          "cannot be told to wrap '"
              + libName + "'; it wraps its default");
    }
  } else {
    library = openLibrary(libName, prefix, sink);
    if (!library)
      return nullptr;
  }
  // The debug layer takes a device handle as a parameter value
  // (`wrappedDevice`): it asks the registry whether one is still live.
  using DeviceCheckHook = void (*)(int (*)(ANARIDevice));
  if (auto hook = (DeviceCheckHook)anari::getSymbolAddress(
          library->libraryHandle(), "prism_debug_set_device_check"))
    hook(&isLiveDevice);
  HandleRegistry::instance().addLibrary(library, sink);
  return library;
}

} // namespace prism::frontend
