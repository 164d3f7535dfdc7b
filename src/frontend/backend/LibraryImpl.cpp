// Base behaviour of a device library, shared by libanari (exported) and by
// device libraries (compiled in statically, so they need no libanari).
#include "anari/backend/LibraryImpl.h"

#include <dlfcn.h>

namespace anari {

void *loadANARILibrary(const std::string &libName)
{
  return dlopen(libName.c_str(), RTLD_LAZY | RTLD_LOCAL);
}

void freeLibrary(void *lib)
{
  if (lib)
    dlclose(lib);
}

void *getSymbolAddress(void *lib, const std::string &symbol)
{
  return lib ? dlsym(lib, symbol.c_str()) : nullptr;
}

LibraryImpl::LibraryImpl(
    void *lib, ANARIStatusCallback defaultStatusCB, const void *statusCBPtr)
    : m_lib(lib),
      m_defaultStatusCB(defaultStatusCB),
      m_defaultStatusCBUserPtr(statusCBPtr)
{}

LibraryImpl::~LibraryImpl() = default;

ANARIDevice LibraryImpl::newInitializedDevice(
    const char *subtype, ANARIParameterValue *)
{
  return newDevice(subtype);
}

const char **LibraryImpl::getDeviceSubtypes()
{
  static const char *subtypes[] = {"default", nullptr};
  return subtypes;
}

void LibraryImpl::loadModule(const char *) {}

void LibraryImpl::unloadModule(const char *) {}

ANARIStatusCallback LibraryImpl::defaultStatusCB() const
{
  return m_defaultStatusCB;
}

const void *LibraryImpl::defaultStatusCBUserPtr() const
{
  return m_defaultStatusCBUserPtr;
}

ANARILibrary LibraryImpl::this_library() const
{
  return (ANARILibrary)this;
}

void *LibraryImpl::libraryHandle() const
{
  return m_lib;
}

} // namespace anari
