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

// The element type and sizes of a new array, checked; false (with `f`
// told why) if the array cannot be made.
bool checkArrayShape(Findings &f,
    ANARIDataType arrayType,
    ANARIDataType elementType,
    const uint64_t items[3])
{
  if (!isArrayElementType(elementType)) {
    f.error(std::string("element type ") + anari::toString(elementType) + " ("
            + std::to_string(int(elementType))
            + ") cannot be an array element");
    return false;
  }
  const int dimensions = arrayType == ANARI_ARRAY1D   ? 1
                         : arrayType == ANARI_ARRAY2D ? 2
                                                      : 3;
  for (int i = 0; i < dimensions; ++i) {
    if (items[i] == 0) {
      f.error("the array has no elements (dimension " + std::to_string(i + 1)
              + " is 0)");
      return false;
    }
  }
  uint64_t bytes = anari::sizeOf(elementType);
  for (int i = 0; i < 3; ++i) {
    if (items[i] && __builtin_mul_overflow(bytes, items[i], &bytes)) {
      f.error("the array's size in bytes overflows 64 bits",
          ANARI_STATUS_OUT_OF_MEMORY);
      return false;
    }
  }
  return true;
}

uint64_t elementCount(const uint64_t items[3])
{
  uint64_t count = 1;
  for (int i = 0; i < 3; ++i)
    count *= items[i] ? items[i] : 1;
  return count;
}

// "[2 3 0]"
std::string itemsOperand(const uint64_t items[3])
{
  // Appended, not concatenated: GCC 12 raises a false -Wrestrict.
  return std::string("[")
      .append(std::to_string(items[0]))
      .append(" ")
      .append(std::to_string(items[1]))
      .append(" ")
      .append(std::to_string(items[2]))
      .append("]");
}

} // namespace

ANARIObject DebugDevice::newObjectOf(ANARIDataType type, const char *subtype)
{
  const char *function = newFunctionName(type);
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
      wrapped = ForwardingDevice::newObjectOf(type, subtype);
    }
    ANARIObject handle = nullptr;
    {
      std::lock_guard lock(m_mutex);
      handle = created(function, type, subtype, wrapped, f);
      if (handle && tracing()) {
        ObjectRecord &record = *m_objects.find(handle);
        record.knownSubtype = known;
        // Appended, not concatenated: GCC 12 raises a false -Wrestrict.
        std::string line = "New " + traceName(handle) + " ";
        line.append(trace::typeName(type));
        if (subtype)
          line.append(" ").append(trace::quote(subtype));
        record.traceLine = trace(line);
      } else if (handle) {
        m_objects.find(handle)->knownSubtype = known;
      }
    }
    report(f);
    return handle;
  });
}

ANARIObject DebugDevice::newObject(const char *objectType, const char *subtype)
{
  return guarded("anariNewObject", ANARIObject(nullptr), [&] {
    Findings f("anariNewObject");
    ANARIObject wrapped = inner()->newObject(objectType, subtype);
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

ANARIArray DebugDevice::refuseArray(Findings &f,
    ANARIDataType arrayType,
    ANARIDataType elementType,
    const uint64_t items[3])
{
  {
    // Refused: no object, so no name (`-`), and no data.
    std::lock_guard lock(m_mutex);
    if (tracing() && anari::isValidDataType(elementType)) {
      trace("Refused Array - " + trace::typeName(arrayType) + " "
            + trace::typeName(elementType) + " " + itemsOperand(items) + " -");
    }
  }
  report(f);
  return nullptr;
}

void DebugDevice::recordArray(ANARIObject handle,
    ANARIDataType arrayType,
    ANARIDataType elementType,
    const uint64_t items[3],
    const void *appMemory,
    std::vector<ANARIObject> copied)
{
  ObjectRecord &record = *m_objects.find(handle);
  record.elementType = elementType;
  for (int i = 0; i < 3; ++i)
    record.items[i] = items[i];
  const bool objects = anari::isObject(elementType);
  if (objects) {
    record.objectArray = true;
    record.appMemory = appMemory;
    if (!record.appMemory)
      record.ownedHandles.assign(record.itemCount(), nullptr);
    record.copiedHandles = std::move(copied);
  } else if (appMemory) {
    record.hasLargestIndex = largestComponent(
        appMemory, elementType, record.itemCount(), 0, record.largestIndex);
  }
  if (tracing()) {
    record.traceLine = trace(
        "Array " + traceName(handle) + " " + trace::typeName(arrayType) + " "
        + trace::typeName(elementType) + " " + itemsOperand(items) + " "
        + traceContents(elementType, appMemory, record.itemCount(), 0));
  }
}

ANARIArray DebugDevice::newArrayOf(ANARIDataType arrayType,
    const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType elementType,
    const uint64_t items[3])
{
  const char *function = newFunctionName(arrayType);
  return guarded(function, ANARIArray(nullptr), [&]() -> ANARIArray {
    Findings f(function);
    if (!checkArrayShape(f, arrayType, elementType, items))
      return refuseArray(f, arrayType, elementType, items);
    const void *applicationMemory = appMemory;
    // Object arrays hold layer handles; the wrapped device reads a
    // translated copy that its deleter call frees.
    std::vector<ANARIObject> copied;
    if (anari::isObject(elementType)) {
      auto *storage = new ObjectArrayStorage;
      {
        std::lock_guard lock(m_mutex);
        storage->handles = translateHandles(f,
            (const ANARIObject *)appMemory,
            elementCount(items),
            elementType,
            copied);
      }
      storage->appDeleter = deleter;
      storage->appUserPtr = userData;
      storage->appMemory = appMemory;
      appMemory = storage->handles.data();
      deleter = &ObjectArrayStorage::release;
      userData = storage;
    }
    ANARIObject wrapped = nullptr;
    {
      const auto quiet = withheldAfter(f);
      wrapped = ForwardingDevice::newArrayOf(
          arrayType, appMemory, deleter, userData, elementType, items);
    }
    ANARIObject handle = nullptr;
    {
      std::lock_guard lock(m_mutex);
      handle = created(function, arrayType, nullptr, wrapped, f);
      if (handle) {
        recordArray(handle,
            arrayType,
            elementType,
            items,
            applicationMemory,
            std::move(copied));
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

} // namespace prism::debug
