// The backend interface a device library implements: what ANARILibrary
// points to. Layout and virtual order are fixed by the ABI (docs/ABI.md).
#pragma once

#include "anari/anari.h"

#include <string>

#ifndef ANARI_BACKEND_INTERFACE
#ifdef ANARI_BACKEND_STATIC
#define ANARI_BACKEND_INTERFACE
#else
#define ANARI_BACKEND_INTERFACE __attribute__((visibility("default")))
#endif
#endif

namespace anari {

// Opens a shared library by file name; NULL on failure (see dlerror()).
ANARI_BACKEND_INTERFACE void *loadANARILibrary(const std::string &libName);
// Closes a handle returned by loadANARILibrary().
ANARI_BACKEND_INTERFACE void freeLibrary(void *lib);
// Looks up a symbol in an opened library; NULL when absent.
ANARI_BACKEND_INTERFACE void *getSymbolAddress(
    void *lib, const std::string &symbol);

struct ANARI_BACKEND_INTERFACE LibraryImpl
{
  LibraryImpl(
      void *lib, ANARIStatusCallback defaultStatusCB, const void *statusCBPtr);
  virtual ~LibraryImpl();

  // Creates a device of `subtype` ("default" picks the library's choice).
  virtual ANARIDevice newDevice(const char *subtype) = 0;
  // Creates a device from initial parameters; by default ignores them.
  virtual ANARIDevice newInitializedDevice(
      const char *subtype, ANARIParameterValue *parameters);
  // NULL-terminated extension names of one device subtype.
  virtual const char **getDeviceExtensions(const char *deviceSubtype) = 0;
  // NULL-terminated device subtypes; by default {"default", NULL}.
  virtual const char **getDeviceSubtypes();
  // Optional plug-in modules; no-ops by default.
  virtual void loadModule(const char *name);
  virtual void unloadModule(const char *name);

  // The status callback given to anariLoadLibrary (used by new devices).
  ANARIStatusCallback defaultStatusCB() const;
  // Its user pointer.
  const void *defaultStatusCBUserPtr() const;
  // `this` as the C handle.
  ANARILibrary this_library() const;
  // The dlopen handle this library was loaded from (closed after delete).
  void *libraryHandle() const;

 private:
  void *m_lib{nullptr};
  ANARIStatusCallback m_defaultStatusCB{nullptr};
  const void *m_defaultStatusCBUserPtr{nullptr};
};

} // namespace anari

// Declares a library's entry point, the C symbol the front-end looks up as
// anari_library_<name>_new_library.
#define ANARI_DEFINE_LIBRARY_ENTRYPOINT(libname, handle, scb, scbPtr) \
  extern "C" __attribute__((visibility("default")))                   \
  ANARILibrary anari_library_##libname##_new_library(                 \
      void *handle, ANARIStatusCallback scb, const void *scbPtr)
