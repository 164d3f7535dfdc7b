#include "ForwardingDevice.h"

namespace prism {

ForwardingDevice::ForwardingDevice(ANARILibrary library)
    : anari::DeviceImpl(library)
{}

ANARIObject ForwardingDevice::innerHandle(ANARIObject object) const
{
  return handleIsDevice(object) ? (ANARIObject)m_inner : object;
}

bool ForwardingDevice::admits(ANARIObject, const char *)
{
  return true;
}

void ForwardingDevice::beforeCreating(ANARIDataType) {}

bool ForwardingDevice::forwards(ANARIObject object, const char *function)
{
  return m_inner && (handleIsDevice(object) || admits(object, function));
}

const char *ForwardingDevice::newFunctionName(ANARIDataType type)
{
  switch (type) {
  case ANARI_ARRAY1D:
    return "anariNewArray1D";
  case ANARI_ARRAY2D:
    return "anariNewArray2D";
  case ANARI_ARRAY3D:
    return "anariNewArray3D";
  case ANARI_GEOMETRY:
    return "anariNewGeometry";
  case ANARI_MATERIAL:
    return "anariNewMaterial";
  case ANARI_SAMPLER:
    return "anariNewSampler";
  case ANARI_SURFACE:
    return "anariNewSurface";
  case ANARI_SPATIAL_FIELD:
    return "anariNewSpatialField";
  case ANARI_VOLUME:
    return "anariNewVolume";
  case ANARI_LIGHT:
    return "anariNewLight";
  case ANARI_GROUP:
    return "anariNewGroup";
  case ANARI_INSTANCE:
    return "anariNewInstance";
  case ANARI_WORLD:
    return "anariNewWorld";
  case ANARI_CAMERA:
    return "anariNewCamera";
  case ANARI_RENDERER:
    return "anariNewRenderer";
  case ANARI_FRAME:
    return "anariNewFrame";
  default:
    return "anariNewObject";
  }
}

const char *ForwardingDevice::mapParameterArrayFunctionName(
    ANARIDataType arrayType)
{
  return arrayType == ANARI_ARRAY1D   ? "anariMapParameterArray1D"
         : arrayType == ANARI_ARRAY2D ? "anariMapParameterArray2D"
                                      : "anariMapParameterArray3D";
}

// Creation: each call to its hook //////////////////////////////////////////

ANARIArray1D ForwardingDevice::newArray1D(const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType elementType,
    uint64_t numItems1)
{
  const uint64_t items[3] = {numItems1, 0, 0};
  beforeCreating(ANARI_ARRAY1D);
  return (ANARIArray1D)newArrayOf(
      ANARI_ARRAY1D, appMemory, deleter, userData, elementType, items);
}

ANARIArray2D ForwardingDevice::newArray2D(const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType elementType,
    uint64_t numItems1,
    uint64_t numItems2)
{
  const uint64_t items[3] = {numItems1, numItems2, 0};
  beforeCreating(ANARI_ARRAY2D);
  return (ANARIArray2D)newArrayOf(
      ANARI_ARRAY2D, appMemory, deleter, userData, elementType, items);
}

ANARIArray3D ForwardingDevice::newArray3D(const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType elementType,
    uint64_t numItems1,
    uint64_t numItems2,
    uint64_t numItems3)
{
  const uint64_t items[3] = {numItems1, numItems2, numItems3};
  beforeCreating(ANARI_ARRAY3D);
  return (ANARIArray3D)newArrayOf(
      ANARI_ARRAY3D, appMemory, deleter, userData, elementType, items);
}

ANARIGeometry ForwardingDevice::newGeometry(const char *subtype)
{
  beforeCreating(ANARI_GEOMETRY);
  return (ANARIGeometry)newObjectOf(ANARI_GEOMETRY, subtype);
}

ANARIMaterial ForwardingDevice::newMaterial(const char *subtype)
{
  beforeCreating(ANARI_MATERIAL);
  return (ANARIMaterial)newObjectOf(ANARI_MATERIAL, subtype);
}

ANARISampler ForwardingDevice::newSampler(const char *subtype)
{
  beforeCreating(ANARI_SAMPLER);
  return (ANARISampler)newObjectOf(ANARI_SAMPLER, subtype);
}

ANARISurface ForwardingDevice::newSurface()
{
  beforeCreating(ANARI_SURFACE);
  return (ANARISurface)newObjectOf(ANARI_SURFACE, nullptr);
}

ANARISpatialField ForwardingDevice::newSpatialField(const char *subtype)
{
  beforeCreating(ANARI_SPATIAL_FIELD);
  return (ANARISpatialField)newObjectOf(ANARI_SPATIAL_FIELD, subtype);
}

ANARIVolume ForwardingDevice::newVolume(const char *subtype)
{
  beforeCreating(ANARI_VOLUME);
  return (ANARIVolume)newObjectOf(ANARI_VOLUME, subtype);
}

ANARILight ForwardingDevice::newLight(const char *subtype)
{
  beforeCreating(ANARI_LIGHT);
  return (ANARILight)newObjectOf(ANARI_LIGHT, subtype);
}

ANARIGroup ForwardingDevice::newGroup()
{
  beforeCreating(ANARI_GROUP);
  return (ANARIGroup)newObjectOf(ANARI_GROUP, nullptr);
}

ANARIInstance ForwardingDevice::newInstance(const char *subtype)
{
  beforeCreating(ANARI_INSTANCE);
  return (ANARIInstance)newObjectOf(ANARI_INSTANCE, subtype);
}

ANARIWorld ForwardingDevice::newWorld()
{
  beforeCreating(ANARI_WORLD);
  return (ANARIWorld)newObjectOf(ANARI_WORLD, nullptr);
}

ANARICamera ForwardingDevice::newCamera(const char *subtype)
{
  beforeCreating(ANARI_CAMERA);
  return (ANARICamera)newObjectOf(ANARI_CAMERA, subtype);
}

ANARIRenderer ForwardingDevice::newRenderer(const char *subtype)
{
  beforeCreating(ANARI_RENDERER);
  return (ANARIRenderer)newObjectOf(ANARI_RENDERER, subtype);
}

ANARIFrame ForwardingDevice::newFrame()
{
  beforeCreating(ANARI_FRAME);
  return (ANARIFrame)newObjectOf(ANARI_FRAME, nullptr);
}

void *ForwardingDevice::mapParameterArray1D(ANARIObject object,
    const char *name,
    ANARIDataType elementType,
    uint64_t numElements1,
    uint64_t *elementStride)
{
  const uint64_t items[3] = {numElements1, 0, 0};
  return mapParameterArrayOf(
      object, name, ANARI_ARRAY1D, elementType, items, elementStride);
}

void *ForwardingDevice::mapParameterArray2D(ANARIObject object,
    const char *name,
    ANARIDataType elementType,
    uint64_t numElements1,
    uint64_t numElements2,
    uint64_t *elementStride)
{
  const uint64_t items[3] = {numElements1, numElements2, 0};
  return mapParameterArrayOf(
      object, name, ANARI_ARRAY2D, elementType, items, elementStride);
}

void *ForwardingDevice::mapParameterArray3D(ANARIObject object,
    const char *name,
    ANARIDataType elementType,
    uint64_t numElements1,
    uint64_t numElements2,
    uint64_t numElements3,
    uint64_t *elementStride)
{
  const uint64_t items[3] = {numElements1, numElements2, numElements3};
  return mapParameterArrayOf(
      object, name, ANARI_ARRAY3D, elementType, items, elementStride);
}

// The hooks' forwarding ////////////////////////////////////////////////////

ANARIObject ForwardingDevice::newObjectOf(
    ANARIDataType type, const char *subtype)
{
  anari::DeviceImpl *d = m_inner;
  if (!d)
    return nullptr;
  switch (type) {
  case ANARI_GEOMETRY:
    return d->newGeometry(subtype);
  case ANARI_MATERIAL:
    return d->newMaterial(subtype);
  case ANARI_SAMPLER:
    return d->newSampler(subtype);
  case ANARI_SURFACE:
    return d->newSurface();
  case ANARI_SPATIAL_FIELD:
    return d->newSpatialField(subtype);
  case ANARI_VOLUME:
    return d->newVolume(subtype);
  case ANARI_LIGHT:
    return d->newLight(subtype);
  case ANARI_GROUP:
    return d->newGroup();
  case ANARI_INSTANCE:
    return d->newInstance(subtype);
  case ANARI_WORLD:
    return d->newWorld();
  case ANARI_CAMERA:
    return d->newCamera(subtype);
  case ANARI_RENDERER:
    return d->newRenderer(subtype);
  case ANARI_FRAME:
    return d->newFrame();
  default:
    return nullptr;
  }
}

ANARIArray ForwardingDevice::newArrayOf(ANARIDataType arrayType,
    const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType elementType,
    const uint64_t items[3])
{
  if (!m_inner)
    return nullptr;
  if (arrayType == ANARI_ARRAY1D) {
    return m_inner->newArray1D(
        appMemory, deleter, userData, elementType, items[0]);
  }
  if (arrayType == ANARI_ARRAY2D) {
    return m_inner->newArray2D(
        appMemory, deleter, userData, elementType, items[0], items[1]);
  }
  return m_inner->newArray3D(
      appMemory, deleter, userData, elementType, items[0], items[1], items[2]);
}

void *ForwardingDevice::mapParameterArrayOf(ANARIObject object,
    const char *name,
    ANARIDataType arrayType,
    ANARIDataType elementType,
    const uint64_t items[3],
    uint64_t *elementStride)
{
  if (!forwards(object, mapParameterArrayFunctionName(arrayType)))
    return nullptr;
  object = innerHandle(object);
  if (arrayType == ANARI_ARRAY1D) {
    return m_inner->mapParameterArray1D(
        object, name, elementType, items[0], elementStride);
  }
  if (arrayType == ANARI_ARRAY2D) {
    return m_inner->mapParameterArray2D(
        object, name, elementType, items[0], items[1], elementStride);
  }
  return m_inner->mapParameterArray3D(
      object, name, elementType, items[0], items[1], items[2], elementStride);
}

// Forwarded as they are ////////////////////////////////////////////////////

ANARIObject ForwardingDevice::newObject(
    const char *objectType, const char *subtype)
{
  beforeCreating(ANARI_OBJECT);
  return m_inner ? m_inner->newObject(objectType, subtype) : nullptr;
}

void ForwardingDevice::setParameter(
    ANARIObject object, const char *name, ANARIDataType type, const void *mem)
{
  if (forwards(object, "anariSetParameter"))
    m_inner->setParameter(innerHandle(object), name, type, mem);
}

void ForwardingDevice::unsetParameter(ANARIObject object, const char *name)
{
  if (forwards(object, "anariUnsetParameter"))
    m_inner->unsetParameter(innerHandle(object), name);
}

void ForwardingDevice::unsetAllParameters(ANARIObject object)
{
  if (forwards(object, "anariUnsetAllParameters"))
    m_inner->unsetAllParameters(innerHandle(object));
}

void ForwardingDevice::unmapParameterArray(ANARIObject object, const char *name)
{
  if (forwards(object, "anariUnmapParameterArray"))
    m_inner->unmapParameterArray(innerHandle(object), name);
}

void ForwardingDevice::commitParameters(ANARIObject object)
{
  if (forwards(object, "anariCommitParameters"))
    m_inner->commitParameters(innerHandle(object));
}

void ForwardingDevice::release(ANARIObject object)
{
  if (!handleIsDevice(object) && forwards(object, "anariRelease"))
    m_inner->release(object);
}

void ForwardingDevice::retain(ANARIObject object)
{
  if (!handleIsDevice(object) && forwards(object, "anariRetain"))
    m_inner->retain(object);
}

void *ForwardingDevice::mapArray(ANARIArray array)
{
  return forwards(array, "anariMapArray") ? m_inner->mapArray(array) : nullptr;
}

void ForwardingDevice::unmapArray(ANARIArray array)
{
  if (forwards(array, "anariUnmapArray"))
    m_inner->unmapArray(array);
}

int ForwardingDevice::getProperty(ANARIObject object,
    const char *name,
    ANARIDataType type,
    void *mem,
    uint64_t size,
    ANARIWaitMask mask)
{
  if (!forwards(object, "anariGetProperty"))
    return 0;
  return m_inner->getProperty(innerHandle(object), name, type, mem, size, mask);
}

const char **ForwardingDevice::getObjectSubtypes(ANARIDataType objectType)
{
  return m_inner ? m_inner->getObjectSubtypes(objectType) : nullptr;
}

const void *ForwardingDevice::getObjectInfo(ANARIDataType objectType,
    const char *objectSubtype,
    const char *infoName,
    ANARIDataType infoType)
{
  return m_inner ? m_inner->getObjectInfo(
             objectType, objectSubtype, infoName, infoType)
                 : nullptr;
}

const void *ForwardingDevice::getParameterInfo(ANARIDataType objectType,
    const char *objectSubtype,
    const char *parameterName,
    ANARIDataType parameterType,
    const char *infoName,
    ANARIDataType infoType)
{
  if (!m_inner)
    return nullptr;
  return m_inner->getParameterInfo(objectType,
      objectSubtype,
      parameterName,
      parameterType,
      infoName,
      infoType);
}

const void *ForwardingDevice::frameBufferMap(ANARIFrame frame,
    const char *channel,
    uint32_t *width,
    uint32_t *height,
    ANARIDataType *pixelType)
{
  if (forwards(frame, "anariMapFrame"))
    return m_inner->frameBufferMap(frame, channel, width, height, pixelType);
  *width = *height = 0;
  *pixelType = ANARI_UNKNOWN;
  return nullptr;
}

void ForwardingDevice::frameBufferUnmap(ANARIFrame frame, const char *channel)
{
  if (forwards(frame, "anariUnmapFrame"))
    m_inner->frameBufferUnmap(frame, channel);
}

void ForwardingDevice::renderFrame(ANARIFrame frame)
{
  if (forwards(frame, "anariRenderFrame"))
    m_inner->renderFrame(frame);
}

int ForwardingDevice::frameReady(ANARIFrame frame, ANARIWaitMask mask)
{
  return forwards(frame, "anariFrameReady") ? m_inner->frameReady(frame, mask)
                                            : 0;
}

void ForwardingDevice::discardFrame(ANARIFrame frame)
{
  if (forwards(frame, "anariDiscardFrame"))
    m_inner->discardFrame(frame);
}

} // namespace prism
