#include "Device.h"

#include "DeviceInfo.h"
#include "Subtypes.h"
#include "array/Array.h"
#include "frame/Frame.h"
#include "introspection/Introspection.h"
#include "object/UnknownObject.h"
#include "renderer/wavefront/LocalTransport.h"

#include "MachineLimits.h"

#include "anari/frontend/type_utility.h"

#include <algorithm>
#include <cstring>

namespace prism {
namespace {

// Commit order within a flush: children before the objects that use them.
int commitRank(ANARIDataType type)
{
  switch (int(type)) {
  case ANARI_ARRAY1D:
  case ANARI_ARRAY2D:
  case ANARI_ARRAY3D:
    return 0;
  case ANARI_SAMPLER:
  case ANARI_SPATIAL_FIELD:
    return 1;
  case ANARI_GEOMETRY:
  case ANARI_MATERIAL:
  case ANARI_LIGHT:
  case ANARI_VOLUME:
    return 2;
  case ANARI_SURFACE:
    return 3;
  case ANARI_GROUP:
    return 4;
  case ANARI_INSTANCE:
    return 5;
  case ANARI_WORLD:
    return 6;
  case ANARI_CAMERA:
  case ANARI_RENDERER:
    return 7;
  default:
    return 8; // frames
  }
}

bool copyOut(void *mem, uint64_t size, const void *value, size_t valueSize)
{
  if (!mem || size < valueSize)
    return false;
  std::memcpy(mem, value, valueSize);
  return true;
}

} // namespace

Device::Device(ANARILibrary library)
    : anari::DeviceImpl(library),
      m_rtContext([this](const std::string &message) {
        reportStatus(this_device(),
            ANARI_DEVICE,
            ANARI_SEVERITY_ERROR,
            ANARI_STATUS_UNKNOWN_ERROR,
            message);
      })
{
  m_statusCallback = m_defaultStatusCB;
  m_statusUserPtr = m_defaultStatusCBUserPtr;
  addPrismSubtypes(m_subtypes);
  // Objects read their parameters' defaults and bounds from introspection;
  // a device made without the library (tests of the core) needs it too.
  // A no-op once the library (or the data-parallel one) has set it.
  introspection::setImplementedExtensions(
      kImplementedExtensions, kRendererSubtypes);
}

Device::~Device()
{
  m_taskPool.wait();
  releaseAllObjects();
}

void Device::releaseAllObjects()
{
  {
    std::lock_guard lock(m_commitMutex);
    for (Object *object : m_pendingCommits)
      object->releaseInternal();
    m_pendingCommits.clear();
  }
  {
    std::lock_guard lock(m_mappedMutex);
    for (auto &[key, array] : m_mappedParameters)
      array->releaseInternal();
    m_mappedParameters.clear();
  }
  auto leaked = m_handles.liveObjects();
  if (!leaked.empty()) {
    std::string list;
    for (Object *object : leaked)
      list += (list.empty() ? "" : ", ") + object->describe();
    reportStatus(this_device(),
        ANARI_DEVICE,
        ANARI_SEVERITY_DEBUG,
        ANARI_STATUS_NO_ERROR,
        "device released with " + std::to_string(leaked.size())
            + " object(s) the application did not release: " + list);
  }
  // Every object, held by the application or not (reference cycles keep
  // objects alive that no handle names). Break every reference between
  // them first, then drop the public ones: each object is then freed
  // exactly once, whatever the reference graph.
  std::vector<Object *> all;
  {
    std::lock_guard lock(m_objectsMutex);
    all.assign(m_objects.begin(), m_objects.end());
  }
  for (Object *object : all)
    object->retainInternal();
  for (Object *object : all)
    object->dropReferences();
  for (Object *object : leaked) {
    m_handles.remove(object->handle());
    while (object->publicReferences() > 0) {
      object->dropPublicReference();
      object->releaseInternal();
    }
  }
  for (Object *object : all)
    object->releaseInternal();
}

void Device::objectCreated(Object *object)
{
  std::lock_guard lock(m_objectsMutex);
  m_objects.insert(object);
}

void Device::objectDestroyed(Object *object)
{
  std::lock_guard lock(m_objectsMutex);
  m_objects.erase(object);
}

// Status ///////////////////////////////////////////////////////////////////

void Device::reportStatus(ANARIObject source,
    ANARIDataType sourceType,
    ANARIStatusSeverity severity,
    ANARIStatusCode code,
    const std::string &message) const
{
  std::lock_guard lock(m_statusMutex);
  if (m_statusCallback) {
    m_statusCallback(m_statusUserPtr,
        this_device(),
        source,
        sourceType,
        severity,
        code,
        message.c_str());
  }
}

void Device::reportException(const char *function) const noexcept
{
  try {
    try {
      throw;
    } catch (const std::bad_alloc &) {
      reportStatus(this_device(),
          ANARI_DEVICE,
          ANARI_SEVERITY_ERROR,
          ANARI_STATUS_OUT_OF_MEMORY,
          std::string(function) + ": out of memory; the call had no effect");
    } catch (const std::exception &e) {
      reportStatus(this_device(),
          ANARI_DEVICE,
          ANARI_SEVERITY_ERROR,
          ANARI_STATUS_UNKNOWN_ERROR,
          std::string(function) + ": internal error: " + e.what());
    }
  } catch (...) {
    // Nothing may cross the C boundary, not even a failed report.
  }
}

// Handles //////////////////////////////////////////////////////////////////

Object *Device::lookup(ANARIObject handle) const
{
  return m_handles.find(handle);
}

const char *Device::whyNotLive(ANARIObject handle) const
{
  if (!handle)
    return "object handle is NULL";
  if (m_handles.isForeign(handle))
    return "handle belongs to another device";
  return "handle is not a live object of this device (released, or never "
         "created)";
}

Object *Device::checked(ANARIObject handle,
    const char *function,
    std::initializer_list<ANARIDataType> types) const
{
  Object *object = lookup(handle);
  if (!object) {
    reportStatus(handle,
        ANARI_OBJECT,
        ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_ARGUMENT,
        std::string(function) + ": " + whyNotLive(handle));
    return nullptr;
  }
  if (types.size() == 0
      || std::find(types.begin(), types.end(), object->type()) != types.end())
    return object;
  reportStatus(handle,
      object->type(),
      ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      std::string(function) + ": " + object->describe()
          + " is not of the expected type " + anari::toString(*types.begin()));
  return nullptr;
}

ANARIObject Device::track(Object *object)
{
  ANARIObject handle = m_handles.add(object);
  object->setHandle(handle);
  return handle;
}

template <typename Handle>
Handle Device::create(ANARIDataType type, const char *subtype)
{
  const std::string name = subtype ? subtype : "";
  if (!m_subtypes.creates(type))
    return nullptr;
  Object *object = m_subtypes.create(*this, type, name);
  if (!object) {
    object = new UnknownObject(*this, type, name);
    object->report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "unknown subtype '%s'; the object will not render",
        name.c_str());
  }
  return (Handle)track(object);
}

ANARIGeometry Device::newGeometry(const char *subtype)
try {
  return create<ANARIGeometry>(ANARI_GEOMETRY, subtype);
} catch (...) {
  reportException("anariNewGeometry");
  return nullptr;
}
ANARIMaterial Device::newMaterial(const char *subtype)
try {
  return create<ANARIMaterial>(ANARI_MATERIAL, subtype);
} catch (...) {
  reportException("anariNewMaterial");
  return nullptr;
}
ANARISampler Device::newSampler(const char *subtype)
try {
  return create<ANARISampler>(ANARI_SAMPLER, subtype);
} catch (...) {
  reportException("anariNewSampler");
  return nullptr;
}
ANARISurface Device::newSurface()
try {
  return create<ANARISurface>(ANARI_SURFACE, nullptr);
} catch (...) {
  reportException("anariNewSurface");
  return nullptr;
}
ANARISpatialField Device::newSpatialField(const char *subtype)
try {
  return create<ANARISpatialField>(ANARI_SPATIAL_FIELD, subtype);
} catch (...) {
  reportException("anariNewSpatialField");
  return nullptr;
}
ANARIVolume Device::newVolume(const char *subtype)
try {
  return create<ANARIVolume>(ANARI_VOLUME, subtype);
} catch (...) {
  reportException("anariNewVolume");
  return nullptr;
}
ANARILight Device::newLight(const char *subtype)
try {
  return create<ANARILight>(ANARI_LIGHT, subtype);
} catch (...) {
  reportException("anariNewLight");
  return nullptr;
}
ANARIGroup Device::newGroup()
try {
  return create<ANARIGroup>(ANARI_GROUP, nullptr);
} catch (...) {
  reportException("anariNewGroup");
  return nullptr;
}
ANARIInstance Device::newInstance(const char *subtype)
try {
  return create<ANARIInstance>(ANARI_INSTANCE, subtype);
} catch (...) {
  reportException("anariNewInstance");
  return nullptr;
}
ANARIWorld Device::newWorld()
try {
  return create<ANARIWorld>(ANARI_WORLD, nullptr);
} catch (...) {
  reportException("anariNewWorld");
  return nullptr;
}
ANARICamera Device::newCamera(const char *subtype)
try {
  return create<ANARICamera>(ANARI_CAMERA, subtype);
} catch (...) {
  reportException("anariNewCamera");
  return nullptr;
}
ANARIRenderer Device::newRenderer(const char *subtype)
try {
  return create<ANARIRenderer>(ANARI_RENDERER, subtype);
} catch (...) {
  reportException("anariNewRenderer");
  return nullptr;
}
ANARIFrame Device::newFrame()
try {
  return create<ANARIFrame>(ANARI_FRAME, nullptr);
} catch (...) {
  reportException("anariNewFrame");
  return nullptr;
}

ANARIObject Device::newObject(const char *objectType, const char *subtype)
try {
  reportStatus(nullptr,
      ANARI_OBJECT,
      ANARI_SEVERITY_WARNING,
      ANARI_STATUS_INVALID_ARGUMENT,
      std::string("anariNewObject: unknown object type '")
          + (objectType ? objectType : "") + "'");
  return nullptr;
} catch (...) {
  reportException("anariNewObject");
  return nullptr;
}

// Arrays ///////////////////////////////////////////////////////////////////

ANARIArray Device::newArray(const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType elementType,
    int dimensions,
    const uint64_t size[3])
{
  Array::Shape shape;
  shape.elementType = elementType;
  shape.dimensions = dimensions;
  for (int i = 0; i < dimensions; i++)
    shape.size[i] = size[i];
  if (const char *why = Array::whyNotCreatable(shape)) {
    reportStatus(nullptr,
        ANARI_ARRAY,
        ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_ARGUMENT,
        std::string("anariNewArray") + char('0' + dimensions) + "D ("
            + anari::toString(elementType) + "): " + why);
    return nullptr;
  }
  if (!appMemory && !limits::fitsInMemory(Array::bytesNeeded(shape))) {
    std::string sizes = std::to_string(shape.size[0]);
    for (int i = 1; i < dimensions; i++)
      sizes += "x" + std::to_string(shape.size[i]);
    reportStatus(nullptr,
        ANARI_ARRAY,
        ANARI_SEVERITY_ERROR,
        ANARI_STATUS_OUT_OF_MEMORY,
        std::string("anariNewArray") + char('0' + dimensions) + "D ("
            + anari::toString(elementType) + "): a managed array of " + sizes
            + " elements needs " + limits::byteSize(Array::bytesNeeded(shape))
            + ", more than " + limits::memoryLimitText()
            + "; it is not created");
    return nullptr;
  }
  try {
    return (ANARIArray)track(
        new Array(*this, appMemory, deleter, userData, shape));
  } catch (const std::bad_alloc &) {
    reportStatus(nullptr,
        ANARI_ARRAY,
        ANARI_SEVERITY_ERROR,
        ANARI_STATUS_OUT_OF_MEMORY,
        "anariNewArray: out of memory for a managed array");
    return nullptr;
  }
}

ANARIArray1D Device::newArray1D(const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType elementType,
    uint64_t numItems1)
try {
  const uint64_t size[3] = {numItems1, 1, 1};
  return (ANARIArray1D)newArray(
      appMemory, deleter, userData, elementType, 1, size);
} catch (...) {
  reportException("anariNewArray1D");
  return nullptr;
}

ANARIArray2D Device::newArray2D(const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType elementType,
    uint64_t numItems1,
    uint64_t numItems2)
try {
  const uint64_t size[3] = {numItems1, numItems2, 1};
  return (ANARIArray2D)newArray(
      appMemory, deleter, userData, elementType, 2, size);
} catch (...) {
  reportException("anariNewArray2D");
  return nullptr;
}

ANARIArray3D Device::newArray3D(const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType elementType,
    uint64_t numItems1,
    uint64_t numItems2,
    uint64_t numItems3)
try {
  const uint64_t size[3] = {numItems1, numItems2, numItems3};
  return (ANARIArray3D)newArray(
      appMemory, deleter, userData, elementType, 3, size);
} catch (...) {
  reportException("anariNewArray3D");
  return nullptr;
}

void *Device::mapArray(ANARIArray handle)
try {
  auto *array = (Array *)checked(
      handle, "anariMapArray", {ANARI_ARRAY1D, ANARI_ARRAY2D, ANARI_ARRAY3D});
  if (!array)
    return nullptr;
  if (array->isMapped()) {
    array->report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_OPERATION,
        "anariMapArray: array is already mapped");
  }
  // Writes must not race a frame reading the array.
  waitForFrames();
  return array->map();
} catch (...) {
  reportException("anariMapArray");
  return nullptr;
}

void Device::unmapArray(ANARIArray handle)
try {
  auto *array = (Array *)checked(
      handle, "anariUnmapArray", {ANARI_ARRAY1D, ANARI_ARRAY2D, ANARI_ARRAY3D});
  if (!array)
    return;
  if (!array->isMapped()) {
    array->report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_OPERATION,
        "anariUnmapArray: array is not mapped");
    return;
  }
  array->unmap();
} catch (...) {
  reportException("anariUnmapArray");
  return;
}

// Parameters ///////////////////////////////////////////////////////////////

bool Device::isMappedParameter(Object *object, const std::string &name) const
{
  std::lock_guard lock(m_mappedMutex);
  return m_mappedParameters.count({object, name}) != 0;
}

void Device::setParameter(
    ANARIObject handle, const char *name, ANARIDataType type, const void *mem)
try {
  if (handle == (ANARIObject)this_device()) {
    setDeviceParameter(name, type, mem);
    return;
  }
  Object *object = checked(handle, "anariSetParameter");
  if (!object)
    return;
  if (!anari::isValidDataType(type) || type == ANARI_UNKNOWN) {
    object->report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_ARGUMENT,
        "anariSetParameter: parameter '%s' has invalid data type %d",
        name,
        int(type));
    return;
  }
  if (isMappedParameter(object, name)) {
    object->report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_OPERATION,
        "anariSetParameter: parameter '%s' is mapped; unmap it first",
        name);
    return;
  }
  Object *value = nullptr;
  if (anari::isObject(type)) {
    ANARIObject valueHandle = mem ? *(const ANARIObject *)mem : nullptr;
    value = valueHandle ? lookup(valueHandle) : nullptr;
    if (valueHandle && !value) {
      object->report(ANARI_SEVERITY_ERROR,
          ANARI_STATUS_INVALID_ARGUMENT,
          "anariSetParameter: parameter '%s' is not set: %s",
          name,
          whyNotLive(valueHandle));
      return;
    }
    if (!value) {
      // A NULL object is the same as no object.
      object->unstageParameter(name);
      return;
    }
    const bool arrayMatch =
        type == ANARI_ARRAY && anari::isArray(value->type());
    if (value->type() != type && !arrayMatch && type != ANARI_OBJECT) {
      object->report(ANARI_SEVERITY_ERROR,
          ANARI_STATUS_INVALID_ARGUMENT,
          "anariSetParameter: parameter '%s' set as %s but the handle is a %s",
          name,
          anari::toString(type),
          anari::toString(value->type()));
      return;
    }
    type = value->type();
  } else if (!mem && type != ANARI_VOID_POINTER) {
    object->report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_ARGUMENT,
        "anariSetParameter: parameter '%s' has a NULL value pointer",
        name);
    return;
  }
  object->stageParameter(name, Parameter::make(type, mem, value));
} catch (...) {
  reportException("anariSetParameter");
  return;
}

void Device::setDeviceParameter(
    const char *name, ANARIDataType type, const void *mem)
{
  const std::string n = name;
  std::lock_guard lock(m_statusMutex);
  if (n == "statusCallback" && type == ANARI_STATUS_CALLBACK) {
    m_statusCallback = mem ? *(const ANARIStatusCallback *)mem : nullptr;
  } else if (n == "statusCallbackUserData" && type == ANARI_VOID_POINTER) {
    m_statusUserPtr = mem;
  } else if (n == "bvhQuality" && type == ANARI_STRING && mem
             && m_rtContext.setBuildQuality((const char *)mem)) {
    // PRISM_BVH_QUALITY: BVHs built from now on.
  } else if (n != "name" && m_statusCallback) {
    m_statusCallback(m_statusUserPtr,
        this_device(),
        (ANARIObject)this_device(),
        ANARI_DEVICE,
        ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        ("device: unknown parameter '" + n + "' (" + anari::toString(type)
            + ") is ignored")
            .c_str());
  }
}

void Device::unsetParameter(ANARIObject handle, const char *name)
try {
  if (handle == (ANARIObject)this_device())
    return;
  Object *object = checked(handle, "anariUnsetParameter");
  if (!object)
    return;
  if (isMappedParameter(object, name)) {
    object->report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_OPERATION,
        "anariUnsetParameter: parameter '%s' is mapped; unmap it first",
        name);
    return;
  }
  object->unstageParameter(name);
} catch (...) {
  reportException("anariUnsetParameter");
  return;
}

void Device::unsetAllParameters(ANARIObject handle)
try {
  if (handle == (ANARIObject)this_device())
    return;
  if (Object *object = checked(handle, "anariUnsetAllParameters"))
    object->unstageAllParameters();
} catch (...) {
  reportException("anariUnsetAllParameters");
  return;
}

void *Device::mapParameterArray(ANARIObject handle,
    const char *name,
    ANARIDataType elementType,
    int dimensions,
    const uint64_t size[3],
    uint64_t *elementStride,
    const char *function)
{
  Object *object = checked(handle, function);
  if (!object)
    return nullptr;
  if (!elementStride) {
    object->report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_ARGUMENT,
        "%s: elementStride must not be NULL",
        function);
    return nullptr;
  }
  if (isMappedParameter(object, name)) {
    object->report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_OPERATION,
        "%s: parameter '%s' is already mapped",
        function,
        name);
    return nullptr;
  }
  auto arrayHandle =
      newArray(nullptr, nullptr, nullptr, elementType, dimensions, size);
  if (!arrayHandle)
    return nullptr;
  auto *array = (Array *)lookup(arrayHandle);
  // The object keeps the only reference; the handle is never seen outside.
  array->retainInternal();
  m_handles.remove(arrayHandle);
  array->dropPublicReference();
  array->releaseInternal();
  {
    std::lock_guard lock(m_mappedMutex);
    m_mappedParameters[{object, name}] = array;
  }
  *elementStride = array->elementSize();
  return array->map();
}

void *Device::mapParameterArray1D(ANARIObject object,
    const char *name,
    ANARIDataType elementType,
    uint64_t numElements1,
    uint64_t *elementStride)
try {
  const uint64_t size[3] = {numElements1, 1, 1};
  return mapParameterArray(object,
      name,
      elementType,
      1,
      size,
      elementStride,
      "anariMapParameterArray1D");
} catch (...) {
  reportException("anariMapParameterArray1D");
  return nullptr;
}

void *Device::mapParameterArray2D(ANARIObject object,
    const char *name,
    ANARIDataType elementType,
    uint64_t numElements1,
    uint64_t numElements2,
    uint64_t *elementStride)
try {
  const uint64_t size[3] = {numElements1, numElements2, 1};
  return mapParameterArray(object,
      name,
      elementType,
      2,
      size,
      elementStride,
      "anariMapParameterArray2D");
} catch (...) {
  reportException("anariMapParameterArray2D");
  return nullptr;
}

void *Device::mapParameterArray3D(ANARIObject object,
    const char *name,
    ANARIDataType elementType,
    uint64_t numElements1,
    uint64_t numElements2,
    uint64_t numElements3,
    uint64_t *elementStride)
try {
  const uint64_t size[3] = {numElements1, numElements2, numElements3};
  return mapParameterArray(object,
      name,
      elementType,
      3,
      size,
      elementStride,
      "anariMapParameterArray3D");
} catch (...) {
  reportException("anariMapParameterArray3D");
  return nullptr;
}

void Device::unmapParameterArray(ANARIObject handle, const char *name)
try {
  Object *object = checked(handle, "anariUnmapParameterArray");
  if (!object)
    return;
  Array *array = nullptr;
  {
    std::lock_guard lock(m_mappedMutex);
    auto it = m_mappedParameters.find({object, name});
    if (it != m_mappedParameters.end()) {
      array = it->second;
      m_mappedParameters.erase(it);
    }
  }
  if (!array) {
    object->report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_OPERATION,
        "anariUnmapParameterArray: parameter '%s' is not mapped",
        name);
    return;
  }
  array->unmap();
  object->stageParameter(name, Parameter::make(array->type(), nullptr, array));
  array->releaseInternal();
} catch (...) {
  reportException("anariUnmapParameterArray");
  return;
}

void Device::commitParameters(ANARIObject handle)
try {
  if (handle == (ANARIObject)this_device())
    return; // device parameters apply as they are set
  Object *object = checked(handle, "anariCommitParameters");
  if (!object)
    return;
  object->snapshotForCommit();
  object->retainInternal();
  std::lock_guard lock(m_commitMutex);
  m_pendingCommits.push_back(object);
} catch (...) {
  reportException("anariCommitParameters");
  return;
}

void Device::flushCommits()
{
  std::lock_guard lock(m_flushMutex);
  flushCommitsLocked(++m_refreshGeneration);
}

void Device::flushCommitsAndRefresh(Object &object)
{
  std::lock_guard lock(m_flushMutex);
  const uint64_t generation = ++m_refreshGeneration;
  flushCommitsLocked(generation);
  object.refresh(generation);
}

void Device::flushCommitsLocked(uint64_t generation)
{
  waitForFrames();
  std::vector<Object *> pending;
  {
    std::lock_guard lock(m_commitMutex);
    pending.swap(m_pendingCommits);
  }
  if (pending.empty())
    return;
  std::stable_sort(pending.begin(), pending.end(), [](Object *a, Object *b) {
    return commitRank(a->type()) < commitRank(b->type());
  });
  // Each object once, in order: commit all, then build derived state.
  std::vector<Object *> unique;
  for (Object *object : pending) {
    if (std::find(unique.begin(), unique.end(), object) == unique.end())
      unique.push_back(object);
  }
  for (Object *object : unique)
    object->applyCommit();
  // What the commits read may have changed since it was committed itself
  // (an array the application released now reads a private copy): brought
  // up to date before anything is built on it.
  for (Object *object : unique)
    object->refreshDependencies(generation);
  for (Object *object : unique) {
    try {
      object->finalize();
    } catch (const std::bad_alloc &) {
      object->report(ANARI_SEVERITY_ERROR,
          ANARI_STATUS_OUT_OF_MEMORY,
          "out of memory building the committed object");
    }
  }
  for (Object *object : pending)
    object->releaseInternal();
}

// Lifetime /////////////////////////////////////////////////////////////////

void Device::release(ANARIObject handle)
try {
  if (!handle)
    return; // releasing NULL is not an error (spec 3.5)
  if (handle == (ANARIObject)this_device()) {
    if (--m_publicRefs == 0)
      delete this;
    return;
  }
  Object *object = checked(handle, "anariRelease");
  if (!object)
    return;
  if (object->type() == ANARI_FRAME && object->publicReferences() == 1)
    ((Frame *)object)->abandon();
  if (object->dropPublicReference() == 0) {
    m_handles.remove(handle);
    if (anari::isArray(object->type()) && object->totalReferences() > 1)
      keepArrayAfterRelease((Array *)object);
  }
  object->releaseInternal();
} catch (...) {
  reportException("anariRelease");
  return;
}

void Device::keepArrayAfterRelease(Array *array)
{
  if (!array->borrowsApplicationMemory())
    return;
  // The application may free the memory as soon as this returns (the SDK's
  // own scenes do), so no frame may still read it, and objects that use
  // the array read a copy from now on (spec 3.9: "may result in the
  // creation of internal copies").
  auto copy = [&] {
    try {
      array->takePrivateCopy();
    } catch (const std::bad_alloc &) {
      array->report(ANARI_SEVERITY_ERROR,
          ANARI_STATUS_OUT_OF_MEMORY,
          "anariRelease: out of memory copying the released array's data; "
          "objects using it may read memory the application freed");
    }
  };
  if (m_taskPool.isWorkerThread()) {
    // From a frame completion callback: that frame has finished and the
    // next cannot start until the callback returns.
    copy();
    return;
  }
  std::lock_guard lock(m_flushMutex);
  waitForFrames();
  copy();
}

void Device::retain(ANARIObject handle)
try {
  if (handle == (ANARIObject)this_device()) {
    m_publicRefs++;
    return;
  }
  if (Object *object = checked(handle, "anariRetain"))
    object->retainPublic();
} catch (...) {
  reportException("anariRetain");
  return;
}

// Properties ///////////////////////////////////////////////////////////////

bool Device::getDeviceProperty(
    const std::string &name, ANARIDataType type, void *mem, uint64_t size)
{
  auto asInt = [&](int32_t value) {
    return type == ANARI_INT32 && copyOut(mem, size, &value, sizeof(value));
  };
  if (name == "version")
    return asInt(kVersionMajor * 10000 + kVersionMinor * 100 + kVersionPatch);
  if (name == "version.major")
    return asInt(kVersionMajor);
  if (name == "version.minor")
    return asInt(kVersionMinor);
  if (name == "version.patch")
    return asInt(kVersionPatch);
  if (name == "anariVersion.major")
    return asInt(1);
  if (name == "anariVersion.minor")
    return asInt(1);
  if (name == "geometryMaxIndex") {
    const uint64_t value = kGeometryMaxIndex;
    return type == ANARI_UINT64 && copyOut(mem, size, &value, sizeof(value));
  }
  if (name == "extension") {
    const char **list = introspection::deviceExtensions();
    return type == ANARI_STRING_LIST && copyOut(mem, size, &list, sizeof(list));
  }
  const std::string deviceName = kDeviceName;
  if (name == "version.name" && type == ANARI_STRING)
    return copyOut(mem, size, deviceName.c_str(), deviceName.size() + 1);
  if (name == "version.name.size" && type == ANARI_UINT64) {
    const uint64_t length = deviceName.size() + 1;
    return copyOut(mem, size, &length, sizeof(length));
  }
  return false;
}

int Device::getProperty(ANARIObject handle,
    const char *name,
    ANARIDataType type,
    void *mem,
    uint64_t size,
    ANARIWaitMask mask)
try {
  if (handle == (ANARIObject)this_device())
    return getDeviceProperty(name, type, mem, size) ? 1 : 0;
  Object *object = checked(handle, "anariGetProperty");
  if (!object)
    return 0;
  if (mask & ANARI_WAIT)
    flushCommitsAndRefresh(*object);
  return object->getProperty(name, type, mem, size, mask) ? 1 : 0;
} catch (...) {
  reportException("anariGetProperty");
  return 0;
}

// Introspection ////////////////////////////////////////////////////////////

const char **Device::getObjectSubtypes(ANARIDataType objectType)
try {
  return introspection::objectSubtypes(objectType);
} catch (...) {
  reportException("anariGetObjectSubtypes");
  return nullptr;
}

const void *Device::getObjectInfo(ANARIDataType objectType,
    const char *objectSubtype,
    const char *infoName,
    ANARIDataType infoType)
try {
  return introspection::objectInfo(
      objectType, objectSubtype, infoName, infoType);
} catch (...) {
  reportException("anariGetObjectInfo");
  return nullptr;
}

const void *Device::getParameterInfo(ANARIDataType objectType,
    const char *objectSubtype,
    const char *parameterName,
    ANARIDataType parameterType,
    const char *infoName,
    ANARIDataType infoType)
try {
  return introspection::parameterInfo(objectType,
      objectSubtype,
      parameterName,
      parameterType,
      infoName,
      infoType);
} catch (...) {
  reportException("anariGetParameterInfo");
  return nullptr;
}

// Frames ///////////////////////////////////////////////////////////////////

std::unique_ptr<RayTransport> Device::transportFor(const World &world)
{
  std::lock_guard lock(m_transportMutex);
  if (m_transportSource)
    return m_transportSource(world);
  return std::make_unique<LocalTransport>(world);
}

void Device::setTransportSource(TransportSource source)
{
  std::lock_guard lock(m_transportMutex);
  m_transportSource = std::move(source);
}

void Device::frameStarted()
{
  std::lock_guard lock(m_frameMutex);
  m_framesInFlight++;
}

void Device::frameFinished()
{
  std::lock_guard lock(m_frameMutex);
  m_framesInFlight--;
  m_frameDone.notify_all();
}

void Device::waitForFrames()
{
  std::unique_lock lock(m_frameMutex);
  m_frameDone.wait(lock, [&] { return m_framesInFlight == 0; });
}

void Device::renderFrame(ANARIFrame handle)
try {
  auto *frame = (Frame *)checked(handle, "anariRenderFrame", {ANARI_FRAME});
  if (!frame)
    return;
  // NOTE: one flush-and-start at a time, so no thread's frame starts between
  // another thread's flush and the commits it applies.
  std::lock_guard lock(m_flushMutex);
  // Rebuild what depends on arrays or children changed since their commit;
  // what the flush brought up to date is not walked again.
  const uint64_t generation = ++m_refreshGeneration;
  flushCommitsLocked(generation);
  frame->refresh(generation);
  frame->renderAsync();
} catch (...) {
  reportException("anariRenderFrame");
  return;
}

int Device::frameReady(ANARIFrame handle, ANARIWaitMask mask)
try {
  auto *frame = (Frame *)checked(handle, "anariFrameReady", {ANARI_FRAME});
  if (!frame)
    return 0;
  return frame->ready(mask) ? 1 : 0;
} catch (...) {
  reportException("anariFrameReady");
  return 0;
}

void Device::discardFrame(ANARIFrame handle)
try {
  if (auto *frame =
          (Frame *)checked(handle, "anariDiscardFrame", {ANARI_FRAME}))
    frame->discard();
} catch (...) {
  reportException("anariDiscardFrame");
  return;
}

const void *Device::frameBufferMap(ANARIFrame handle,
    const char *channel,
    uint32_t *width,
    uint32_t *height,
    ANARIDataType *pixelType)
try {
  *width = 0;
  *height = 0;
  *pixelType = ANARI_UNKNOWN;
  auto *frame = (Frame *)checked(handle, "anariMapFrame", {ANARI_FRAME});
  if (!frame)
    return nullptr;
  return frame->map(channel, *width, *height, *pixelType);
} catch (...) {
  reportException("anariMapFrame");
  return nullptr;
}

void Device::frameBufferUnmap(ANARIFrame handle, const char *channel)
try {
  if (auto *frame = (Frame *)checked(handle, "anariUnmapFrame", {ANARI_FRAME}))
    frame->unmap(channel);
} catch (...) {
  reportException("anariUnmapFrame");
  return;
}

} // namespace prism
