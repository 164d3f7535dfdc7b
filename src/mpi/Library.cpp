// The prism_mpi library: the entry point libanari looks up, and the prism
// device's extensions plus KHR_DATA_PARALLEL_MPI.
#include "DataParallelDevice.h"

#include "DeviceInfo.h"
#include "introspection/Introspection.h"

#include <string>
#include <vector>

namespace prism::mpi {
namespace {

const char **dataParallelExtensions()
{
  static std::vector<const char *> extensions = [] {
    std::vector<const char *> list;
    for (const char **name = kImplementedExtensions; *name; name++)
      list.push_back(*name);
    list.push_back("ANARI_KHR_DATA_PARALLEL_MPI");
    list.push_back(nullptr);
    return list;
  }();
  return extensions.data();
}

class Library : public anari::LibraryImpl
{
 public:
  Library(void *dlHandle, ANARIStatusCallback callback, const void *userPtr)
      : anari::LibraryImpl(dlHandle, callback, userPtr)
  {
    introspection::setImplementedExtensions(
        dataParallelExtensions(), kRendererSubtypes);
  }

  ANARIDevice newDevice(const char *subtype) override
  {
    const std::string s = subtype ? subtype : "default";
    if (s != "default" && s != "prism_mpi")
      return nullptr;
    return (ANARIDevice) new DataParallelDevice(this_library());
  }

  const char **getDeviceExtensions(const char *) override
  {
    return introspection::deviceExtensions();
  }
};

} // namespace
} // namespace prism::mpi

ANARI_DEFINE_LIBRARY_ENTRYPOINT(prism_mpi, handle, callback, userPtr)
{
  try {
    return (ANARILibrary) new prism::mpi::Library(handle, callback, userPtr);
  } catch (...) {
    return nullptr;
  }
}
