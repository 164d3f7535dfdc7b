#include "Interrupt.h"

#include <unistd.h>

#include <atomic>
#include <ctime>

namespace prism::render {
namespace {

volatile std::sig_atomic_t g_interrupted = 0;
std::atomic<long long> g_firstInterruptMs{0};

extern "C" void onInterrupt(int)
{
  // Only async-signal-safe calls here.
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  const long long ms = now.tv_sec * 1000ll + now.tv_nsec / 1000000;
  if (!g_interrupted) {
    g_firstInterruptMs = ms;
    g_interrupted = 1;
  } else if (ms - g_firstInterruptMs >= 1000) {
    // Ctrl-C again, a second later: end the process at once. (Sooner, it
    // is the same Ctrl-C delivered twice, as wrappers that signal both the
    // process and its group do.)
    _exit(kExitInterrupted);
  }
}

} // namespace

void watchInterrupts()
{
  std::signal(SIGINT, onInterrupt);
}

bool interrupted()
{
  return g_interrupted != 0;
}

} // namespace prism::render
