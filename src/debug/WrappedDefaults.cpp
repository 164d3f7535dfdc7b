#include "WrappedLibrary.h"

#include <cstdlib>

namespace prism::debug {

std::string defaultWrappedLibrary()
{
  const char *name = std::getenv("ANARI_DEBUG_WRAPPED_LIBRARY");
  return name && *name ? name : "prism";
}

std::string defaultWrappedDevice(const char *requested)
{
  const char *subtype = std::getenv("ANARI_DEBUG_WRAPPED_DEVICE");
  if (subtype && *subtype)
    return subtype;
  return requested ? requested : "default";
}

} // namespace prism::debug
