// The device library the debug layer wraps, loaded by the layer itself (not
// through libanari) so the layer works under any front-end.
#pragma once

#include "LoadedLibrary.h"

#include <string>

namespace prism::debug {

using WrappedLibrary = frontend::LoadedLibrary;

// The library to wrap when nothing else says: ANARI_DEBUG_WRAPPED_LIBRARY,
// else "prism".
std::string defaultWrappedLibrary();
// The device subtype of the wrapped library to create when nothing else
// says: ANARI_DEBUG_WRAPPED_DEVICE, else the one the application asked the
// layer for (NULL: "default").
std::string defaultWrappedDevice(const char *requested);

} // namespace prism::debug
