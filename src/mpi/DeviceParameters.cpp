// The parameters prism_mpi reads itself: the device's (mode, mpiTimeout,
// numThreads, wrappedLibrary, wrappedDevice, the status callback) and the
// `mpiCommunicator` of frames and worlds. Any other reaches the local
// renderer's device.
#include "DataParallelDevice.h"

#include "MachineLimits.h"

#include "anari/frontend/type_utility.h"

#include <cmath>
#include <cstring>
#include <limits>

namespace prism::mpi {

void DataParallelDevice::setMode(ANARIDataType type, const void *mem)
{
  const auto mode = type == ANARI_STRING && mem
                        ? parseRenderMode((const char *)mem)
                        : std::nullopt;
  if (!mode) {
    std::string message =
        "device: parameter 'mode' must be the STRING 'pathtracer',"
        " 'composite' or 'replicated' (got ";
    if (type == ANARI_STRING && mem)
      message.append("'").append((const char *)mem).append("'");
    else
      message.append(anari::toString(type));
    message.append("); it stays '").append(toString(m_mode)).append("'");
    reportBadDeviceParameter(message);
    return;
  }
  m_mode = *mode;
  m_modeExplicit = true;
}

void DataParallelDevice::setTimeout(ANARIDataType type, const void *mem)
{
  double seconds = 0.0;
  if (type == ANARI_FLOAT32 && mem)
    seconds = *(const float *)mem;
  else if (type == ANARI_FLOAT64 && mem)
    seconds = *(const double *)mem;
  else
    seconds = std::numeric_limits<double>::quiet_NaN();
  if (!(seconds >= 0.0) || !std::isfinite(seconds)) {
    std::string message =
        "device: parameter 'mpiTimeout' must be a FLOAT32"
        " or FLOAT64 number of seconds, 0 or more (got ";
    message.append(std::isnan(seconds) ? std::string(anari::toString(type))
                                       : std::to_string(seconds));
    message.append("); it stays ");
    message.append(std::to_string(m_timeoutSeconds));
    reportBadDeviceParameter(message);
    return;
  }
  m_timeoutSeconds = seconds;
}

void DataParallelDevice::setThreads(ANARIDataType type, const void *mem)
{
  const bool isCount = (type == ANARI_INT32 || type == ANARI_UINT32) && mem;
  int64_t threads = -1;
  if (isCount && type == ANARI_INT32)
    threads = *(const int32_t *)mem;
  else if (isCount)
    threads = *(const uint32_t *)mem;
  const unsigned limit = limits::maxPoolThreads();
  if (threads < 0 || threads > int64_t(limit)) {
    std::string message =
        "device: parameter 'numThreads' must be an INT32 or UINT32 count, 0"
        " (every hardware thread) up to "
        + std::to_string(limit) + ", this machine's limit (got ";
    message.append(
        isCount ? std::to_string(threads) : std::string(anari::toString(type)));
    message.append("); it is ignored");
    reportBadDeviceParameter(message);
    return;
  }
  m_core->setThreads(int(threads));
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
                             + m_local->description() + ")");
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
  std::lock_guard lock(m_wrapMutex);
  if (m_wrapChosen.load()) {
    if (m_wrapped) {
      m_wrapped->setParameter(
          (ANARIObject)m_wrapped->this_device(), name.c_str(), type, mem);
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

void DataParallelDevice::setDeviceParameter(
    const std::string &name, ANARIDataType type, const void *mem)
{
  if (name == "mode") {
    setMode(type, mem);
  } else if (name == "mpiTimeout") {
    setTimeout(type, mem);
  } else if (name == "numThreads") {
    setThreads(type, mem);
  } else if (name == "wrappedLibrary" || name == "wrappedDevice") {
    setWrapParameter(name, type, mem);
  } else if (name == "statusCallback" && type == ANARI_STATUS_CALLBACK) {
    // Every inner device reports through this device (forwardStatus).
    std::lock_guard lock(m_statusMutex);
    m_statusCallback = mem ? *(const ANARIStatusCallback *)mem : nullptr;
  } else if (name == "statusCallbackUserData" && type == ANARI_VOID_POINTER) {
    std::lock_guard lock(m_statusMutex);
    m_statusUserPtr = mem;
  } else {
    coreDevice().setParameter(coreHandle(), name.c_str(), type, mem);
    passDeviceParameter(name, type, mem);
  }
}

void DataParallelDevice::unsetDeviceParameter(const std::string &name)
{
  if (name == "wrappedLibrary") {
    setWrapParameter(name, ANARI_STRING, "");
  } else if (name == "wrappedDevice") {
    setWrapParameter(name, ANARI_STRING, "default");
  } else {
    coreDevice().unsetParameter(coreHandle(), name.c_str());
    if (!wrapOpen() && m_wrapped) {
      m_wrapped->unsetParameter(
          (ANARIObject)m_wrapped->this_device(), name.c_str());
    }
  }
}

DataParallelDevice::CommunicatorParameter *DataParallelDevice::communicatorOf(
    ANARIObject object)
{
  auto frame = m_frames.find(object);
  if (frame != m_frames.end())
    return &frame->second.communicator;
  auto world = m_worlds.find(object);
  return world != m_worlds.end() ? &world->second.communicator : nullptr;
}

bool DataParallelDevice::setCommunicator(
    ANARIObject object, ANARIDataType type, const void *mem)
{
  std::lock_guard lock(m_stateMutex);
  CommunicatorParameter *communicator = communicatorOf(object);
  if (!communicator)
    return false;
  if (type != ANARI_VOID_POINTER || !mem) {
    report(object,
        m_frames.count(object) ? ANARI_FRAME : ANARI_WORLD,
        ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_ARGUMENT,
        std::string("anariSetParameter: parameter 'mpiCommunicator' must"
                    " be a non-NULL VOID_POINTER to an MPI_Comm (got ")
            + (mem ? anari::toString(type) : "NULL") + "); it is ignored");
    return true;
  }
  communicator->staged = *(const MPI_Comm *)mem;
  return true;
}

void DataParallelDevice::setParameter(
    ANARIObject object, const char *name, ANARIDataType type, const void *mem)
try {
  const std::string parameter = name ? name : "";
  if (handleIsDevice(object)) {
    setDeviceParameter(parameter, type, mem);
    return;
  }
  if (parameter == "mpiCommunicator" && setCommunicator(object, type, mem))
    return;
  ForwardingDevice::setParameter(object, name, type, mem);
} catch (...) {
  report(object,
      ANARI_OBJECT,
      ANARI_SEVERITY_ERROR,
      ANARI_STATUS_UNKNOWN_ERROR,
      "anariSetParameter: failed (out of memory?)");
}

void DataParallelDevice::unsetParameter(ANARIObject object, const char *name)
{
  const std::string parameter = name ? name : "";
  if (handleIsDevice(object)) {
    unsetDeviceParameter(parameter);
    return;
  }
  if (parameter == "mpiCommunicator") {
    std::lock_guard lock(m_stateMutex);
    if (CommunicatorParameter *communicator = communicatorOf(object)) {
      communicator->staged = MPI_COMM_WORLD;
      return;
    }
  }
  ForwardingDevice::unsetParameter(object, name);
}

void DataParallelDevice::unsetAllParameters(ANARIObject object)
{
  {
    std::lock_guard lock(m_stateMutex);
    if (CommunicatorParameter *communicator = communicatorOf(object))
      communicator->staged = MPI_COMM_WORLD;
  }
  if (handleIsDevice(object))
    coreDevice().unsetAllParameters(coreHandle());
  else
    ForwardingDevice::unsetAllParameters(object);
}

void DataParallelDevice::commitParameters(ANARIObject object)
{
  {
    std::lock_guard lock(m_stateMutex);
    if (CommunicatorParameter *communicator = communicatorOf(object))
      communicator->committed = communicator->staged;
  }
  if (!handleIsDevice(object)) {
    ForwardingDevice::commitParameters(object);
    return;
  }
  coreDevice().commitParameters(coreHandle());
  if (!wrapOpen() && m_wrapped)
    m_wrapped->commitParameters((ANARIObject)m_wrapped->this_device());
}

} // namespace prism::mpi
