// The debug library: the entry point libanari looks up
// (anari_library_debug_new_library), and the hook through which libanari's
// ANARI_DEBUG_LAYER wrapping names the library to wrap.
#include "DebugDevice.h"
#include "WrappedLibrary.h"

#include <mutex>
#include <string>

namespace prism::debug {
namespace {

bool isLayerParameter(const std::string &name)
{
  return name == "wrappedLibrary" || name == "wrappedDevice";
}

class Library : public anari::LibraryImpl
{
 public:
  Library(void *dlHandle, ANARIStatusCallback callback, const void *userPtr)
      : anari::LibraryImpl(dlHandle, callback, userPtr),
        m_wrappedSpec(defaultWrappedLibrary())
  {}

  void setWrappedLibrary(const char *spec)
  {
    std::lock_guard lock(m_mutex);
    m_wrappedSpec = spec;
    m_probe.reset();
  }

  ANARIDevice newDevice(const char *subtype) override
  {
    auto *device = new DebugDevice(
        this_library(), wrappedSpec(), defaultWrappedDevice(subtype));
    if (!device->failure().empty()) {
      report("anariNewDevice: " + device->failure());
      delete device;
      return nullptr;
    }
    return (ANARIDevice)device;
  }

  ANARIDevice newInitializedDevice(
      const char *subtype, ANARIParameterValue *parameters) override
  {
    // The layer's own parameters choose the library and its device before
    // the device exists; the others go to the new device as
    // anariSetParameter would.
    std::string spec = wrappedSpec();
    std::string s = defaultWrappedDevice(subtype);
    for (auto *p = parameters; p && p->name; ++p) {
      if (isLayerParameter(p->name) && p->type == ANARI_STRING && p->value)
        (std::string(p->name) == "wrappedLibrary" ? spec : s) =
            (const char *)p->value;
    }
    auto *device = new DebugDevice(this_library(), spec, s);
    if (!device->failure().empty()) {
      report("anariNewInitializedDevice: " + device->failure());
      delete device;
      return nullptr;
    }
    bool any = false;
    for (auto *p = parameters; p && p->name; ++p) {
      if (!isLayerParameter(p->name)) {
        device->setParameter((ANARIObject)device, p->name, p->type, p->value);
        any = true;
      }
    }
    if (any)
      device->commitParameters((ANARIObject)device);
    return (ANARIDevice)device;
  }

  const char **getDeviceExtensions(const char *deviceSubtype) override
  {
    auto *wrapped = probe();
    // Those of the device the layer would wrap for this subtype.
    return wrapped ? wrapped->library().getDeviceExtensions(
               defaultWrappedDevice(deviceSubtype).c_str())
                   : nullptr;
  }

  const char **getDeviceSubtypes() override
  {
    auto *wrapped = probe();
    return wrapped ? wrapped->library().getDeviceSubtypes()
                   : anari::LibraryImpl::getDeviceSubtypes();
  }

 private:
  std::string wrappedSpec()
  {
    std::lock_guard lock(m_mutex);
    return m_wrappedSpec;
  }

  // The wrapped library, loaded once for the library-level queries.
  WrappedLibrary *probe()
  {
    std::lock_guard lock(m_mutex);
    if (!m_probe) {
      std::string error;
      m_probe = WrappedLibrary::load(m_wrappedSpec,
          defaultStatusCB(),
          defaultStatusCBUserPtr(),
          "debug",
          error);
      if (!m_probe)
        report("cannot load the wrapped library '" + m_wrappedSpec
               + "': " + error);
    }
    return m_probe.get();
  }

  void report(const std::string &message) const
  {
    if (auto callback = defaultStatusCB()) {
      callback(defaultStatusCBUserPtr(),
          nullptr,
          nullptr,
          ANARI_LIBRARY,
          ANARI_SEVERITY_ERROR,
          ANARI_STATUS_INVALID_OPERATION,
          message.c_str());
    }
  }

  std::mutex m_mutex;
  std::string m_wrappedSpec;
  std::shared_ptr<WrappedLibrary> m_probe;
};

} // namespace
} // namespace prism::debug

ANARI_DEFINE_LIBRARY_ENTRYPOINT(debug, handle, callback, userPtr)
{
  try {
    return (ANARILibrary) new prism::debug::Library(handle, callback, userPtr);
  } catch (...) {
    return nullptr;
  }
}

// Called by libanari when ANARI_DEBUG_LAYER wraps the library the
// application asked for ("name" or "name,folder/").
extern "C" __attribute__((visibility("default"))) void
prism_debug_set_wrapped_library(ANARILibrary library, const char *spec)
{
  if (library && spec && *spec)
    ((prism::debug::Library *)library)->setWrappedLibrary(spec);
}

// Called by libanari when it loads the layer: how to tell a live device
// handle (a `wrappedDevice` the application hands over) from a released
// one. Another front-end has no such hook; the handle is then trusted.
extern "C" __attribute__((visibility("default"))) void
prism_debug_set_device_check(int (*isLiveDevice)(ANARIDevice))
{
  prism::debug::DebugDevice::setDeviceCheck(isLiveDevice);
}
