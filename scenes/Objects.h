// Helpers that make ANARI objects through the public C API only, so scenes
// build on any device. Arrays are shared arrays over memory the helpers own
// and the device frees through the array's deleter: no device is asked to
// hand out memory it may not have (some test devices map a fixed scratch
// buffer).
#pragma once

#include "Math.h"

#include <anari/anari.h>

#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace prism::scenes {

// A 1D array of `count` elements of `type` holding a copy of `bytes`.
ANARIArray1D newArray1D(ANARIDevice device,
    ANARIDataType type,
    const void *bytes,
    uint64_t count,
    size_t elementSize);
ANARIArray2D newArray2D(ANARIDevice device,
    ANARIDataType type,
    const void *bytes,
    uint64_t width,
    uint64_t height,
    size_t elementSize);
ANARIArray3D newArray3D(ANARIDevice device,
    ANARIDataType type,
    const void *bytes,
    uint64_t width,
    uint64_t height,
    uint64_t depth,
    size_t elementSize);

template <typename T>
ANARIArray1D newArray1D(
    ANARIDevice device, ANARIDataType type, const std::vector<T> &elements)
{
  return newArray1D(device, type, elements.data(), elements.size(), sizeof(T));
}

// A shared array over `elements` themselves, no copy: the device owns them
// from here and frees them when it no longer reads them. `count` elements
// of `type` (as many bytes as `elements` hold; by default one per T).
template <typename T>
ANARIArray1D newArray1D(ANARIDevice device,
    ANARIDataType type,
    std::vector<T> &&elements,
    uint64_t count = ~0ull)
{
  if (count == ~0ull)
    count = elements.size();
  auto *owned = new std::vector<T>(std::move(elements));
  return anariNewArray1D(
      device,
      owned->data(),
      [](const void *userPtr, const void *) {
        delete static_cast<const std::vector<T> *>(userPtr);
      },
      owned,
      type,
      count);
}

// Sets array parameter `name` of `object` to a new array and releases the
// helper's reference (the object keeps its own).
template <typename Elements>
void setArray(ANARIDevice device,
    ANARIObject object,
    const char *name,
    ANARIDataType type,
    Elements &&elements)
{
  ANARIArray1D array =
      newArray1D(device, type, std::forward<Elements>(elements));
  anariSetParameter(device, object, name, ANARI_ARRAY1D, &array);
  anariRelease(device, array);
}

// An ARRAY1D of object handles of `elementType` (e.g. ANARI_SURFACE); of
// surfaces and volumes only this process's share (Partition.h).
void setObjectArray(ANARIDevice device,
    ANARIObject object,
    const char *name,
    ANARIDataType elementType,
    const std::vector<ANARIObject> &objects);

void setFloat(
    ANARIDevice device, ANARIObject object, const char *name, float value);
void setVec3(
    ANARIDevice device, ANARIObject object, const char *name, const Vec3 &v);
void setString(ANARIDevice device,
    ANARIObject object,
    const char *name,
    const char *value);
void setObject(ANARIDevice device,
    ANARIObject object,
    const char *name,
    ANARIDataType type,
    ANARIObject value);

// A committed surface of `geometry` and `material`; releases neither.
ANARISurface newSurface(
    ANARIDevice device, ANARIGeometry geometry, ANARIMaterial material);
// A committed matte material of one color.
ANARIMaterial newMatte(ANARIDevice device, const Vec3 &color);

// Whether the device can create objects of `type` with this subtype, by
// introspection (anariGetObjectSubtypes).
bool hasSubtype(ANARIDevice device, ANARIDataType type, const char *subtype);
// Whether the device lists `extension` (e.g. "ANARI_KHR_LIGHT_QUAD") in its
// `extension` property. Devices that do not report the property list none.
bool hasExtension(ANARIDevice device, const char *extension);

} // namespace prism::scenes
