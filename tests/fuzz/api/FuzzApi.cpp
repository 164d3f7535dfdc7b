// fuzz_api: libFuzzer's entry points around the ANARI call interpreter.
#include "ApiInterpreter.h"

#include <cstdio>
#include <cstdlib>

// Sanitizer settings that hold however the target is started (fuzz.sh, the
// corpus replay test, a developer reproducing a crash by hand).
extern "C" const char *__asan_default_options()
{
  // Leaks are checked after each input; a device's own threads and caches
  // are reachable, so only what an input lost is reported. Allocation stacks
  // of 15 frames keep the fuzzer ~15% faster than 30 (override with
  // ASAN_OPTIONS=malloc_context_size=30 when reproducing). No
  // __tls_get_addr interception: it misreads dynamic TLS blocks and crashes
  // LeakSanitizer's tracer (see scripts/test.sh).
  return "detect_leaks=1:abort_on_error=1:malloc_context_size=15:"
         "intercept_tls_get_addr=0";
}

extern "C" const char *__ubsan_default_options()
{
  return "print_stacktrace=1:halt_on_error=1";
}

namespace {

void printStatistics()
{
  const prism::fuzz::RunStatistics s = prism::fuzz::statistics();
  std::fprintf(stderr,
      "fuzz_api: %llu programs, %llu ANARI calls, %llu status messages "
      "(%llu errors), %llu frames completed, %llu frames mapped\n",
      (unsigned long long)s.programs,
      (unsigned long long)s.calls,
      (unsigned long long)s.messages,
      (unsigned long long)s.errors,
      (unsigned long long)s.framesCompleted,
      (unsigned long long)s.framesMapped);
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int *, char ***)
{
  std::atexit(printStatistics);
  prism::fuzz::loadDeviceLibrary();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  prism::fuzz::runProgram(data, size);
  return 0;
}
