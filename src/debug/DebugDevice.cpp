#include "DebugDevice.h"
#include "WithheldReports.h"
#include "trace/TraceFormat.h"

#include "anari/frontend/type_utility.h"

#include <atomic>
#include <cstdio>
#include <cstring>

namespace prism::debug {

DebugDevice::DebugDevice(ANARILibrary library,
    const std::string &wrappedSpec,
    const std::string &subtype)
    : ForwardingDevice(library), m_subtype(subtype)
{
  m_statusCallback = m_defaultStatusCB;
  m_statusUserPtr = m_defaultStatusCBUserPtr;
  if (wrap(wrappedSpec, subtype))
    openTrace();
}

DebugDevice::~DebugDevice()
{
  trace("Release device");
  reportLeaks();
  dropWrapped(); // runs the deleters of every array still alive
}

bool DebugDevice::wrap(
    const std::string &wrappedSpec, const std::string &subtype)
{
  std::string error;
  auto library =
      WrappedLibrary::load(wrappedSpec, &forwardStatus, this, "debug", error);
  if (!library) {
    m_failure =
        "cannot load the wrapped library '" + wrappedSpec + "': " + error;
    return false;
  }
  auto *device =
      (anari::DeviceImpl *)library->library().newDevice(subtype.c_str());
  if (!device) {
    m_failure = "the wrapped library '" + wrappedSpec
                + "' created no device of subtype '" + subtype + "'";
    return false;
  }
  dropWrapped();
  m_wrappedLibrary = std::move(library);
  setInner(device);
  m_ownsWrapped = true;
  m_wrappedSpec = wrappedSpec;
  m_failure.clear();
  readWrappedDefinitions(
      m_wrappedLibrary->library().getDeviceExtensions(subtype.c_str()));
  return true;
}

void DebugDevice::adopt(anari::DeviceImpl *device)
{
  dropWrapped();
  setInner(device);
  m_ownsWrapped = false;
  m_failure.clear();
  // No library to ask: the device's own "extension" property (spec 5.1).
  const char **extensions = nullptr;
  if (!inner()->getProperty((ANARIObject)inner(),
          "extension",
          ANARI_STRING_LIST,
          &extensions,
          sizeof(extensions),
          ANARI_WAIT))
    extensions = nullptr;
  readWrappedDefinitions(extensions);
}

void DebugDevice::readWrappedDefinitions(const char **extensions)
{
  // The definitions the wrapped device implements are those checked.
  const char **renderers = inner()->getObjectSubtypes(ANARI_RENDERER);
  m_catalog = std::make_unique<introspection::Catalog>(extensions, renderers);
  m_rules = std::make_unique<Rules>(*m_catalog, *inner());
}

void DebugDevice::dropWrapped()
{
  // A device the application handed over is the application's to release.
  if (inner() && m_ownsWrapped)
    inner()->release((ANARIObject)inner());
  setInner(nullptr);
  m_ownsWrapped = true;
  m_rules.reset();
  m_catalog.reset();
  m_wrappedLibrary.reset();
}

// Status /////////////////////////////////////////////////////////////////////

void DebugDevice::report(Findings &findings)
{
  if (tracing()) {
    // After the call's line: a replay checks the same reports come out.
    for (const Finding &f : findings.list())
      trace(trace::reportLine(f.severity, f.code, f.text));
  }
  if (!m_statusCallback) {
    findings.list().clear();
    return;
  }
  for (const Finding &f : findings.list()) {
    m_statusCallback(m_statusUserPtr,
        this_device(),
        f.source ? f.source : (ANARIObject)this_device(),
        f.source ? f.sourceType : ANARI_DEVICE,
        f.severity,
        f.code,
        f.text.c_str());
  }
  findings.list().clear();
}

void DebugDevice::report(
    ANARIStatusSeverity severity, ANARIStatusCode code, const std::string &text)
{
  if (m_statusCallback) {
    m_statusCallback(m_statusUserPtr,
        this_device(),
        (ANARIObject)this_device(),
        ANARI_DEVICE,
        severity,
        code,
        text.c_str());
  }
}

void DebugDevice::forwardStatus(const void *userPtr,
    ANARIDevice device,
    ANARIObject source,
    ANARIDataType sourceType,
    ANARIStatusSeverity severity,
    ANARIStatusCode code,
    const char *message)
{
  auto *self = (DebugDevice *)userPtr;
  if (WithheldReports::withheld(self, severity))
    return;
  ANARIObject translated = nullptr;
  if (source
      && (source == (ANARIObject)device
          || source == (ANARIObject)self->inner())) {
    translated = (ANARIObject)self->this_device();
  } else if (source) {
    std::lock_guard lock(self->m_mutex);
    translated = self->m_objects.fromWrapped(source);
  }
  if (self->m_statusCallback) {
    self->m_statusCallback(self->m_statusUserPtr,
        self->this_device(),
        translated,
        sourceType,
        severity,
        code,
        message);
  }
}

void DebugDevice::forwardFrameCompletion(
    const void *userPtr, ANARIDevice, ANARIFrame frame)
{
  auto *self = (DebugDevice *)userPtr;
  if (!self)
    return; // cannot happen: the layer always sets itself as user data
  ANARIFrameCompletionCallback callback = nullptr;
  const void *callbackUserPtr = nullptr;
  ANARIObject handle = nullptr;
  {
    std::lock_guard lock(self->m_mutex);
    handle = self->m_objects.fromWrapped((ANARIObject)frame);
    if (ObjectRecord *record = self->m_objects.find(handle)) {
      record->awaited = true;
      callback = record->completion;
      callbackUserPtr = record->completionUserPtr;
    }
  }
  if (callback)
    callback(callbackUserPtr, self->this_device(), (ANARIFrame)handle);
}

// Handles ////////////////////////////////////////////////////////////////////

ObjectRecord *DebugDevice::live(
    Findings &f, ANARIObject handle, ANARIDataType expected, const char *what)
{
  char address[32];
  std::snprintf(address, sizeof(address), "%p", (void *)handle);
  switch (m_objects.state(handle)) {
  case HandleState::kNull:
    f.error(std::string(what) + " handle is NULL");
    return nullptr;
  case HandleState::kForeign:
    f.error(std::string(what) + " handle " + address
        + " is not an object of this device (another device's, corrupt, or "
          "never created)");
    return nullptr;
  case HandleState::kReleased:
    f.error(std::string(what) + " handle is "
            + describe(*m_objects.find(handle)) + ", used after its release");
    return nullptr;
  case HandleState::kLive:
    break;
  }
  ObjectRecord *record = m_objects.find(handle);
  if (!handleTypeFits(expected, record->type)) {
    f.error(std::string(what) + " is " + describe(*record) + ", not "
            + typeName(expected));
    return nullptr;
  }
  return record;
}

bool DebugDevice::translate(Findings &f,
    ANARIObject handle,
    ANARIDataType expected,
    const char *what,
    ANARIObject &wrapped)
{
  wrapped = nullptr;
  if (!handle)
    return true;
  ObjectRecord *record = live(f, handle, expected, what);
  if (!record)
    return false;
  wrapped = record->wrapped;
  return true;
}

ANARIObject DebugDevice::created(const char *function,
    ANARIDataType type,
    const char *subtype,
    ANARIObject wrapped,
    Findings &f)
{
  if (!wrapped) {
    f.warning("the wrapped device created no object", ANARI_STATUS_NO_ERROR);
    return nullptr;
  }
  ObjectRecord &record = m_objects.add(wrapped, type);
  record.hasSubtype = subtype != nullptr;
  record.subtype = subtype ? subtype : "";
  record.createdAtCall = m_calls.load();
  record.createdBy = function;
  return record.handle;
}

// The device object //////////////////////////////////////////////////////////

void DebugDevice::setDeviceParameter(
    const char *name, ANARIDataType type, const void *mem)
{
  Findings f("anariSetParameter");
  f.about(nullptr, name ? name : "");
  if (!name || (!mem && type != ANARI_VOID_POINTER)) {
    f.error(name ? "value pointer is NULL" : "parameter name is NULL");
    report(f);
    return;
  }
  const std::string n = name;
  if (n == "statusCallback" && type == ANARI_STATUS_CALLBACK) {
    std::memcpy(&m_statusCallback, mem, sizeof(m_statusCallback));
    return; // the wrapped device keeps reporting to the layer
  }
  if (n == "statusCallbackUserData" && type == ANARI_VOID_POINTER) {
    m_statusUserPtr = mem; // a VOID_POINTER value is `mem` itself
    return;
  }
  if (n == "wrappedDevice" && type == ANARI_DEVICE) {
    stageWrappedHandle(f, mem);
    report(f);
    return;
  }
  if (n == "wrappedLibrary" || n == "wrappedDevice") {
    if (type != ANARI_STRING) {
      f.error(
          n == "wrappedLibrary"
              ? "type must be ANARI_STRING"
              : "type must be ANARI_STRING (a device subtype) or ANARI_DEVICE "
                "(a device to wrap)");
    } else {
      (n == "wrappedLibrary" ? m_pendingWrappedSpec : m_pendingSubtype) =
          (const char *)mem;
    }
    report(f);
    return;
  }
  if (n == "traceDir" || n == "traceMode") {
    stageTraceParameter(f, n, type, mem);
    report(f);
    return;
  }
  ANARIObject translated = nullptr;
  bool good = true;
  {
    std::lock_guard lock(m_mutex);
    if (anari::isObject(type)) {
      // An object value is checked and translated as on any object.
      ANARIObject handle = nullptr;
      std::memcpy(&handle, mem, sizeof(handle));
      good = translate(f, handle, type, "value", translated);
    }
    const std::string value = good && tracing() ? traceValue(type, mem) : "";
    if (!value.empty()) {
      trace("Set device " + trace::quote(name) + " " + trace::typeName(type)
            + " " + value);
    }
  }
  report(f);
  if (!good)
    return;
  inner()->setParameter((ANARIObject)inner(),
      name,
      type,
      anari::isObject(type) ? (const void *)&translated : mem);
}

namespace {
std::atomic<DebugDevice::DeviceCheck> g_deviceCheck{nullptr};
} // namespace

void DebugDevice::setDeviceCheck(DeviceCheck check)
{
  g_deviceCheck = check;
}

void DebugDevice::stageWrappedHandle(Findings &f, const void *mem)
{
  ANARIDevice handle = nullptr;
  std::memcpy(&handle, mem, sizeof(handle));
  char address[32];
  std::snprintf(address, sizeof(address), "%p", (void *)handle);
  const DeviceCheck check = g_deviceCheck.load();
  if (!handle) {
    f.error("the device handle is NULL");
  } else if (handle == this_device()) {
    f.error("the device handle is this debug device itself");
  } else if (check && !check(handle)) {
    f.error(std::string("device handle ") + address
            + " is not a live device (released, or never created)");
  } else {
    m_pendingDevice = (anari::DeviceImpl *)handle;
    m_pendingSubtype.clear();
  }
}

void DebugDevice::stageTraceParameter(
    Findings &f, const std::string &name, ANARIDataType type, const void *mem)
{
  if (type != ANARI_STRING) {
    f.error("type must be ANARI_STRING");
    return;
  }
  const std::string value = (const char *)mem;
  if (name == "traceDir") {
    m_pendingTraceDir = value;
    return;
  }
  // The SDK's debug device writes C code for "code"; the layer writes its
  // own trace (docs/debug-layer.md), which anari-replay replays.
  if (value == "code") {
    f.warning(
        "C-code traces are not written; the layer writes its own trace, "
        "which anari-replay replays",
        ANARI_STATUS_INVALID_ARGUMENT);
  } else if (value != "prism") {
    f.warning("'" + value
            + "' is not a trace mode (\"prism\", or \"code\" as the SDK "
              "names it); the layer's trace is written",
        ANARI_STATUS_INVALID_ARGUMENT);
  }
}

void DebugDevice::openTraceInDirectory(Findings &f)
{
  if (m_pendingTraceDir.empty())
    return;
  const std::string directory = m_pendingTraceDir;
  m_pendingTraceDir.clear();
  if (tracing()) {
    f.warning("a trace is being written already; 'traceDir' is ignored",
        ANARI_STATUS_INVALID_OPERATION);
    return;
  }
  const std::string file = directory + "/anari.trace";
  auto writer = std::make_unique<trace::TraceWriter>(file);
  if (!writer->ok()) {
    f.error(
        "cannot write the trace '" + file + "'", ANARI_STATUS_INVALID_ARGUMENT);
    return;
  }
  m_trace = std::move(writer);
  traceDeviceLine();
}

void DebugDevice::commitDevice()
{
  Findings f("anariCommitParameters");
  f.about(nullptr);
  if (m_pendingDevice) {
    std::unique_lock lock(m_mutex);
    if (m_objects.size() > 0) {
      f.error(
          "'wrappedDevice' can change only before the first object is "
          "created; keeping the device wrapped now",
          ANARI_STATUS_INVALID_OPERATION);
    } else if (m_pendingDevice != inner()) {
      adopt(m_pendingDevice);
    }
    m_pendingDevice = nullptr;
    m_pendingWrappedSpec.clear();
    m_pendingSubtype.clear();
  }
  const std::string spec =
      m_pendingWrappedSpec.empty() ? m_wrappedSpec : m_pendingWrappedSpec;
  const std::string subtype =
      m_pendingSubtype.empty() ? m_subtype : m_pendingSubtype;
  if (spec != m_wrappedSpec || subtype != m_subtype) {
    std::unique_lock lock(m_mutex);
    const std::string previous =
        "'" + m_wrappedSpec + "' device '" + m_subtype + "'";
    if (m_objects.size() > 0) {
      f.error(
          "'wrappedLibrary' and 'wrappedDevice' can change only before the "
          "first object is created; keeping "
              + previous,
          ANARI_STATUS_INVALID_OPERATION);
    } else if (wrap(spec, subtype)) {
      m_subtype = subtype;
    } else {
      f.error(
          m_failure + "; keeping " + previous, ANARI_STATUS_INVALID_OPERATION);
    }
  }
  m_pendingWrappedSpec.clear();
  m_pendingSubtype.clear();
  openTraceInDirectory(f);
  report(f);
  trace("Commit device");
  inner()->commitParameters((ANARIObject)inner());
}

void (*DebugDevice::getProcAddress(const char *name))(void)
{
  ++m_calls;
  if (name && inner()->getProcAddress(name)) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_UNSUPPORTED_DEVICE,
        std::string("anariDeviceGetProcAddress(device '") + name
            + "'): the wrapped device's extension function is not available "
              "through the debug layer, which cannot translate its handles");
  }
  return nullptr;
}

void DebugDevice::reportLeaks()
{
  Findings f("anariRelease");
  f.about(nullptr);
  std::vector<ObjectRecord *> leaked;
  for (ObjectRecord *record : m_objects.all()) {
    if (!record->released)
      leaked.push_back(record);
  }
  if (leaked.empty())
    return;
  f.add(ANARI_SEVERITY_WARNING,
      ANARI_STATUS_NO_ERROR,
      "device released with " + std::to_string(leaked.size())
          + " object(s) the application did not release");
  for (ObjectRecord *record : leaked) {
    f.add(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_NO_ERROR,
        "leaked " + describe(*record) + ", created by " + record->createdBy
            + " (API call " + std::to_string(record->createdAtCall)
            + (record->traceLine
                    ? ", trace line " + std::to_string(record->traceLine)
                    : std::string())
            + "), " + std::to_string(record->publicReferences)
            + " reference(s)");
  }
  report(f);
}

} // namespace prism::debug
