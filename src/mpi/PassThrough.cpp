// wrappedLibrary / wrappedDevice: the prism_mpi device as a pass-through
// compositing device (Wald et al. 2024, section 5.1). Every object call
// goes to a device of another ANARI library, with that device's handles;
// anariRenderFrame renders locally on it (linear color and depth, no
// background) and composites the processes' pixels by depth, as composite
// mode does with the built-in core.
#include "DataParallelDevice.h"

#include "DepthCompositor.h"
#include "PoliteWait.h"

#include "frame/PixelFormat.h"

#include "anari/frontend/type_utility.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <optional>
#include <type_traits>

namespace prism::mpi {
namespace {

// The wrapped library's status callback: its messages reach the
// application as this device's.
void forwardStatus(const void *userPtr,
    ANARIDevice,
    ANARIObject source,
    ANARIDataType sourceType,
    ANARIStatusSeverity severity,
    ANARIStatusCode code,
    const char *message)
{
  if (userPtr) {
    ((const DataParallelDevice *)userPtr)
        ->reportStatus(
            source, sourceType, severity, code, message ? message : "");
  }
}

const float4 kTransparent{0.f, 0.f, 0.f, 0.f};
const float4 kDefaultBackground{0.f, 0.f, 0.f, 1.f}; // the spec's

// Gives `renderer` of `device` a transparent background.
void clearBackground(anari::DeviceImpl &device, ANARIObject renderer)
{
  device.setParameter(
      renderer, "background", ANARI_FLOAT32_VEC4, &kTransparent);
}

} // namespace

// The choice /////////////////////////////////////////////////////////////////

anari::DeviceImpl *DataParallelDevice::wrapped()
{
  if (!m_wrapChosen.load())
    chooseWrapped();
  return m_wrappedDevice;
}

void DataParallelDevice::chooseWrapped()
{
  std::lock_guard lock(m_wrapMutex);
  if (m_wrapChosen.load())
    return;
  if (!m_wrappedSpec.empty()) {
    std::string error;
    auto library = frontend::LoadedLibrary::load(
        m_wrappedSpec, &forwardStatus, this, "prism_mpi", error);
    anari::DeviceImpl *device = nullptr;
    if (!library) {
      reportBadDeviceParameter("device: cannot load wrappedLibrary '"
                               + m_wrappedSpec + "' (" + error
                               + "); the built-in prism core renders instead");
    } else {
      try {
        device = (anari::DeviceImpl *)library->library().newDevice(
            m_wrappedSubtype.c_str());
      } catch (...) {
        device = nullptr;
      }
      if (!device) {
        reportBadDeviceParameter("device: wrappedLibrary '" + m_wrappedSpec
                                 + "' has no device of subtype '"
                                 + m_wrappedSubtype
                                 + "' (wrappedDevice); the built-in prism"
                                   " core renders instead");
      }
    }
    if (device) {
      for (const DeviceParameter &p : m_stagedDeviceParameters) {
        device->setParameter(
            (ANARIObject)device, p.name.c_str(), p.type, p.value.data());
      }
      if (!m_stagedDeviceParameters.empty())
        device->commitParameters((ANARIObject)device);
      m_wrappedLibrary = std::move(library);
      m_wrappedDevice = device;
    }
  }
  m_stagedDeviceParameters.clear();
  m_wrapChosen.store(true);
}

void DataParallelDevice::setWrapParameter(
    const std::string &name, ANARIDataType type, const void *mem)
{
  if (type != ANARI_STRING || !mem) {
    reportBadDeviceParameter(
        "device: parameter '" + name + "' must be a STRING (got "
        + (mem ? anari::toString(type) : "NULL") + "); it is ignored");
    return;
  }
  std::string value = (const char *)mem;
  std::lock_guard lock(m_wrapMutex);
  if (m_wrapChosen.load()) {
    reportBadDeviceParameter("device: parameter '" + name
                             + "' must be set before the device's first"
                               " object is created; it is ignored (objects"
                               " render with "
                             + (m_wrappedDevice ? "library '"
                                                      + m_wrappedLibrary->name()
                                                      + "'"
                                                : "the built-in prism core")
                             + ")");
    return;
  }
  if (name == "wrappedLibrary")
    m_wrappedSpec = value;
  else
    m_wrappedSubtype = value.empty() ? "default" : value;
}

void DataParallelDevice::passDeviceParameter(
    const std::string &name, ANARIDataType type, const void *mem)
{
  // The wrapped device reports through this device's callback (above).
  if (name == "statusCallback" || name == "statusCallbackUserData")
    return;
  std::lock_guard lock(m_wrapMutex);
  if (m_wrapChosen.load()) {
    if (m_wrappedDevice) {
      m_wrappedDevice->setParameter(
          (ANARIObject)m_wrappedDevice, name.c_str(), type, mem);
    }
    return;
  }
  // Kept for the wrapped device, if one is chosen: values only (no object
  // exists before the choice).
  DeviceParameter p{name, type, {}};
  if (!mem || anari::isObject(type))
    return;
  if (type == ANARI_STRING) {
    const char *text = (const char *)mem;
    p.value.assign(text, text + std::strlen(text) + 1);
  } else {
    const size_t bytes = anari::sizeOf(type);
    if (bytes == 0)
      return;
    p.value.assign(
        (const unsigned char *)mem, (const unsigned char *)mem + bytes);
  }
  std::erase_if(m_stagedDeviceParameters,
      [&](const DeviceParameter &old) { return old.name == name; });
  m_stagedDeviceParameters.push_back(std::move(p));
}

bool DataParallelDevice::liveWrapped(ANARIObject object, const char *call)
{
  {
    std::lock_guard lock(m_stateMutex);
    if (object && m_wrappedObjects.count(object))
      return true;
  }
  // Never forwarded: another library may not check its handles.
  reportStatus(object,
      ANARI_OBJECT,
      ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      std::string(call)
          + ": the handle is no live object of this device (NULL, released"
            " or another device's); the call is ignored");
  return false;
}

// Calls forwarded as they are /////////////////////////////////////////////////

ANARIArray1D DataParallelDevice::newArray1D(const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType elementType,
    uint64_t numItems1)
{
  if (anari::DeviceImpl *device = wrapped()) {
    return created(device->newArray1D(
                       appMemory, deleter, userData, elementType, numItems1),
        ANARI_ARRAY1D);
  }
  return Device::newArray1D(
      appMemory, deleter, userData, elementType, numItems1);
}

ANARIArray2D DataParallelDevice::newArray2D(const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType elementType,
    uint64_t numItems1,
    uint64_t numItems2)
{
  if (anari::DeviceImpl *device = wrapped()) {
    return created(
        device->newArray2D(
            appMemory, deleter, userData, elementType, numItems1, numItems2),
        ANARI_ARRAY2D);
  }
  return Device::newArray2D(
      appMemory, deleter, userData, elementType, numItems1, numItems2);
}

ANARIArray3D DataParallelDevice::newArray3D(const void *appMemory,
    ANARIMemoryDeleter deleter,
    const void *userData,
    ANARIDataType elementType,
    uint64_t numItems1,
    uint64_t numItems2,
    uint64_t numItems3)
{
  if (anari::DeviceImpl *device = wrapped()) {
    return created(device->newArray3D(appMemory,
                       deleter,
                       userData,
                       elementType,
                       numItems1,
                       numItems2,
                       numItems3),
        ANARI_ARRAY3D);
  }
  return Device::newArray3D(appMemory,
      deleter,
      userData,
      elementType,
      numItems1,
      numItems2,
      numItems3);
}

#define PRISM_MPI_FORWARD_NEW(Handle, Name, Type)      \
  Handle DataParallelDevice::Name(const char *subtype) \
  {                                                    \
    if (anari::DeviceImpl *device = wrapped())         \
      return created(device->Name(subtype), Type);     \
    return Device::Name(subtype);                      \
  }
PRISM_MPI_FORWARD_NEW(ANARIGeometry, newGeometry, ANARI_GEOMETRY)
PRISM_MPI_FORWARD_NEW(ANARIMaterial, newMaterial, ANARI_MATERIAL)
PRISM_MPI_FORWARD_NEW(ANARISampler, newSampler, ANARI_SAMPLER)
PRISM_MPI_FORWARD_NEW(ANARISpatialField, newSpatialField, ANARI_SPATIAL_FIELD)
PRISM_MPI_FORWARD_NEW(ANARIVolume, newVolume, ANARI_VOLUME)
PRISM_MPI_FORWARD_NEW(ANARILight, newLight, ANARI_LIGHT)
PRISM_MPI_FORWARD_NEW(ANARIInstance, newInstance, ANARI_INSTANCE)
PRISM_MPI_FORWARD_NEW(ANARICamera, newCamera, ANARI_CAMERA)
#undef PRISM_MPI_FORWARD_NEW

ANARISurface DataParallelDevice::newSurface()
{
  if (anari::DeviceImpl *device = wrapped())
    return created(device->newSurface(), ANARI_SURFACE);
  return Device::newSurface();
}

ANARIGroup DataParallelDevice::newGroup()
{
  if (anari::DeviceImpl *device = wrapped())
    return created(device->newGroup(), ANARI_GROUP);
  return Device::newGroup();
}

ANARIObject DataParallelDevice::newObject(
    const char *objectType, const char *subtype)
{
  if (anari::DeviceImpl *device = wrapped())
    return created(device->newObject(objectType, subtype), ANARI_OBJECT);
  return Device::newObject(objectType, subtype);
}

ANARIRenderer DataParallelDevice::newRenderer(const char *subtype)
{
  anari::DeviceImpl *device = wrapped();
  if (!device)
    return Device::newRenderer(subtype);
  ANARIRenderer renderer =
      created(device->newRenderer(subtype), ANARI_RENDERER);
  if (renderer) {
    // Committed at once: a renderer the application never commits must
    // not render the spec's opaque black either.
    clearBackground(*device, renderer);
    device->commitParameters(renderer);
    std::lock_guard lock(m_stateMutex);
    m_wrappedRenderers[renderer] = WrappedRenderer{
        subtype ? subtype : "default", kDefaultBackground, kDefaultBackground};
  }
  return renderer;
}

void *DataParallelDevice::mapParameterArray1D(ANARIObject object,
    const char *name,
    ANARIDataType elementType,
    uint64_t numElements1,
    uint64_t *elementStride)
{
  if (anari::DeviceImpl *device = wrapped()) {
    if (!liveWrapped(object, "anariMapParameterArray1D"))
      return nullptr;
    return device->mapParameterArray1D(
        object, name, elementType, numElements1, elementStride);
  }
  return Device::mapParameterArray1D(
      object, name, elementType, numElements1, elementStride);
}

void *DataParallelDevice::mapParameterArray2D(ANARIObject object,
    const char *name,
    ANARIDataType elementType,
    uint64_t numElements1,
    uint64_t numElements2,
    uint64_t *elementStride)
{
  if (anari::DeviceImpl *device = wrapped()) {
    if (!liveWrapped(object, "anariMapParameterArray2D"))
      return nullptr;
    return device->mapParameterArray2D(
        object, name, elementType, numElements1, numElements2, elementStride);
  }
  return Device::mapParameterArray2D(
      object, name, elementType, numElements1, numElements2, elementStride);
}

void *DataParallelDevice::mapParameterArray3D(ANARIObject object,
    const char *name,
    ANARIDataType elementType,
    uint64_t numElements1,
    uint64_t numElements2,
    uint64_t numElements3,
    uint64_t *elementStride)
{
  if (anari::DeviceImpl *device = wrapped()) {
    if (!liveWrapped(object, "anariMapParameterArray3D"))
      return nullptr;
    return device->mapParameterArray3D(object,
        name,
        elementType,
        numElements1,
        numElements2,
        numElements3,
        elementStride);
  }
  return Device::mapParameterArray3D(object,
      name,
      elementType,
      numElements1,
      numElements2,
      numElements3,
      elementStride);
}

void DataParallelDevice::unmapParameterArray(
    ANARIObject object, const char *name)
{
  if (anari::DeviceImpl *device = wrapped()) {
    if (liveWrapped(object, "anariUnmapParameterArray"))
      device->unmapParameterArray(object, name);
  } else
    Device::unmapParameterArray(object, name);
}

void DataParallelDevice::retain(ANARIObject object)
{
  if (object == (ANARIObject)this_device() || !wrapped()) {
    Device::retain(object);
    return;
  }
  {
    std::lock_guard lock(m_stateMutex);
    auto it = m_wrappedObjects.find(object);
    if (it != m_wrappedObjects.end())
      it->second.references++;
  }
  if (liveWrapped(object, "anariRetain"))
    m_wrappedDevice->retain(object);
}

void *DataParallelDevice::mapArray(ANARIArray array)
{
  if (anari::DeviceImpl *device = wrapped())
    return liveWrapped(array, "anariMapArray") ? device->mapArray(array)
                                               : nullptr;
  return Device::mapArray(array);
}

void DataParallelDevice::unmapArray(ANARIArray array)
{
  if (anari::DeviceImpl *device = wrapped()) {
    if (liveWrapped(array, "anariUnmapArray"))
      device->unmapArray(array);
  } else
    Device::unmapArray(array);
}

// Introspection answers for the device objects are made on: the core's
// until a wrapped device is chosen (asking does not choose).
const char **DataParallelDevice::getObjectSubtypes(ANARIDataType objectType)
{
  if (!wrapOpen() && m_wrappedDevice)
    return m_wrappedDevice->getObjectSubtypes(objectType);
  return Device::getObjectSubtypes(objectType);
}

const void *DataParallelDevice::getObjectInfo(ANARIDataType objectType,
    const char *objectSubtype,
    const char *infoName,
    ANARIDataType infoType)
{
  if (!wrapOpen() && m_wrappedDevice) {
    return m_wrappedDevice->getObjectInfo(
        objectType, objectSubtype, infoName, infoType);
  }
  return Device::getObjectInfo(objectType, objectSubtype, infoName, infoType);
}

const void *DataParallelDevice::getParameterInfo(ANARIDataType objectType,
    const char *objectSubtype,
    const char *parameterName,
    ANARIDataType parameterType,
    const char *infoName,
    ANARIDataType infoType)
{
  if (!wrapOpen() && m_wrappedDevice) {
    return m_wrappedDevice->getParameterInfo(objectType,
        objectSubtype,
        parameterName,
        parameterType,
        infoName,
        infoType);
  }
  return Device::getParameterInfo(objectType,
      objectSubtype,
      parameterName,
      parameterType,
      infoName,
      infoType);
}

void DataParallelDevice::frameBufferUnmap(ANARIFrame frame, const char *channel)
{
  anari::DeviceImpl *device = wrapped();
  if (!device) {
    Device::frameBufferUnmap(frame, channel);
    return;
  }
  {
    // Channels this device assembled were never mapped on the wrapped one.
    std::lock_guard lock(m_stateMutex);
    auto it = m_frames.find(frame);
    if (it != m_frames.end() && channel && it->second.assembled.count(channel))
      return;
  }
  if (liveWrapped(frame, "anariUnmapFrame"))
    device->frameBufferUnmap(frame, channel);
}

int DataParallelDevice::frameReady(ANARIFrame frame, ANARIWaitMask mask)
{
  if (anari::DeviceImpl *device = wrapped()) {
    return liveWrapped(frame, "anariFrameReady")
               ? device->frameReady(frame, mask)
               : 0;
  }
  return Device::frameReady(frame, mask);
}

void DataParallelDevice::discardFrame(ANARIFrame frame)
{
  if (anari::DeviceImpl *device = wrapped()) {
    if (liveWrapped(frame, "anariDiscardFrame"))
      device->discardFrame(frame);
  } else
    Device::discardFrame(frame);
}

// Parameters the wrapped device sees otherwise ///////////////////////////////

bool DataParallelDevice::setWrappedParameter(ANARIObject object,
    const std::string &name,
    ANARIDataType type,
    const void *mem)
{
  std::lock_guard lock(m_stateMutex);
  auto renderer = m_wrappedRenderers.find(object);
  if (renderer != m_wrappedRenderers.end() && name == "background") {
    float4 &background = renderer->second.stagedBackground;
    if (type == ANARI_FLOAT32_VEC4 && mem) {
      std::memcpy(&background, mem, sizeof(float4));
      return true;
    }
    if (type == ANARI_FLOAT32_VEC3 && mem) {
      std::memcpy(&background, mem, 3 * sizeof(float));
      background.w = 1.f;
      return true;
    }
    // An image (or a wrong type, for the wrapped device to report): every
    // process renders it; nothing is added under the composite.
    background = kTransparent;
    return false;
  }
  auto frame = m_frames.find(object);
  if (frame == m_frames.end())
    return false;
  WrappedFrameParameters &p = frame->second.staged;
  const ANARIObject value =
      anari::isObject(type) && mem ? *(const ANARIObject *)mem : nullptr;
  for (int c = 0; c < kChannelCount; c++) {
    if (name != kChannelNames[c])
      continue;
    const ANARIDataType channelType = type == ANARI_DATA_TYPE && mem
                                          ? *(const ANARIDataType *)mem
                                          : ANARI_UNKNOWN;
    if (c >= 2) {
      // The others the wrapped frame renders in the application's type.
      p.channelTypes[c] = channelType;
      return false;
    }
    // Color and depth stay linear float on the wrapped frame; rank 0
    // converts the composite to the application's type.
    const bool valid = c == 0 ? isValidColorFormat(channelType)
                              : isValidDepthFormat(channelType);
    if (!valid) {
      reportStatus(object,
          ANARI_FRAME,
          ANARI_SEVERITY_ERROR,
          ANARI_STATUS_INVALID_ARGUMENT,
          std::string("anariSetParameter: frame parameter '") + name
              + "' must be a DATA_TYPE naming a " + (c == 0 ? "color" : "depth")
              + " pixel type (got "
              + anari::toString(type == ANARI_DATA_TYPE ? channelType : type)
              + "); it is ignored");
      return true;
    }
    p.channelTypes[c] = channelType;
    return true;
  }
  if (name == "size") {
    uint32_t size[2] = {0, 0};
    if (type == ANARI_UINT32_VEC2 && mem)
      std::memcpy(size, mem, sizeof(size));
    p.width = size[0];
    p.height = size[1];
  } else if (name == "renderer") {
    p.renderer = type == ANARI_RENDERER ? value : nullptr;
  } else if (name == "world") {
    p.world = type == ANARI_WORLD && value;
  } else if (name == "camera") {
    p.camera = type == ANARI_CAMERA && value;
  }
  return false;
}

bool DataParallelDevice::unsetWrappedParameter(
    ANARIObject object, const std::string &name)
{
  std::lock_guard lock(m_stateMutex);
  auto renderer = m_wrappedRenderers.find(object);
  if (renderer != m_wrappedRenderers.end() && name == "background") {
    renderer->second.stagedBackground = kDefaultBackground;
    clearBackground(*m_wrappedDevice, object);
    return true;
  }
  auto frame = m_frames.find(object);
  if (frame == m_frames.end())
    return false;
  WrappedFrameParameters &p = frame->second.staged;
  for (int c = 0; c < kChannelCount; c++) {
    if (name == kChannelNames[c]) {
      p.channelTypes[c] = ANARI_UNKNOWN;
      return c < 2; // the wrapped frame keeps linear color and depth
    }
  }
  if (name == "size")
    p.width = p.height = 0;
  else if (name == "renderer")
    p.renderer = nullptr;
  else if (name == "world")
    p.world = false;
  else if (name == "camera")
    p.camera = false;
  return false;
}

void DataParallelDevice::unsetAllWrappedParameters(ANARIObject object)
{
  if (!liveWrapped(object, "anariUnsetAllParameters"))
    return;
  anari::DeviceImpl &device = *m_wrappedDevice;
  device.unsetAllParameters(object);
  std::lock_guard lock(m_stateMutex);
  auto renderer = m_wrappedRenderers.find(object);
  if (renderer != m_wrappedRenderers.end()) {
    renderer->second.stagedBackground = kDefaultBackground;
    clearBackground(device, object);
  }
  auto frame = m_frames.find(object);
  if (frame != m_frames.end()) {
    frame->second.staged = {};
    const ANARIDataType color = ANARI_FLOAT32_VEC4;
    const ANARIDataType depth = ANARI_FLOAT32;
    device.setParameter(object, "channel.color", ANARI_DATA_TYPE, &color);
    device.setParameter(object, "channel.depth", ANARI_DATA_TYPE, &depth);
  }
}

void DataParallelDevice::commitWrapped(ANARIObject object)
{
  {
    std::lock_guard lock(m_stateMutex);
    auto renderer = m_wrappedRenderers.find(object);
    if (renderer != m_wrappedRenderers.end())
      renderer->second.background = renderer->second.stagedBackground;
    auto frame = m_frames.find(object);
    if (frame != m_frames.end())
      frame->second.committed = frame->second.staged;
  }
  if (liveWrapped(object, "anariCommitParameters"))
    m_wrappedDevice->commitParameters(object);
}

void DataParallelDevice::releaseWrapped(ANARIObject object)
{
  if (!liveWrapped(object, "anariRelease"))
    return;
  {
    // The application's last reference gone: so is what this device kept
    // (renderers' backgrounds stay: a frame may still render with one).
    std::lock_guard lock(m_stateMutex);
    auto it = m_wrappedObjects.find(object);
    if (it != m_wrappedObjects.end() && --it->second.references <= 0) {
      m_wrappedObjects.erase(it);
      m_frames.erase(object);
      m_worlds.erase(object);
    }
  }
  m_wrappedDevice->release(object);
}

// Rendering //////////////////////////////////////////////////////////////////

FrameDescriptor DataParallelDevice::describeWrapped(
    const FrameState &state) const
{
  FrameDescriptor d;
  d.frameIndex = state.index;
  d.renderIndex = state.renders;
  d.mode = uint32_t(RenderMode::Composite);
  const WrappedFrameParameters &p = state.committed;
  d.width = p.width;
  d.height = p.height;
  d.valid = p.world && p.camera && p.renderer && p.width && p.height ? 1 : 0;
  for (int c = 0; c < kChannelCount; c++)
    d.channelTypes[c] = p.channelTypes[c];
  auto renderer = m_wrappedRenderers.find(p.renderer);
  if (renderer != m_wrappedRenderers.end()) {
    const std::string &subtype = renderer->second.subtype;
    std::memcpy(d.renderer,
        subtype.data(),
        std::min(subtype.size(), sizeof(d.renderer) - 1));
  }
  return d;
}

void DataParallelDevice::renderWrapped(ANARIFrame handle)
try {
  FrameState unknownFrame; // a stale handle still answers the agreement
  unknownFrame.index = ~0ull;
  FrameState *state = &unknownFrame;
  FrameDescriptor descriptor;
  {
    std::lock_guard lock(m_stateMutex);
    auto it = m_frames.find(handle);
    if (it != m_frames.end())
      state = &it->second;
    state->assembled.clear();
    state->bytesSent = 0;
    descriptor = describeWrapped(*state);
  }
  const bool known = state != &unknownFrame;
  const bool collective = m_session.usable();
  const MPI_Comm communicator = state->communicator.committed;
  bool allValid = descriptor.valid != 0;
  if (collective) {
    const RendezvousResult meeting =
        m_rendezvous.meet(descriptor, communicator, m_timeoutSeconds);
    if (!meeting.render) {
      reportStatus(handle,
          ANARI_FRAME,
          ANARI_SEVERITY_ERROR,
          ANARI_STATUS_INVALID_OPERATION,
          "anariRenderFrame: nothing is rendered: " + meeting.problem);
      return;
    }
    state->renders++;
    allValid = meeting.allValid;
  }
  if (!known) {
    reportStatus(handle,
        ANARI_FRAME,
        ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_ARGUMENT,
        "anariRenderFrame: the handle is no live frame of this device");
    return;
  }
  if (!allValid) {
    // The wrapped device reports what the frame lacks.
    m_wrappedDevice->renderFrame(handle);
    m_wrappedDevice->frameReady(handle, ANARI_WAIT);
    return;
  }
  if (m_mode != RenderMode::Composite && m_modeExplicit
      && !m_wrappedModeWarned) {
    m_wrappedModeWarned = true;
    reportStatus(handle,
        ANARI_FRAME,
        ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_OPERATION,
        std::string("anariRenderFrame: mode '") + toString(m_mode)
            + "' needs the built-in prism core; frames of wrappedLibrary '"
            + m_wrappedLibrary->name() + "' are composited instead");
  }
  renderWrappedComposited(
      handle, *state, collective ? communicator : MPI_COMM_NULL);
} catch (const std::exception &e) {
  reportStatus(handle,
      ANARI_FRAME,
      ANARI_SEVERITY_ERROR,
      ANARI_STATUS_UNKNOWN_ERROR,
      std::string("anariRenderFrame: ") + e.what());
}

void DataParallelDevice::renderWrappedComposited(
    ANARIFrame handle, FrameState &state, MPI_Comm communicator)
{
  anari::DeviceImpl &device = *m_wrappedDevice;
  const WrappedFrameParameters p = state.committed;
  const uint32_t width = p.width;
  const uint32_t height = p.height;
  const size_t pixels = size_t(width) * height;
  state.width = width;
  state.height = height;
  device.renderFrame(handle);
  device.frameReady(handle, ANARI_WAIT);

  // This process's linear color and depth, as the wrapped frame rendered
  // them (nothing, when it gave other types or sizes).
  std::vector<float4> color;
  std::vector<float> depth;
  auto readLocal = [&](const char *channel, ANARIDataType want, auto &to) {
    uint32_t w = 0, h = 0;
    ANARIDataType type = ANARI_UNKNOWN;
    const void *mapped = device.frameBufferMap(handle, channel, &w, &h, &type);
    if (!mapped)
      return;
    if (type == want && w == width && h == height) {
      using Pixel = typename std::decay_t<decltype(to)>::value_type;
      to.assign((const Pixel *)mapped, (const Pixel *)mapped + pixels);
    }
    device.frameBufferUnmap(handle, channel);
  };
  readLocal("channel.color", ANARI_FLOAT32_VEC4, color);
  readLocal("channel.depth", ANARI_FLOAT32, depth);
  if (color.empty() || depth.empty()) {
    reportStatus(handle,
        ANARI_FRAME,
        ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_OPERATION,
        "anariRenderFrame: library '" + m_wrappedLibrary->name()
            + "' gave no FLOAT32_VEC4 channel.color and FLOAT32"
              " channel.depth of the frame's size; this process's pixels"
              " are left out");
    color.clear();
    depth.clear();
  }

  CompositedImage image;
  std::optional<DepthCompositor> compositor;
  if (communicator != MPI_COMM_NULL) {
    politeBarrier(communicator);
    compositor.emplace(communicator, width, height);
    image = compositor->composite(color, depth);
  } else {
    // No MPI: this process's pixels are the image.
    image.color = color;
    image.depth = depth;
    if (image.color.empty()) {
      image.color.assign(pixels, kTransparent);
      image.depth.assign(pixels, std::numeric_limits<float>::infinity());
    }
  }
  const bool rankZero = !image.color.empty();
  if (rankZero) {
    float4 background = kDefaultBackground;
    {
      std::lock_guard lock(m_stateMutex);
      auto renderer = m_wrappedRenderers.find(p.renderer);
      if (renderer != m_wrappedRenderers.end())
        background = renderer->second.background;
    }
    addBackground(
        width, image.color, [&](uint32_t, uint32_t) { return background; });
  }

  // Every enabled channel in the application's type: rank 0's composite,
  // and elsewhere this process's own pixels (defined by nothing).
  std::map<std::string, MappedChannel> assembled;
  for (int c = 0; c < kChannelCount; c++) {
    const ANARIDataType type = p.channelTypes[c];
    const size_t unit = pixelSize(type);
    if (type == ANARI_UNKNOWN || unit == 0)
      continue;
    const char *name = kChannelNames[c];
    MappedChannel channel{type, {}};
    if (c == 0) {
      const std::vector<float4> &source = rankZero ? image.color : color;
      if (source.empty())
        continue;
      channel.pixels.resize(source.size() * unit);
      writeColorPixels(
          type, source.data(), source.size(), channel.pixels.data());
    } else if (c == 1) {
      const std::vector<float> &source = rankZero ? image.depth : depth;
      if (source.empty())
        continue;
      channel.pixels.resize(source.size() * sizeof(float));
      std::memcpy(channel.pixels.data(), source.data(), channel.pixels.size());
    } else {
      // Channels that do not blend show the nearest fragment's process.
      uint32_t w = 0, h = 0;
      ANARIDataType mappedType = ANARI_UNKNOWN;
      const void *mapped =
          device.frameBufferMap(handle, name, &w, &h, &mappedType);
      const bool usable =
          mapped && mappedType == type && w == width && h == height;
      const auto *local = usable ? (const unsigned char *)mapped : nullptr;
      if (compositor)
        channel.pixels = compositor->takeNearest(local, unit);
      else if (local)
        channel.pixels.assign(local, local + pixels * unit);
      else
        channel.pixels.assign(pixels * unit, 0);
      if (mapped)
        device.frameBufferUnmap(handle, name);
      if (!rankZero)
        continue; // mapped from the wrapped frame itself
    }
    assembled[name] = std::move(channel);
  }
  std::lock_guard lock(m_stateMutex);
  state.assembled = std::move(assembled);
  state.bytesSent = compositor ? compositor->bytesSent() : 0;
}

} // namespace prism::mpi
