// The C++ convenience layer over the ANARI C API: type-inferring wrappers
// source-compatible with the Khronos ANARI-SDK 0.17 anari_cpp.hpp.
#pragma once

#include "anari.h"
#include "anari_cpp/Traits.h"
#include "frontend/type_utility.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>

namespace anari {

// Types ////////////////////////////////////////////////////////////////////

using Library = ANARILibrary;
using Object = ANARIObject;
using Device = ANARIDevice;
using Camera = ANARICamera;
using Array = ANARIArray;
using Array1D = ANARIArray1D;
using Array2D = ANARIArray2D;
using Array3D = ANARIArray3D;
using Frame = ANARIFrame;
using Future = ANARIFuture;
using Geometry = ANARIGeometry;
using Group = ANARIGroup;
using Instance = ANARIInstance;
using Light = ANARILight;
using Material = ANARIMaterial;
using Renderer = ANARIRenderer;
using Surface = ANARISurface;
using Sampler = ANARISampler;
using SpatialField = ANARISpatialField;
using Volume = ANARIVolume;
using World = ANARIWorld;

using StatusCallback = ANARIStatusCallback;
using Parameter = ANARIParameter;
using FrameCompletionCallback = ANARIFrameCompletionCallback;
using MemoryDeleter = ANARIMemoryDeleter;

using StatusSeverity = ANARIStatusSeverity;
using StatusCode = ANARIStatusCode;
using WaitMask = ANARIWaitMask;
using DataType = ANARIDataType;

namespace detail {

template <typename T>
constexpr DataType getType()
{
  return ANARITypeFor<T>::value;
}

// Defers a static_assert(false) to instantiation.
template <typename T>
constexpr bool alwaysFalse = false;

template <typename T>
constexpr void requireKnownType()
{
  static_assert(ANARITypeFor<T>::value != int(ANARI_UNKNOWN),
      "no ANARIDataType is known for this C++ type: add an "
      "ANARI_TYPEFOR_SPECIALIZATION for it");
}

// Copies `count` elements of `size` bytes between buffers with their own
// strides (0 meaning packed), in one memcpy when both are packed.
inline void copyElements(void *dst,
    uint64_t dstStride,
    const void *src,
    uint64_t srcStride,
    uint64_t size,
    uint64_t count)
{
  if (!dst || !src || size == 0)
    return;
  dstStride = dstStride ? dstStride : size;
  srcStride = srcStride ? srcStride : size;
  if (dstStride == size && srcStride == size) {
    std::memcpy(dst, src, size * count);
    return;
  }
  for (uint64_t i = 0; i < count; ++i) {
    std::memcpy(static_cast<char *>(dst) + i * dstStride,
        static_cast<const char *>(src) + i * srcStride,
        size);
  }
}

// Fills a freshly created managed array with `count` elements of type T.
template <typename T, typename A>
A fillManagedArray(Device d, A array, const T *items, uint64_t count)
{
  if (!array || !items || count == 0)
    return array;
  const uint64_t elementSize = sizeOf(getType<T>());
  // Element sizes differ only for ill-mapped user types; copy what fits.
  detail::copyElements(anariMapArray(d, array),
      elementSize,
      items,
      sizeof(T),
      std::min<uint64_t>(elementSize, sizeof(T)),
      count);
  anariUnmapArray(d, array);
  return array;
}

} // namespace detail

// Libraries and devices ////////////////////////////////////////////////////

inline Library loadLibrary(const char *name,
    StatusCallback defaultStatus = nullptr,
    const void *defaultStatusPtr = nullptr)
{
  return anariLoadLibrary(name, defaultStatus, defaultStatusPtr);
}

inline void unloadLibrary(Library l)
{
  anariUnloadLibrary(l);
}

inline void loadModule(Library l, const char *name)
{
  anariLoadModule(l, name);
}

inline void unloadModule(Library l, const char *name)
{
  anariUnloadModule(l, name);
}

inline Device newDevice(Library l, const char *name = "default")
{
  return anariNewDevice(l, name);
}

// Object creation //////////////////////////////////////////////////////////

inline Object newObject(Device d, const char *type, const char *subtype)
{
  return anariNewObject(d, type, subtype);
}

// Surface, Group, World and Frame have no subtype.
template <typename T>
T newObject(Device d)
{
  if constexpr (std::is_same_v<T, Surface>)
    return anariNewSurface(d);
  else if constexpr (std::is_same_v<T, Group>)
    return anariNewGroup(d);
  else if constexpr (std::is_same_v<T, World>)
    return anariNewWorld(d);
  else if constexpr (std::is_same_v<T, Frame>)
    return anariNewFrame(d);
  else
    static_assert(detail::alwaysFalse<T>,
        "anari::newObject<T>(device) is for Surface, Group, World and Frame; "
        "other object types need a subtype");
}

template <typename T>
T newObject(Device d, const char *subtype)
{
  if constexpr (std::is_same_v<T, Camera>)
    return anariNewCamera(d, subtype);
  else if constexpr (std::is_same_v<T, Geometry>)
    return anariNewGeometry(d, subtype);
  else if constexpr (std::is_same_v<T, Instance>)
    return anariNewInstance(d, subtype);
  else if constexpr (std::is_same_v<T, Light>)
    return anariNewLight(d, subtype);
  else if constexpr (std::is_same_v<T, Material>)
    return anariNewMaterial(d, subtype);
  else if constexpr (std::is_same_v<T, Renderer>)
    return anariNewRenderer(d, subtype);
  else if constexpr (std::is_same_v<T, Sampler>)
    return anariNewSampler(d, subtype);
  else if constexpr (std::is_same_v<T, SpatialField>)
    return anariNewSpatialField(d, subtype);
  else if constexpr (std::is_same_v<T, Volume>)
    return anariNewVolume(d, subtype);
  else
    static_assert(detail::alwaysFalse<T>,
        "anari::newObject<T>(device, subtype) is for Camera, Geometry, "
        "Instance, Light, Material, Renderer, Sampler, SpatialField and "
        "Volume");
}

// Arrays ///////////////////////////////////////////////////////////////////

// The forms taking a deleter share `appMemory` with the device exactly as
// the C call does; the typed forms without one copy the data into a managed
// array, so the caller's buffer may go away right after the call.

inline Array1D newArray1D(Device d,
    const void *appMemory,
    MemoryDeleter deleter,
    const void *userPtr,
    DataType elementType,
    uint64_t numItems1)
{
  return anariNewArray1D(
      d, appMemory, deleter, userPtr, elementType, numItems1);
}

template <typename T>
Array1D newArray1D(Device d,
    const T *appMemory,
    MemoryDeleter deleter,
    const void *userPtr,
    uint64_t numItems1)
{
  detail::requireKnownType<T>();
  return anariNewArray1D(
      d, appMemory, deleter, userPtr, detail::getType<T>(), numItems1);
}

template <typename T>
Array1D newArray1D(Device d, const T *appMemory, uint64_t numItems1 = 1)
{
  detail::requireKnownType<T>();
  return detail::fillManagedArray(d,
      anariNewArray1D(
          d, nullptr, nullptr, nullptr, detail::getType<T>(), numItems1),
      appMemory,
      numItems1);
}

inline Array1D newArray1D(Device d, DataType type, uint64_t numItems1)
{
  return anariNewArray1D(d, nullptr, nullptr, nullptr, type, numItems1);
}

inline Array2D newArray2D(Device d,
    const void *appMemory,
    MemoryDeleter deleter,
    const void *userPtr,
    DataType elementType,
    uint64_t numItems1,
    uint64_t numItems2)
{
  return anariNewArray2D(
      d, appMemory, deleter, userPtr, elementType, numItems1, numItems2);
}

template <typename T>
Array2D newArray2D(Device d,
    const T *appMemory,
    MemoryDeleter deleter,
    const void *userPtr,
    uint64_t numItems1,
    uint64_t numItems2)
{
  detail::requireKnownType<T>();
  return anariNewArray2D(d,
      appMemory,
      deleter,
      userPtr,
      detail::getType<T>(),
      numItems1,
      numItems2);
}

template <typename T>
Array2D newArray2D(
    Device d, const T *appMemory, uint64_t numItems1, uint64_t numItems2)
{
  detail::requireKnownType<T>();
  return detail::fillManagedArray(d,
      anariNewArray2D(d,
          nullptr,
          nullptr,
          nullptr,
          detail::getType<T>(),
          numItems1,
          numItems2),
      appMemory,
      numItems1 * numItems2);
}

inline Array2D newArray2D(
    Device d, DataType type, uint64_t numItems1, uint64_t numItems2)
{
  return anariNewArray2D(
      d, nullptr, nullptr, nullptr, type, numItems1, numItems2);
}

inline Array3D newArray3D(Device d,
    const void *appMemory,
    MemoryDeleter deleter,
    const void *userPtr,
    DataType elementType,
    uint64_t numItems1,
    uint64_t numItems2,
    uint64_t numItems3)
{
  return anariNewArray3D(d,
      appMemory,
      deleter,
      userPtr,
      elementType,
      numItems1,
      numItems2,
      numItems3);
}

template <typename T>
Array3D newArray3D(Device d,
    const T *appMemory,
    MemoryDeleter deleter,
    const void *userPtr,
    uint64_t numItems1,
    uint64_t numItems2,
    uint64_t numItems3)
{
  detail::requireKnownType<T>();
  return anariNewArray3D(d,
      appMemory,
      deleter,
      userPtr,
      detail::getType<T>(),
      numItems1,
      numItems2,
      numItems3);
}

template <typename T>
Array3D newArray3D(Device d,
    const T *appMemory,
    uint64_t numItems1,
    uint64_t numItems2,
    uint64_t numItems3)
{
  detail::requireKnownType<T>();
  return detail::fillManagedArray(d,
      anariNewArray3D(d,
          nullptr,
          nullptr,
          nullptr,
          detail::getType<T>(),
          numItems1,
          numItems2,
          numItems3),
      appMemory,
      numItems1 * numItems2 * numItems3);
}

inline Array3D newArray3D(Device d,
    DataType type,
    uint64_t numItems1,
    uint64_t numItems2,
    uint64_t numItems3)
{
  return anariNewArray3D(
      d, nullptr, nullptr, nullptr, type, numItems1, numItems2, numItems3);
}

template <typename T>
T *map(Device d, Array a)
{
  return static_cast<T *>(anariMapArray(d, a));
}

inline void unmap(Device d, Array a)
{
  anariUnmapArray(d, a);
}

// Array parameters written straight into device memory /////////////////////

// `stride` is the distance in bytes between the caller's elements.
inline void setParameterArray1DStrided(Device d,
    Object o,
    const char *name,
    DataType type,
    const void *v,
    uint64_t numElements1,
    uint64_t stride)
{
  uint64_t deviceStride = 0;
  void *mem =
      anariMapParameterArray1D(d, o, name, type, numElements1, &deviceStride);
  if (!mem)
    return;
  detail::copyElements(
      mem, deviceStride, v, stride, sizeOf(type), numElements1);
  anariUnmapParameterArray(d, o, name);
}

inline void setParameterArray1D(Device d,
    Object o,
    const char *name,
    DataType type,
    const void *v,
    uint64_t numElements1)
{
  setParameterArray1DStrided(d, o, name, type, v, numElements1, sizeOf(type));
}

template <typename T>
void setParameterArray1D(
    Device d, Object o, const char *name, const T *v, uint64_t numElements1)
{
  detail::requireKnownType<T>();
  setParameterArray1DStrided(
      d, o, name, detail::getType<T>(), v, numElements1, sizeof(T));
}

inline void setParameterArray2D(Device d,
    Object o,
    const char *name,
    DataType type,
    const void *v,
    uint64_t numElements1,
    uint64_t numElements2)
{
  uint64_t deviceStride = 0;
  void *mem = anariMapParameterArray2D(
      d, o, name, type, numElements1, numElements2, &deviceStride);
  if (!mem)
    return;
  detail::copyElements(mem,
      deviceStride,
      v,
      sizeOf(type),
      sizeOf(type),
      numElements1 * numElements2);
  anariUnmapParameterArray(d, o, name);
}

template <typename T>
void setParameterArray2D(Device d,
    Object o,
    const char *name,
    const T *v,
    uint64_t numElements1,
    uint64_t numElements2)
{
  detail::requireKnownType<T>();
  setParameterArray2D(
      d, o, name, detail::getType<T>(), v, numElements1, numElements2);
}

inline void setParameterArray3D(Device d,
    Object o,
    const char *name,
    DataType type,
    const void *v,
    uint64_t numElements1,
    uint64_t numElements2,
    uint64_t numElements3)
{
  uint64_t deviceStride = 0;
  void *mem = anariMapParameterArray3D(d,
      o,
      name,
      type,
      numElements1,
      numElements2,
      numElements3,
      &deviceStride);
  if (!mem)
    return;
  detail::copyElements(mem,
      deviceStride,
      v,
      sizeOf(type),
      sizeOf(type),
      numElements1 * numElements2 * numElements3);
  anariUnmapParameterArray(d, o, name);
}

template <typename T>
void setParameterArray3D(Device d,
    Object o,
    const char *name,
    const T *v,
    uint64_t numElements1,
    uint64_t numElements2,
    uint64_t numElements3)
{
  detail::requireKnownType<T>();
  setParameterArray3D(d,
      o,
      name,
      detail::getType<T>(),
      v,
      numElements1,
      numElements2,
      numElements3);
}

// Parameters ///////////////////////////////////////////////////////////////

// Strings and void pointers are passed as the pointer itself, everything
// else (handles and callbacks included) by the address of the value.
template <typename T>
void setParameter(Device d, Object o, const char *name, T &&v)
{
  using Value = std::remove_reference_t<T>;
  if constexpr (std::is_convertible_v<Value &, const char *>) {
    anariSetParameter(d, o, name, ANARI_STRING, static_cast<const char *>(v));
  } else if constexpr (std::is_function_v<Value>) {
    Value *function = &v;
    detail::requireKnownType<Value *>();
    anariSetParameter(d, o, name, detail::getType<Value *>(), &function);
  } else if constexpr (detail::getType<Value>() == ANARI_VOID_POINTER) {
    anariSetParameter(d, o, name, ANARI_VOID_POINTER, v);
  } else {
    detail::requireKnownType<Value>();
    anariSetParameter(d, o, name, detail::getType<Value>(), &v);
  }
}

inline void setParameter(Device d, Object o, const char *name, std::string v)
{
  anariSetParameter(d, o, name, ANARI_STRING, v.c_str());
}

// ANARI_BOOL values travel as 32 bits, as the SDK sends them.
inline void setParameter(Device d, Object o, const char *name, bool v)
{
  const uint32_t value = v ? 1 : 0;
  anariSetParameter(d, o, name, ANARI_BOOL, &value);
}

inline void setParameter(
    Device d, Object o, const char *name, DataType type, const void *v)
{
  anariSetParameter(d, o, name, type, v);
}

// Sends `v` as `type` regardless of its C++ type.
template <typename T>
void setParameterAs(Device d, Object o, const char *name, DataType type, T &&v)
{
  anariSetParameter(d, o, name, type, &v);
}

template <typename T>
void setAndReleaseParameter(Device d, Object o, const char *name, const T &v)
{
  constexpr int type = ANARITypeFor<T>::value;
  static_assert(type >= int(ANARI_OBJECT) && type <= int(ANARI_WORLD),
      "anari::setAndReleaseParameter() takes object handles only");
  anariSetParameter(d, o, name, type, &v);
  anariRelease(d, v);
}

inline void unsetParameter(Device d, Object o, const char *id)
{
  anariUnsetParameter(d, o, id);
}

inline void unsetAllParameters(Device d, Object o)
{
  anariUnsetAllParameters(d, o);
}

inline void commitParameters(Device d, Object o)
{
  anariCommitParameters(d, o);
}

inline void release(Device d, Object o)
{
  anariRelease(d, o);
}

inline void retain(Device d, Object o)
{
  anariRetain(d, o);
}

// Properties ///////////////////////////////////////////////////////////////

// True if the object has the property with that type; `dst` is left alone
// otherwise. bool goes through a 32-bit value and std::string through the
// device's `const char *`, copied before returning.
template <typename T>
bool getProperty(Device d,
    Object o,
    const char *propertyName,
    T &dst,
    WaitMask mask = ANARI_WAIT)
{
  if constexpr (std::is_same_v<T, bool>) {
    uint32_t value = 0;
    const int found = anariGetProperty(
        d, o, propertyName, ANARI_BOOL, &value, sizeof(value), mask);
    if (found)
      dst = value != 0;
    return found != 0;
  } else if constexpr (std::is_same_v<T, std::string>) {
    const char *value = nullptr;
    const int found = anariGetProperty(
        d, o, propertyName, ANARI_STRING, &value, sizeof(value), mask);
    if (found)
      dst = value ? value : "";
    return found != 0;
  } else {
    detail::requireKnownType<T>();
    return anariGetProperty(
               d, o, propertyName, detail::getType<T>(), &dst, sizeof(T), mask)
           != 0;
  }
}

// Frames ///////////////////////////////////////////////////////////////////

template <typename T>
struct MappedFrameData
{
  uint32_t width{0};
  uint32_t height{0};
  DataType pixelType{ANARI_UNKNOWN};
  const T *data{nullptr};
};

template <typename T>
MappedFrameData<T> map(Device d, Frame f, const char *channel)
{
  MappedFrameData<T> mapped;
  mapped.data = static_cast<const T *>(anariMapFrame(
      d, f, channel, &mapped.width, &mapped.height, &mapped.pixelType));
  return mapped;
}

inline void unmap(Device d, Frame f, const char *channel)
{
  anariUnmapFrame(d, f, channel);
}

inline void render(Device d, Frame f)
{
  anariRenderFrame(d, f);
}

inline bool isReady(Device d, Frame f)
{
  return anariFrameReady(d, f, ANARI_NO_WAIT) != 0;
}

inline void wait(Device d, Frame f)
{
  anariFrameReady(d, f, ANARI_WAIT);
}

inline void discard(Device d, Frame f)
{
  anariDiscardFrame(d, f);
}

} // namespace anari
