// The prism library: the entry point libanari looks up, and device creation.
#include "Device.h"
#include "DeviceInfo.h"
#include "introspection/Introspection.h"

#include <string>

namespace prism {
namespace {

class Library : public anari::LibraryImpl
{
 public:
  Library(void *dlHandle, ANARIStatusCallback callback, const void *userPtr)
      : anari::LibraryImpl(dlHandle, callback, userPtr)
  {
    introspection::setImplementedExtensions(
        kImplementedExtensions, kRendererSubtypes);
  }

  ANARIDevice newDevice(const char *subtype) override
  {
    const std::string s = subtype ? subtype : "default";
    if (s != "default" && s != "prism")
      return nullptr;
    return (ANARIDevice) new Device(this_library());
  }

  const char **getDeviceExtensions(const char *) override
  {
    return introspection::deviceExtensions();
  }
};

} // namespace
} // namespace prism

ANARI_DEFINE_LIBRARY_ENTRYPOINT(prism, handle, callback, userPtr)
{
  try {
    return (ANARILibrary) new prism::Library(handle, callback, userPtr);
  } catch (...) {
    return nullptr;
  }
}
