// anariNew*: subtypes checked, arrays' element types, sizes and (for object
// arrays) elements checked; every new object gets a layer handle.
#include "ArrayContents.h"
#include "DebugDevice.h"
#include "trace/TraceFormat.h"

#include "anari/frontend/type_utility.h"

namespace prism::debug {
namespace {

// The translated handles the wrapped device reads for an object array; the
// wrapped device's deleter call frees them and runs the application's
// deleter, exactly when it would have without the layer.
struct ObjectArrayStorage
{
  std::vector<ANARIObject> handles;
  ANARIMemoryDeleter appDeleter = nullptr;
  const void *appUserPtr = nullptr;
  const void *appMemory = nullptr;

  static void release(const void *userPtr, const void *)
  {
    auto *storage = (ObjectArrayStorage *)userPtr;
    if (storage->appDeleter)
      storage->appDeleter(storage->appUserPtr, storage->appMemory);
    delete storage;
  }
};

// Numbers and vectors of them, and handles of objects an array can hold.
bool isArrayElementType(ANARIDataType type)
{
  if (anari::isObject(type))
    return type != ANARI_DEVICE && type != ANARI_OBJECT;
  return anari::isValidDataType(type) && int(type) >= int(ANARI_INT8)
         && anari::sizeOf(type) > 0;
}

} // namespace

template <typename NewObject>
ANARIObject DebugDevice::newSubtyped(const char *function,
    ANARIDataType type,
    const char *subtype,
    NewObject &&make)
{
  return guarded(function, ANARIObject(nullptr), [&]() -> ANARIObject {
    Findings f(function);
    if (type != ANARI_SURFACE && type != ANARI_GROUP && type != ANARI_WORLD
        && type != ANARI_FRAME) {
      std::lock_guard lock(m_mutex);
      if (!subtype) {
        f.error("subtype is NULL");
        // Refused: no object, so no name (`-`) and no subtype.
        if (tracing())
          trace("Refused New - " + trace::typeName(type));
      } else {
        m_rules->checkSubtype(f, type, subtype);
      }
    }
    if (!subtype && f.any()) {
      report(f);
      return nullptr;
    }
    const bool known = !f.any();
    ANARIObject wrapped = nullptr;
    {
      const auto quiet = withheldAfter(f);
      wrapped = make();
    }
    ANARIObject handle = nullptr;
    {
      std::lock_guard lock(m_mutex);
      handle = created(function, type, subtype, wrapped, f);
      if (handle && tracing()) {
        ObjectRecord &record = *m_objects.find(handle);
        record.knownSubtype = known;
        record.traceLine =
            trace("New " + traceName(handle) + " " + trace::typeName(type)
                  + (subtype ? " " + trace::quote(subtype) : std::string()));

      } else if (handle) {
        m_objects.find(handle)->knownSubtype = known;
      }
    }
    report(f);
    return handle;
  });
}

ANARIGeometry DebugDevice::newGeometry(const char *subtype)
{
  return (ANARIGeometry)newSubtyped(
      "anariNewGeometry", ANARI_GEOMETRY, subtype, [&] {
        return (ANARIObject)m_wrapped->newGeometry(subtype);
      });
}

ANARIMaterial DebugDevice::newMaterial(const char *subtype)
{
  return (ANARIMaterial)newSubtyped(
      "anariNewMaterial", ANARI_MATERIAL, subtype, [&] {
        return (ANARIObject)m_wrapped->newMaterial(subtype);
      });
}

ANARISampler DebugDevice::newSampler(const char *subtype)
{
  return (ANARISampler)newSubtyped(
      "anariNewSampler", ANARI_SAMPLER, subtype, [&] {
        return (ANARIObject)m_wrapped->newSampler(subtype);
      });
}

ANARISurface DebugDevice::newSurface()
{
  return (ANARISurface)newSubtyped(
      "anariNewSurface", ANARI_SURFACE, nullptr, [&] {
        return (ANARIObject)m_wrapped->newSurface();
      });
}

ANARISpatialField DebugDevice::newSpatialField(const char *subtype)
{
  return (ANARISpatialField)newSubtyped(
      "anariNewSpatialField", ANARI_SPATIAL_FIELD, subtype, [&] {
        return (ANARIObject)m_wrapped->newSpatialField(subtype);
      });
}

ANARIVolume DebugDevice::newVolume(const char *subtype)
{
  return (ANARIVolume)newSubtyped("anariNewVolume", ANARI_VOLUME, subtype, [&] {
    return (ANARIObject)m_wrapped->newVolume(subtype);
  });
}

ANARILight DebugDevice::newLight(const char *subtype)
{
  return (ANARILight)newSubtyped("anariNewLight", ANARI_LIGHT, subtype, [&] {
    return (ANARIObject)m_wrapped->newLight(subtype);
  });
}

ANARIGroup DebugDevice::newGroup()
{
  return (ANARIGroup)newSubtyped("anariNewGroup", ANARI_GROUP, nullptr, [&] {
    return (ANARIObject)m_wrapped->newGroup();
  });
}

ANARIInstance DebugDevice::newInstance(const char *subtype)
{
  return (ANARIInstance)newSubtyped(
      "anariNewInstance", ANARI_INSTANCE, subtype, [&] {
        return (ANARIObject)m_wrapped->newInstance(subtype);
      });
}

ANARIWorld DebugDevice::newWorld()
{
  return (ANARIWorld)newSubtyped("anariNewWorld", ANARI_WORLD, nullptr, [&] {
    return (ANARIObject)m_wrapped->newWorld();
  });
}

ANARICamera DebugDevice::newCamera(const char *subtype)
{
  return (ANARICamera)newSubtyped("anariNewCamera", ANARI_CAMERA, subtype, [&] {
    return (ANARIObject)m_wrapped->newCamera(subtype);
  });
}

ANARIRenderer DebugDevice::newRenderer(const char *subtype)
{
  return (ANARIRenderer)newSubtyped(
      "anariNewRenderer", ANARI_RENDERER, subtype, [&] {
        return (ANARIObject)m_wrapped->newRenderer(subtype);
      });
}

ANARIFrame DebugDevice::newFrame()
{
  return (ANARIFrame)newSubtyped("anariNewFrame", ANARI_FRAME, nullptr, [&] {
    return (ANARIObject)m_wrapped->newFrame();
  });
}

ANARIObject DebugDevice::newObject(const char *objectType, const char *subtype)
{
  return guarded("anariNewObject", ANARIObject(nullptr), [&] {
    Findings f("anariNewObject");
    ANARIObject wrapped = m_wrapped->newObject(objectType, subtype);
    std::lock_guard lock(m_mutex);
    ANARIObject handle =
        wrapped ? created("anariNewObject", ANARI_OBJECT, subtype, wrapped, f)
                : nullptr;
    if (handle && tracing()) {
      m_objects.find(handle)->traceLine =
          trace("NewObject " + traceName(handle) + " "
                + trace::quote(objectType ? objectType : "") + " "
                + trace::quote(subtype ? subtype : ""));
    }
    return handle; // NULL from the device is its documented answer
  });
}

// Arrays /////////////////////////////////////////////////////////////////////

ANARIArray DebugDevice::newArray(const char *function,
    ANARIDataType arrayType,
    const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType elementType,
    const uint64_t items[3])
{
  // Refused: no object, so no name (`-`), and no data.
  auto refuse = [&](Findings &f) -> ANARIArray {
    {
      std::lock_guard lock(m_mutex);
      if (tracing() && anari::isValidDataType(elementType)) {
        trace("Refused Array - " + trace::typeName(arrayType) + " "
              + trace::typeName(elementType) + " [" + std::to_string(items[0])
              + " " + std::to_string(items[1]) + " " + std::to_string(items[2])
              + "] -");
      }
    }
    report(f);
    return nullptr;
  };
  return guarded(function, ANARIArray(nullptr), [&]() -> ANARIArray {
    Findings f(function);
    if (!isArrayElementType(elementType)) {
      f.error(std::string("element type ") + anari::toString(elementType) + " ("
              + std::to_string(int(elementType))
              + ") cannot be an array element");
      return refuse(f);
    }
    const int dimensions = arrayType == ANARI_ARRAY1D   ? 1
                           : arrayType == ANARI_ARRAY2D ? 2
                                                        : 3;
    for (int i = 0; i < dimensions; ++i) {
      if (items[i] == 0) {
        f.error("the array has no elements (dimension " + std::to_string(i + 1)
                + " is 0)");
        return refuse(f);
      }
    }
    uint64_t bytes = anari::sizeOf(elementType);
    for (int i = 0; i < 3; ++i) {
      if (items[i] && __builtin_mul_overflow(bytes, items[i], &bytes)) {
        f.error("the array's size in bytes overflows 64 bits",
            ANARI_STATUS_OUT_OF_MEMORY);
        return refuse(f);
      }
    }
    const bool objects = anari::isObject(elementType);
    uint64_t count = 1;
    for (int i = 0; i < 3; ++i)
      count *= items[i] ? items[i] : 1;
    // Object arrays hold layer handles; the wrapped device reads a
    // translated copy that its deleter call frees.
    ObjectArrayStorage *storage = nullptr;
    std::vector<ANARIObject> copied;
    if (objects) {
      storage = new ObjectArrayStorage;
      {
        std::lock_guard lock(m_mutex);
        storage->handles = translateHandles(
            f, (const ANARIObject *)appMemory, count, elementType, copied);
      }
      storage->appDeleter = deleter;
      storage->appUserPtr = userData;
      storage->appMemory = appMemory;
      appMemory = storage->handles.data();
      deleter = &ObjectArrayStorage::release;
      userData = storage;
    }
    ANARIObject wrapped = nullptr;
    if (arrayType == ANARI_ARRAY1D) {
      const auto quiet = withheldAfter(f);
      wrapped = m_wrapped->newArray1D(
          appMemory, deleter, userData, elementType, items[0]);
    } else if (arrayType == ANARI_ARRAY2D) {
      const auto quiet = withheldAfter(f);
      wrapped = m_wrapped->newArray2D(
          appMemory, deleter, userData, elementType, items[0], items[1]);
    } else {
      const auto quiet = withheldAfter(f);
      wrapped = m_wrapped->newArray3D(appMemory,
          deleter,
          userData,
          elementType,
          items[0],
          items[1],
          items[2]);
    }
    ANARIObject handle = nullptr;
    {
      std::lock_guard lock(m_mutex);
      handle = created(function, arrayType, nullptr, wrapped, f);
      if (handle) {
        ObjectRecord &record = *m_objects.find(handle);
        record.elementType = elementType;
        for (int i = 0; i < 3; ++i)
          record.items[i] = items[i];
        if (objects) {
          record.objectArray = true;
          record.appMemory = storage->appMemory;
          if (!record.appMemory)
            record.ownedHandles.assign(count, nullptr);
          record.copiedHandles = std::move(copied);
        } else if (appMemory) {
          record.hasLargestIndex = largestComponent(appMemory,
              elementType,
              record.itemCount(),
              0,
              record.largestIndex);
        }
        if (tracing()) {
          record.traceLine = trace(
              "Array " + traceName(handle) + " " + trace::typeName(arrayType)
              + " " + trace::typeName(elementType) + " ["
              + std::to_string(items[0]) + " " + std::to_string(items[1]) + " "
              + std::to_string(items[2]) + "] "
              + traceContents(elementType,
                  objects ? storage->appMemory : appMemory,
                  count,
                  0));
        }
      }
    }
    report(f);
    return (ANARIArray)handle;
  });
}

std::vector<ANARIObject> DebugDevice::translateHandles(Findings &f,
    const ANARIObject *source,
    uint64_t count,
    ANARIDataType elementType,
    std::vector<ANARIObject> &copied)
{
  std::vector<ANARIObject> out(count, nullptr);
  if (!source) {
    copied.assign(count, nullptr);
    return out;
  }
  int reported = 0;
  for (uint64_t i = 0; i < count; ++i) {
    const ANARIObject handle = source[i];
    if (!handle)
      continue;
    if (i < copied.size() && copied[i] == handle) {
      if (const ObjectRecord *record = m_objects.find(handle))
        out[i] = record->wrapped;
      continue;
    }
    Findings element(f.function());
    if (!translate(element, handle, elementType, "element", out[i])
        && reported++ < 4) {
      const Finding &found = element.list().front();
      f.error("element " + std::to_string(i) + ": "
                  + found.text.substr(found.text.find("): ") + 3),
          found.code);
    }
  }
  copied.assign(source, source + count);
  return out;
}

std::vector<ANARIObject> DebugDevice::translateObjectArray(
    Findings &f, ObjectRecord &array)
{
  const auto *source = array.appMemory ? (const ANARIObject *)array.appMemory
                                       : array.ownedHandles.data();
  return translateHandles(
      f, source, array.itemCount(), array.elementType, array.copiedHandles);
}

ANARIArray1D DebugDevice::newArray1D(const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType elementType,
    uint64_t numItems1)
{
  const uint64_t items[3] = {numItems1, 0, 0};
  return (ANARIArray1D)newArray("anariNewArray1D",
      ANARI_ARRAY1D,
      appMemory,
      deleter,
      userData,
      elementType,
      items);
}

ANARIArray2D DebugDevice::newArray2D(const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType elementType,
    uint64_t numItems1,
    uint64_t numItems2)
{
  const uint64_t items[3] = {numItems1, numItems2, 0};
  return (ANARIArray2D)newArray("anariNewArray2D",
      ANARI_ARRAY2D,
      appMemory,
      deleter,
      userData,
      elementType,
      items);
}

ANARIArray3D DebugDevice::newArray3D(const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType elementType,
    uint64_t numItems1,
    uint64_t numItems2,
    uint64_t numItems3)
{
  const uint64_t items[3] = {numItems1, numItems2, numItems3};
  return (ANARIArray3D)newArray("anariNewArray3D",
      ANARI_ARRAY3D,
      appMemory,
      deleter,
      userData,
      elementType,
      items);
}

} // namespace prism::debug
