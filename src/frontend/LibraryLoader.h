// Finds, opens and initialises a device library by name, per the loading
// rules of docs/ABI.md.
#pragma once

#include "HandleRegistry.h"

namespace prism::frontend {

// Loads `name` ("helide", "helide,/opt/lib/" or "environment"), or the debug
// layer wrapping it when ANARI_DEBUG_LAYER is set (not "0"); reports the
// reason through `sink` and returns NULL on failure.
anari::LibraryImpl *loadLibrary(const char *name, StatusSink sink);

} // namespace prism::frontend
