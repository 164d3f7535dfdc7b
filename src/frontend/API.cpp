// The C entry points of libanari: check the library/device handle, then make
// one virtual call into the device library. Nothing throws past this file.
#include "DefaultStatusCallback.h"
#include "HandleRegistry.h"
#include "LibraryLoader.h"

#include <exception>
#include <string>

using anari::DeviceImpl;
using anari::LibraryImpl;
using prism::frontend::HandleRegistry;
using prism::frontend::StatusSink;

#define ANARI_EXPORT extern "C" __attribute__((visibility("default")))

namespace {

void report(StatusSink sink,
    ANARIDevice device,
    ANARIStatusSeverity severity,
    ANARIStatusCode code,
    const std::string &message)
{
  if (sink.callback) {
    sink.callback(sink.userPtr,
        device,
        (ANARIObject)device,
        device ? ANARI_DEVICE : ANARI_LIBRARY,
        severity,
        code,
        message.c_str());
  }
}

void reportBadDevice(ANARIDevice device, const char *function)
{
  report(HandleRegistry::instance().fallbackSink(),
      nullptr,
      ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      std::string(function)
          + (device ? ": device handle is not a live device (released or "
                      "never created by anariNewDevice)"
                    : ": device handle is NULL"));
}

void reportBadLibrary(ANARILibrary library, const char *function)
{
  report(HandleRegistry::instance().fallbackSink(),
      nullptr,
      ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      std::string(function)
          + (library ? ": library handle is not a loaded library"
                     : ": library handle is NULL"));
}

void reportException(ANARIDevice device, const char *function, const char *what)
{
  auto sink = device ? HandleRegistry::instance().sinkOf(device)
                     : HandleRegistry::instance().fallbackSink();
  report(sink,
      device,
      ANARI_SEVERITY_ERROR,
      ANARI_STATUS_UNKNOWN_ERROR,
      std::string(function) + ": the device threw an exception: " + what);
}

// Runs `call` on the device behind `handle` if it is live; otherwise
// reports and returns `neutral`.
template <typename R, typename F>
R onDevice(ANARIDevice handle, const char *function, R neutral, F &&call)
{
  if (!handle || !HandleRegistry::instance().hasDevice(handle)) {
    reportBadDevice(handle, function);
    return neutral;
  }
  try {
    return call(*(DeviceImpl *)handle);
  } catch (const std::exception &e) {
    reportException(handle, function, e.what());
  } catch (...) {
    reportException(handle, function, "(not a std::exception)");
  }
  return neutral;
}

template <typename F>
void onDevice(ANARIDevice handle, const char *function, F &&call)
{
  onDevice(handle, function, 0, [&](DeviceImpl &device) {
    call(device);
    return 0;
  });
}

template <typename R, typename F>
R onLibrary(ANARILibrary handle, const char *function, R neutral, F &&call)
{
  if (!handle || !HandleRegistry::instance().hasLibrary(handle)) {
    reportBadLibrary(handle, function);
    return neutral;
  }
  try {
    return call(*(LibraryImpl *)handle);
  } catch (const std::exception &e) {
    reportException(nullptr, function, e.what());
  } catch (...) {
    reportException(nullptr, function, "(not a std::exception)");
  }
  return neutral;
}

// Strings the API requires (parameter, property and channel names).
bool requireString(ANARIDevice device,
    const char *function,
    const char *value,
    const char *what)
{
  if (value)
    return true;
  report(HandleRegistry::instance().sinkOf(device),
      device,
      ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      std::string(function) + ": " + what + " is NULL");
  return false;
}

ANARIDevice registerDevice(ANARIDevice device,
    LibraryImpl &library,
    const char *function,
    const char *subtype)
{
  if (device) {
    HandleRegistry::instance().addDevice((DeviceImpl *)device, &library);
  } else {
    report(HandleRegistry::instance().fallbackSink(),
        nullptr,
        ANARI_SEVERITY_ERROR,
        ANARI_STATUS_UNSUPPORTED_DEVICE,
        std::string(function) + ": the library created no device of subtype '"
            + subtype + "'");
  }
  return device;
}

} // namespace

ANARI_EXPORT int _anari_anchor(void)
{
  return 1;
}

// Libraries ////////////////////////////////////////////////////////////////

ANARI_EXPORT ANARILibrary anariLoadLibrary(
    const char *name, ANARIStatusCallback statusCallback, const void *userData)
{
  StatusSink sink{statusCallback, userData};
  if (!sink.callback)
    sink = {prism::frontend::defaultStatusCallback, nullptr};
  try {
    return (ANARILibrary)prism::frontend::loadLibrary(name, sink);
  } catch (...) {
    return nullptr;
  }
}

ANARI_EXPORT void anariUnloadLibrary(ANARILibrary module)
{
  onLibrary(module, "anariUnloadLibrary", 0, [&](LibraryImpl &library) {
    void *dlHandle = HandleRegistry::instance().removeLibrary(&library);
    delete &library;
    // NOTE: closing before the delete would unmap the destructor's code.
    anari::freeLibrary(dlHandle);
    return 0;
  });
}

ANARI_EXPORT void anariLoadModule(ANARILibrary library, const char *name)
{
  onLibrary(library, "anariLoadModule", 0, [&](LibraryImpl &l) {
    if (name)
      l.loadModule(name);
    return 0;
  });
}

ANARI_EXPORT void anariUnloadModule(ANARILibrary library, const char *name)
{
  onLibrary(library, "anariUnloadModule", 0, [&](LibraryImpl &l) {
    if (name)
      l.unloadModule(name);
    return 0;
  });
}

ANARI_EXPORT ANARIDevice anariNewDevice(ANARILibrary library, const char *type)
{
  return onLibrary(
      library, "anariNewDevice", ANARIDevice(nullptr), [&](LibraryImpl &l) {
        const char *subtype = type ? type : "default";
        return registerDevice(
            l.newDevice(subtype), l, "anariNewDevice", subtype);
      });
}

ANARI_EXPORT ANARIDevice anariNewInitializedDevice(
    ANARILibrary library, const char *type, ANARIParameterValue *initializers)
{
  return onLibrary(library,
      "anariNewInitializedDevice",
      ANARIDevice(nullptr),
      [&](LibraryImpl &l) {
        const char *subtype = type ? type : "default";
        return registerDevice(l.newInitializedDevice(subtype, initializers),
            l,
            "anariNewInitializedDevice",
            subtype);
      });
}

ANARI_EXPORT const char **anariGetDeviceSubtypes(ANARILibrary library)
{
  return onLibrary(library,
      "anariGetDeviceSubtypes",
      (const char **)nullptr,
      [&](LibraryImpl &l) { return l.getDeviceSubtypes(); });
}

ANARI_EXPORT const char **anariGetDeviceExtensions(
    ANARILibrary library, const char *deviceSubtype)
{
  return onLibrary(library,
      "anariGetDeviceExtensions",
      (const char **)nullptr,
      [&](LibraryImpl &l) {
        return l.getDeviceExtensions(deviceSubtype ? deviceSubtype : "default");
      });
}

// Object creation ///////////////////////////////////////////////////////////

ANARI_EXPORT ANARIArray1D anariNewArray1D(ANARIDevice device,
    const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType dataType,
    uint64_t numElements1)
{
  return onDevice(
      device, "anariNewArray1D", ANARIArray1D(nullptr), [&](DeviceImpl &d) {
        return d.newArray1D(
            appMemory, deleter, userData, dataType, numElements1);
      });
}

ANARI_EXPORT ANARIArray2D anariNewArray2D(ANARIDevice device,
    const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType dataType,
    uint64_t numElements1,
    uint64_t numElements2)
{
  return onDevice(
      device, "anariNewArray2D", ANARIArray2D(nullptr), [&](DeviceImpl &d) {
        return d.newArray2D(
            appMemory, deleter, userData, dataType, numElements1, numElements2);
      });
}

ANARI_EXPORT ANARIArray3D anariNewArray3D(ANARIDevice device,
    const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType dataType,
    uint64_t numElements1,
    uint64_t numElements2,
    uint64_t numElements3)
{
  return onDevice(
      device, "anariNewArray3D", ANARIArray3D(nullptr), [&](DeviceImpl &d) {
        return d.newArray3D(appMemory,
            deleter,
            userData,
            dataType,
            numElements1,
            numElements2,
            numElements3);
      });
}

// One creation function per subtyped object category.
#define PRISM_NEW_SUBTYPED(Function, Handle, Method)                         \
  ANARI_EXPORT Handle Function(ANARIDevice device, const char *type)         \
  {                                                                          \
    return onDevice(device, #Function, Handle(nullptr), [&](DeviceImpl &d) { \
      return d.Method(type);                                                 \
    });                                                                      \
  }

PRISM_NEW_SUBTYPED(anariNewLight, ANARILight, newLight)
PRISM_NEW_SUBTYPED(anariNewCamera, ANARICamera, newCamera)
PRISM_NEW_SUBTYPED(anariNewGeometry, ANARIGeometry, newGeometry)
PRISM_NEW_SUBTYPED(anariNewSpatialField, ANARISpatialField, newSpatialField)
PRISM_NEW_SUBTYPED(anariNewVolume, ANARIVolume, newVolume)
PRISM_NEW_SUBTYPED(anariNewMaterial, ANARIMaterial, newMaterial)
PRISM_NEW_SUBTYPED(anariNewSampler, ANARISampler, newSampler)
PRISM_NEW_SUBTYPED(anariNewInstance, ANARIInstance, newInstance)
PRISM_NEW_SUBTYPED(anariNewRenderer, ANARIRenderer, newRenderer)
#undef PRISM_NEW_SUBTYPED

#define PRISM_NEW_PLAIN(Function, Handle, Method)                            \
  ANARI_EXPORT Handle Function(ANARIDevice device)                           \
  {                                                                          \
    return onDevice(device, #Function, Handle(nullptr), [&](DeviceImpl &d) { \
      return d.Method();                                                     \
    });                                                                      \
  }

PRISM_NEW_PLAIN(anariNewSurface, ANARISurface, newSurface)
PRISM_NEW_PLAIN(anariNewGroup, ANARIGroup, newGroup)
PRISM_NEW_PLAIN(anariNewWorld, ANARIWorld, newWorld)
PRISM_NEW_PLAIN(anariNewFrame, ANARIFrame, newFrame)
#undef PRISM_NEW_PLAIN

ANARI_EXPORT ANARIObject anariNewObject(
    ANARIDevice device, const char *objectType, const char *type)
{
  return onDevice(
      device, "anariNewObject", ANARIObject(nullptr), [&](DeviceImpl &d) {
        return requireString(device, "anariNewObject", objectType, "objectType")
                   ? d.newObject(objectType, type)
                   : nullptr;
      });
}

// Arrays ////////////////////////////////////////////////////////////////////

ANARI_EXPORT void *anariMapArray(ANARIDevice device, ANARIArray array)
{
  return onDevice(device, "anariMapArray", (void *)nullptr, [&](DeviceImpl &d) {
    return d.mapArray(array);
  });
}

ANARI_EXPORT void anariUnmapArray(ANARIDevice device, ANARIArray array)
{
  onDevice(
      device, "anariUnmapArray", [&](DeviceImpl &d) { d.unmapArray(array); });
}

// Parameters ////////////////////////////////////////////////////////////////

ANARI_EXPORT void anariSetParameter(ANARIDevice device,
    ANARIObject object,
    const char *name,
    ANARIDataType dataType,
    const void *mem)
{
  onDevice(device, "anariSetParameter", [&](DeviceImpl &d) {
    if (requireString(device, "anariSetParameter", name, "parameter name"))
      d.setParameter(object, name, dataType, mem);
  });
}

ANARI_EXPORT void anariUnsetParameter(
    ANARIDevice device, ANARIObject object, const char *name)
{
  onDevice(device, "anariUnsetParameter", [&](DeviceImpl &d) {
    if (requireString(device, "anariUnsetParameter", name, "parameter name"))
      d.unsetParameter(object, name);
  });
}

ANARI_EXPORT void anariUnsetAllParameters(
    ANARIDevice device, ANARIObject object)
{
  onDevice(device, "anariUnsetAllParameters", [&](DeviceImpl &d) {
    d.unsetAllParameters(object);
  });
}

ANARI_EXPORT void *anariMapParameterArray1D(ANARIDevice device,
    ANARIObject object,
    const char *name,
    ANARIDataType dataType,
    uint64_t numElements1,
    uint64_t *elementStride)
{
  return onDevice(
      device, "anariMapParameterArray1D", (void *)nullptr, [&](DeviceImpl &d) {
        return requireString(
                   device, "anariMapParameterArray1D", name, "parameter name")
                   ? d.mapParameterArray1D(
                       object, name, dataType, numElements1, elementStride)
                   : nullptr;
      });
}

ANARI_EXPORT void *anariMapParameterArray2D(ANARIDevice device,
    ANARIObject object,
    const char *name,
    ANARIDataType dataType,
    uint64_t numElements1,
    uint64_t numElements2,
    uint64_t *elementStride)
{
  return onDevice(
      device, "anariMapParameterArray2D", (void *)nullptr, [&](DeviceImpl &d) {
        return requireString(
                   device, "anariMapParameterArray2D", name, "parameter name")
                   ? d.mapParameterArray2D(object,
                       name,
                       dataType,
                       numElements1,
                       numElements2,
                       elementStride)
                   : nullptr;
      });
}

ANARI_EXPORT void *anariMapParameterArray3D(ANARIDevice device,
    ANARIObject object,
    const char *name,
    ANARIDataType dataType,
    uint64_t numElements1,
    uint64_t numElements2,
    uint64_t numElements3,
    uint64_t *elementStride)
{
  return onDevice(
      device, "anariMapParameterArray3D", (void *)nullptr, [&](DeviceImpl &d) {
        return requireString(
                   device, "anariMapParameterArray3D", name, "parameter name")
                   ? d.mapParameterArray3D(object,
                       name,
                       dataType,
                       numElements1,
                       numElements2,
                       numElements3,
                       elementStride)
                   : nullptr;
      });
}

ANARI_EXPORT void anariUnmapParameterArray(
    ANARIDevice device, ANARIObject object, const char *name)
{
  onDevice(device, "anariUnmapParameterArray", [&](DeviceImpl &d) {
    if (requireString(
            device, "anariUnmapParameterArray", name, "parameter name"))
      d.unmapParameterArray(object, name);
  });
}

ANARI_EXPORT void anariCommitParameters(ANARIDevice device, ANARIObject object)
{
  onDevice(device, "anariCommitParameters", [&](DeviceImpl &d) {
    d.commitParameters(object);
  });
}

// Lifetime //////////////////////////////////////////////////////////////////

ANARI_EXPORT void anariRelease(ANARIDevice device, ANARIObject object)
{
  onDevice(device, "anariRelease", [&](DeviceImpl &d) {
    d.release(object);
    // Releasing the device itself may have destroyed it; mirror its count.
    if (object == (ANARIObject)device) {
      void *dlHandle =
          HandleRegistry::instance().releaseDevice((DeviceImpl *)device);
      anari::freeLibrary(dlHandle);
    }
  });
}

ANARI_EXPORT void anariRetain(ANARIDevice device, ANARIObject object)
{
  onDevice(device, "anariRetain", [&](DeviceImpl &d) {
    d.retain(object);
    if (object == (ANARIObject)device)
      HandleRegistry::instance().retainDevice((DeviceImpl *)device);
  });
}

// Introspection and properties //////////////////////////////////////////////

ANARI_EXPORT const char **anariGetObjectSubtypes(
    ANARIDevice device, ANARIDataType objectType)
{
  return onDevice(device,
      "anariGetObjectSubtypes",
      (const char **)nullptr,
      [&](DeviceImpl &d) { return d.getObjectSubtypes(objectType); });
}

ANARI_EXPORT const void *anariGetObjectInfo(ANARIDevice device,
    ANARIDataType objectType,
    const char *objectSubtype,
    const char *infoName,
    ANARIDataType infoType)
{
  return onDevice(
      device, "anariGetObjectInfo", (const void *)nullptr, [&](DeviceImpl &d) {
        return requireString(device, "anariGetObjectInfo", infoName, "infoName")
                   ? d.getObjectInfo(
                       objectType, objectSubtype, infoName, infoType)
                   : nullptr;
      });
}

ANARI_EXPORT const void *anariGetParameterInfo(ANARIDevice device,
    ANARIDataType objectType,
    const char *objectSubtype,
    const char *parameterName,
    ANARIDataType parameterType,
    const char *infoName,
    ANARIDataType infoType)
{
  return onDevice(device,
      "anariGetParameterInfo",
      (const void *)nullptr,
      [&](DeviceImpl &d) {
        return requireString(device,
                   "anariGetParameterInfo",
                   parameterName,
                   "parameterName")
                       && requireString(device,
                           "anariGetParameterInfo",
                           infoName,
                           "infoName")
                   ? d.getParameterInfo(objectType,
                       objectSubtype,
                       parameterName,
                       parameterType,
                       infoName,
                       infoType)
                   : nullptr;
      });
}

ANARI_EXPORT int anariGetProperty(ANARIDevice device,
    ANARIObject object,
    const char *name,
    ANARIDataType type,
    void *mem,
    uint64_t size,
    ANARIWaitMask mask)
{
  return onDevice(device, "anariGetProperty", 0, [&](DeviceImpl &d) {
    return requireString(device, "anariGetProperty", name, "property name")
               ? d.getProperty(object, name, type, mem, size, mask)
               : 0;
  });
}

// Frames ////////////////////////////////////////////////////////////////////

ANARI_EXPORT const void *anariMapFrame(ANARIDevice device,
    ANARIFrame frame,
    const char *channel,
    uint32_t *width,
    uint32_t *height,
    ANARIDataType *pixelType)
{
  return onDevice(
      device, "anariMapFrame", (const void *)nullptr, [&](DeviceImpl &d) {
        if (!requireString(device, "anariMapFrame", channel, "channel name"))
          return (const void *)nullptr;
        // Devices write all three outputs; give them somewhere to go.
        uint32_t unusedWidth = 0, unusedHeight = 0;
        ANARIDataType unusedType = ANARI_UNKNOWN;
        return d.frameBufferMap(frame,
            channel,
            width ? width : &unusedWidth,
            height ? height : &unusedHeight,
            pixelType ? pixelType : &unusedType);
      });
}

ANARI_EXPORT void anariUnmapFrame(
    ANARIDevice device, ANARIFrame frame, const char *channel)
{
  onDevice(device, "anariUnmapFrame", [&](DeviceImpl &d) {
    if (requireString(device, "anariUnmapFrame", channel, "channel name"))
      d.frameBufferUnmap(frame, channel);
  });
}

ANARI_EXPORT void anariRenderFrame(ANARIDevice device, ANARIFrame frame)
{
  onDevice(
      device, "anariRenderFrame", [&](DeviceImpl &d) { d.renderFrame(frame); });
}

ANARI_EXPORT int anariFrameReady(
    ANARIDevice device, ANARIFrame frame, ANARIWaitMask mask)
{
  return onDevice(device, "anariFrameReady", 0, [&](DeviceImpl &d) {
    return d.frameReady(frame, mask);
  });
}

ANARI_EXPORT void anariDiscardFrame(ANARIDevice device, ANARIFrame frame)
{
  onDevice(device, "anariDiscardFrame", [&](DeviceImpl &d) {
    d.discardFrame(frame);
  });
}

ANARI_EXPORT ANARIFunctionPointer anariDeviceGetProcAddress(
    ANARIDevice device, const char *name)
{
  return onDevice(device,
      "anariDeviceGetProcAddress",
      ANARIFunctionPointer(nullptr),
      [&](DeviceImpl &d) {
        return requireString(device, "anariDeviceGetProcAddress", name, "name")
                   ? d.getProcAddress(name)
                   : nullptr;
      });
}
