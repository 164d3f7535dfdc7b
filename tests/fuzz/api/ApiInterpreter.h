// Runs one ApiProgram against the prism device through libanari, checking
// what the API promises along the way: well-formed status messages, frames
// no larger than asked for, deleters called exactly once by the time the
// devices are released. A broken promise aborts (a crash for libFuzzer).
#pragma once

#include "ApiProgram.h"

#include <cstddef>
#include <cstdint>

namespace prism::fuzz {

// Loads the prism library once per process; it is never unloaded, so its
// coverage counters stay mapped (call before fuzzing starts, so libFuzzer
// sees the library's counters from the first input).
void loadDeviceLibrary();
// Runs `program` on fresh devices; everything it made is released before it
// returns.
void runProgram(const uint8_t *data, size_t size);

// Counters over every program run so far (for the fuzzer's final report).
struct RunStatistics
{
  uint64_t programs = 0;
  uint64_t calls = 0;           // ANARI calls made
  uint64_t messages = 0;        // status messages received
  uint64_t errors = 0;          // of which severity error or fatal
  uint64_t framesCompleted = 0; // frame completion callbacks
  uint64_t framesMapped = 0;    // frames mapped with pixels
};
RunStatistics statistics();

} // namespace prism::fuzz
