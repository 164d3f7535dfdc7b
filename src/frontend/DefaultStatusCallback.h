// The status callback used when an application passes none to
// anariLoadLibrary: messages at or above ANARI_LOG_LEVEL (default
// "warning") go to stderr, so errors are never silently lost.
#pragma once

#include "anari/anari.h"

namespace prism::frontend {

void defaultStatusCallback(const void *userPtr,
    ANARIDevice device,
    ANARIObject source,
    ANARIDataType sourceType,
    ANARIStatusSeverity severity,
    ANARIStatusCode code,
    const char *message);

} // namespace prism::frontend
