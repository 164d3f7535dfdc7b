#include "DefaultStatusCallback.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace prism::frontend {
namespace {

// Highest severity number still printed (ANARI_SEVERITY_* grow with detail).
int printedSeverityLimit()
{
  const char *level = std::getenv("ANARI_LOG_LEVEL");
  if (!level)
    return ANARI_SEVERITY_WARNING;
  struct Level
  {
    const char *name;
    int limit;
  };
  static const Level kLevels[] = {{"none", 0},
      {"fatal", ANARI_SEVERITY_FATAL_ERROR},
      {"error", ANARI_SEVERITY_ERROR},
      {"warning", ANARI_SEVERITY_PERFORMANCE_WARNING},
      {"info", ANARI_SEVERITY_INFO},
      {"debug", ANARI_SEVERITY_DEBUG}};
  for (const auto &l : kLevels) {
    if (std::strcmp(level, l.name) == 0)
      return l.limit;
  }
  return ANARI_SEVERITY_WARNING;
}

const char *severityName(ANARIStatusSeverity severity)
{
  switch (severity) {
  case ANARI_SEVERITY_FATAL_ERROR:
    return "fatal";
  case ANARI_SEVERITY_ERROR:
    return "error";
  case ANARI_SEVERITY_WARNING:
    return "warning";
  case ANARI_SEVERITY_PERFORMANCE_WARNING:
    return "performance";
  case ANARI_SEVERITY_INFO:
    return "info";
  default:
    return "debug";
  }
}

} // namespace

void defaultStatusCallback(const void *,
    ANARIDevice,
    ANARIObject,
    ANARIDataType,
    ANARIStatusSeverity severity,
    ANARIStatusCode,
    const char *message)
{
  static const int limit = printedSeverityLimit();
  if (severity <= limit)
    std::fprintf(stderr,
        "[anari] %s: %s\n",
        severityName(severity),
        message ? message : "(no message)");
}

} // namespace prism::frontend
