#include "DeviceSession.h"

#include <cstring>

namespace prism::tools {
namespace {

const char *severityName(ANARIStatusSeverity severity)
{
  switch (severity) {
  case ANARI_SEVERITY_FATAL_ERROR:
    return "fatal error";
  case ANARI_SEVERITY_ERROR:
    return "error";
  case ANARI_SEVERITY_WARNING:
    return "warning";
  case ANARI_SEVERITY_PERFORMANCE_WARNING:
    return "performance warning";
  case ANARI_SEVERITY_INFO:
    return "info";
  default:
    return "debug";
  }
}

// The device's extensions: the library's list for the subtype plus the
// device's `extension` property, whichever the device fills in.
std::set<std::string> deviceExtensions(
    ANARILibrary library, ANARIDevice device, const std::string &subtype)
{
  std::set<std::string> extensions;
  for (const char **e = anariGetDeviceExtensions(library, subtype.c_str());
       e && *e;
       ++e)
    extensions.insert(*e);
  const char **property = nullptr;
  if (anariGetProperty(device,
          device,
          "extension",
          ANARI_STRING_LIST,
          &property,
          sizeof(property),
          ANARI_WAIT))
    for (; property && *property; ++property)
      extensions.insert(*property);
  return extensions;
}

} // namespace

std::string joinList(const char **list)
{
  std::string joined;
  for (; list && *list; ++list)
    joined += std::string(joined.empty() ? "" : ", ") + *list;
  return joined.empty() ? "none" : joined;
}

bool contains(const char **list, const std::string &name)
{
  for (; list && *list; ++list)
    if (name == *list)
      return true;
  return false;
}

DeviceSession::DeviceSession(bool verbose, MessageSink sink)
    : m_verbose(verbose), m_sink(sink)
{}

DeviceSession::~DeviceSession()
{
  if (m_device) {
    for (auto it = m_objects.rbegin(); it != m_objects.rend(); ++it)
      if (*it)
        anariRelease(m_device, *it);
    anariRelease(m_device, m_device);
  }
  if (m_library)
    anariUnloadLibrary(m_library);
}

// NOTE: called from device threads.
void DeviceSession::onStatus(const void *self,
    ANARIDevice,
    ANARIObject,
    ANARIDataType,
    ANARIStatusSeverity severity,
    ANARIStatusCode,
    const char *message)
{
  auto *session = (DeviceSession *)self;
  if (severity <= ANARI_SEVERITY_ERROR)
    session->m_errors++;
  if (session->m_sink
      && (severity <= ANARI_SEVERITY_WARNING || session->m_verbose))
    session->m_sink(std::string("device ") + severityName(severity) + ": "
                    + (message ? message : ""));
}

std::string DeviceSession::open(const DeviceChoice &choice, bool &usage)
{
  usage = true;
  m_library =
      anariLoadLibrary(choice.library.c_str(), &DeviceSession::onStatus, this);
  if (!m_library)
    return "cannot load ANARI library '" + choice.library
           + "' (libanari_library_" + choice.library + ".so)";
  const char **subtypes = anariGetDeviceSubtypes(m_library);
  if (subtypes && *subtypes && choice.deviceSubtype != "default"
      && !contains(subtypes, choice.deviceSubtype))
    return "library '" + choice.library + "' has no device '"
           + choice.deviceSubtype + "' (devices: " + joinList(subtypes) + ")";
  m_device = anariNewDevice(m_library, choice.deviceSubtype.c_str());
  if (!m_device) {
    usage = false;
    return "library '" + choice.library + "' could not create device '"
           + choice.deviceSubtype + "'";
  }
  m_extensions = deviceExtensions(m_library, m_device, choice.deviceSubtype);
  limitThreads(choice);
  return {};
}

void DeviceSession::limitThreads(const DeviceChoice &choice)
{
  if (choice.threads == 0)
    return;
  const auto *parameters = (const ANARIParameter *)anariGetObjectInfo(m_device,
      ANARI_DEVICE,
      choice.deviceSubtype.c_str(),
      "parameter",
      ANARI_PARAMETER_LIST);
  for (; parameters && parameters->name; ++parameters)
    if (std::strcmp(parameters->name, "numThreads") == 0) {
      const int32_t threads = int32_t(choice.threads);
      anariSetParameter(
          m_device, m_device, "numThreads", ANARI_INT32, &threads);
      anariCommitParameters(m_device, m_device);
      return;
    }
}

} // namespace prism::tools
