#include "DataParallelDevice.h"

#include "anari/frontend/type_utility.h"

#include <cstdlib>
#include <cstring>
#include <limits>

namespace prism::mpi {

DataParallelDevice::DataParallelDevice(ANARILibrary library)
    : ForwardingDevice(library),
      m_statusCallback(defaultStatusCallback()),
      m_statusUserPtr(defaultStatusCallbackUserPtr()),
      m_core(std::make_unique<CoreRenderer>(library))
{
  // The core's messages are this device's.
  const ANARIStatusCallback status = &forwardStatus;
  coreDevice().setParameter(
      coreHandle(), "statusCallback", ANARI_STATUS_CALLBACK, &status);
  coreDevice().setParameter(
      coreHandle(), "statusCallbackUserData", ANARI_VOID_POINTER, this);
  setInner(&coreDevice());
  if (!m_session.usable()) {
    report(this_device(),
        ANARI_DEVICE,
        ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_OPERATION,
        m_session.problem());
  }
  // An unmodified single-process program chooses its mode from outside.
  if (const char *mode = std::getenv("PRISM_MPI_MODE"))
    setMode(ANARI_STRING, mode);
  // ... and the library that renders its objects.
  const char *wrappedName = std::getenv("PRISM_MPI_WRAPPED_LIBRARY");
  if (wrappedName && *wrappedName)
    setWrapParameter("wrappedLibrary", ANARI_STRING, wrappedName);
  const char *subtype = std::getenv("PRISM_MPI_WRAPPED_DEVICE");
  if (subtype && *subtype)
    setWrapParameter("wrappedDevice", ANARI_STRING, subtype);
  if (const char *timeout = std::getenv("PRISM_MPI_TIMEOUT")) {
    const float seconds = std::strtof(timeout, nullptr);
    setTimeout(ANARI_FLOAT32, &seconds);
  }
}

DataParallelDevice::~DataParallelDevice()
{
  // Frames in flight finish (the devices wait for them) before MPI may be
  // finalized under them.
  setInner(nullptr);
  m_wrapped.reset();
  m_core.reset();
}

// Status /////////////////////////////////////////////////////////////////////

void DataParallelDevice::forwardStatus(const void *userPtr,
    ANARIDevice device,
    ANARIObject source,
    ANARIDataType sourceType,
    ANARIStatusSeverity severity,
    ANARIStatusCode code,
    const char *message)
{
  if (!userPtr)
    return;
  const auto *self = (const DataParallelDevice *)userPtr;
  if (source == (ANARIObject)device)
    source = (ANARIObject)self->this_device();
  self->report(source, sourceType, severity, code, message ? message : "");
}

void DataParallelDevice::report(ANARIObject source,
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

void DataParallelDevice::reportBadDeviceParameter(
    const std::string &message) const
{
  report(this_device(),
      ANARI_DEVICE,
      ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      message);
}

// The choice /////////////////////////////////////////////////////////////////

LocalRenderer &DataParallelDevice::local()
{
  if (!m_wrapChosen.load())
    chooseLocal();
  return *m_local;
}

void DataParallelDevice::chooseLocal()
{
  std::lock_guard lock(m_wrapMutex);
  if (m_wrapChosen.load())
    return;
  m_local = m_core.get();
  if (!m_wrappedSpec.empty()) {
    std::string error;
    m_wrapped = WrappedDevice::load(
        m_wrappedSpec,
        m_wrappedSubtype,
        &forwardStatus,
        this,
        [this](ANARIObject source,
            ANARIDataType sourceType,
            ANARIStatusSeverity severity,
            ANARIStatusCode code,
            const std::string &message) {
          report(source, sourceType, severity, code, message);
        },
        error);
    if (!m_wrapped)
      reportBadDeviceParameter(error);
  }
  if (m_wrapped) {
    const ANARIObject device = (ANARIObject)m_wrapped->this_device();
    for (const DeviceParameter &p : m_stagedDeviceParameters)
      m_wrapped->setParameter(device, p.name.c_str(), p.type, p.value.data());
    if (!m_stagedDeviceParameters.empty())
      m_wrapped->commitParameters(device);
    m_local = m_wrapped.get();
    setInner(m_wrapped.get());
  }
  m_stagedDeviceParameters.clear();
  m_wrapChosen.store(true);
}

// Objects ////////////////////////////////////////////////////////////////////

ANARIObject DataParallelDevice::newObjectOf(
    ANARIDataType type, const char *subtype)
{
  ANARIObject object = ForwardingDevice::newObjectOf(type, subtype);
  if (object && (type == ANARI_FRAME || type == ANARI_WORLD)) {
    std::lock_guard lock(m_stateMutex);
    m_kept[object] = Kept{};
    if (type == ANARI_FRAME)
      m_frames[object].index = m_framesCreated++;
    else
      m_worlds[object] = WorldState{};
  }
  return object;
}

void DataParallelDevice::beforeCreating(ANARIDataType)
{
  local();
}

void DataParallelDevice::retain(ANARIObject object)
{
  if (handleIsDevice(object)) {
    m_publicReferences++;
    return;
  }
  {
    std::lock_guard lock(m_stateMutex);
    auto it = m_kept.find(object);
    if (it != m_kept.end())
      it->second.references++;
  }
  ForwardingDevice::retain(object);
}

void DataParallelDevice::release(ANARIObject object)
{
  if (handleIsDevice(object)) {
    if (--m_publicReferences == 0)
      delete this; // nothing after it
    return;
  }
  {
    // The application's last reference is gone: so is what this device
    // kept for the frame or world (an assembled image can be large).
    std::lock_guard lock(m_stateMutex);
    auto it = m_kept.find(object);
    if (it != m_kept.end() && --it->second.references <= 0) {
      m_kept.erase(it);
      m_frames.erase(object);
      m_worlds.erase(object);
    }
  }
  ForwardingDevice::release(object);
}

// Properties /////////////////////////////////////////////////////////////////

bool DataParallelDevice::collectiveWorldBounds(
    ANARIObject world, bool foundLocally, float bounds[6])
{
  MPI_Comm communicator = MPI_COMM_WORLD;
  {
    std::lock_guard lock(m_stateMutex);
    auto it = m_worlds.find(world);
    if (it != m_worlds.end())
      communicator = it->second.communicator.committed;
  }
  // The union of every process's bounds: lower corners by minimum, upper
  // corners by maximum (negated, so one reduction does both).
  const float infinity = std::numeric_limits<float>::infinity();
  float mine[6];
  for (int i = 0; i < 3; i++) {
    mine[i] = foundLocally ? bounds[i] : infinity;
    mine[3 + i] = foundLocally ? -bounds[3 + i] : infinity;
  }
  float global[6];
  MPI_Allreduce(mine, global, 6, MPI_FLOAT, MPI_MIN, communicator);
  if (!(global[0] <= -global[3]))
    return false; // no process has anything in its world
  for (int i = 0; i < 3; i++) {
    bounds[i] = global[i];
    bounds[3 + i] = -global[3 + i];
  }
  return true;
}

int DataParallelDevice::getProperty(ANARIObject object,
    const char *name,
    ANARIDataType type,
    void *mem,
    uint64_t size,
    ANARIWaitMask mask)
{
  if (int answered = getFrameProperty(object, name, type, mem, size))
    return answered;
  // The device's own properties (its extensions) are the core's.
  const int found =
      handleIsDevice(object)
          ? coreDevice().getProperty(coreHandle(), name, type, mem, size, mask)
          : ForwardingDevice::getProperty(object, name, type, mem, size, mask);
  const bool worldBounds = m_session.usable() && (mask & ANARI_WAIT) && name
                           && std::string(name) == "bounds"
                           && type == ANARI_FLOAT32_BOX3 && mem
                           && size >= 6 * sizeof(float);
  if (!worldBounds)
    return found;
  // A stale handle still takes part, so the other processes never wait on
  // this one.
  // (Asking does not choose the local renderer.)
  LocalRenderer &renderer = wrapOpen() ? *m_core : *m_local;
  const ANARIDataType objectType = renderer.typeOf(object);
  if (objectType != ANARI_UNKNOWN && objectType != ANARI_WORLD)
    return found;
  try {
    return collectiveWorldBounds(object, found != 0, (float *)mem) ? 1 : 0;
  } catch (...) {
    return found;
  }
}

int DataParallelDevice::getFrameProperty(ANARIObject object,
    const char *name,
    ANARIDataType type,
    void *mem,
    uint64_t size)
{
  const std::string property = name ? name : "";
  std::lock_guard lock(m_stateMutex);
  auto it = m_frames.find(object);
  if (it == m_frames.end() || !mem)
    return 0;
  if (property == "mpiBytesSent" && type == ANARI_UINT64
      && size >= sizeof(uint64_t)) {
    std::memcpy(mem, &it->second.bytesSent, sizeof(uint64_t));
    return 1;
  }
  const std::optional<uint64_t> &active = it->second.activePixels;
  if (property == "activePixels" && type == ANARI_UINT64
      && size >= sizeof(uint64_t) && active) {
    std::memcpy(mem, &*active, sizeof(uint64_t));
    return 1;
  }
  if ((property == "mpiRank" || property == "mpiSize") && type == ANARI_INT32
      && size >= sizeof(int32_t) && m_session.usable()) {
    int value = 0;
    if (property == "mpiRank")
      MPI_Comm_rank(it->second.communicator.committed, &value);
    else
      MPI_Comm_size(it->second.communicator.committed, &value);
    const int32_t answer = value;
    std::memcpy(mem, &answer, sizeof(answer));
    return 1;
  }
  return 0;
}

// Frames /////////////////////////////////////////////////////////////////////

const void *DataParallelDevice::frameBufferMap(ANARIFrame frame,
    const char *channel,
    uint32_t *width,
    uint32_t *height,
    ANARIDataType *pixelType)
{
  {
    std::lock_guard lock(m_stateMutex);
    auto it = m_frames.find(frame);
    if (it != m_frames.end() && channel) {
      auto assembled = it->second.assembled.find(channel);
      if (assembled != it->second.assembled.end()) {
        *width = it->second.width;
        *height = it->second.height;
        *pixelType = assembled->second.type;
        return assembled->second.pixels.data();
      }
    }
  }
  return ForwardingDevice::frameBufferMap(
      frame, channel, width, height, pixelType);
}

void DataParallelDevice::frameBufferUnmap(ANARIFrame frame, const char *channel)
{
  {
    // Channels this device assembled were never mapped on the local one.
    std::lock_guard lock(m_stateMutex);
    auto it = m_frames.find(frame);
    if (it != m_frames.end() && channel && it->second.assembled.count(channel))
      return;
  }
  ForwardingDevice::frameBufferUnmap(frame, channel);
}

} // namespace prism::mpi
