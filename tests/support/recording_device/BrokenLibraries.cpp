// Two deliberately broken device libraries for the loader's error paths:
// "noentry" exports no entry point, "nulldevice" has one that returns NULL.
#include "anari/anari.h"

#ifdef PRISM_BROKEN_NULL_ENTRY
extern "C" __attribute__((visibility("default"))) ANARILibrary
anari_library_nulldevice_new_library(void *, ANARIStatusCallback, const void *)
{
  return nullptr;
}
#else
extern "C" __attribute__((visibility("default"))) int not_an_anari_entry_point(
    void)
{
  return 0;
}
#endif
