// Runs one ApiProgram against the prism device through libanari, checking
// what the API promises along the way: well-formed status messages, frames
// no larger than asked for, deleters called exactly once by the time the
// devices are released. A broken promise aborts (a crash for libFuzzer).
#pragma once

#include "ApiProgram.h"

#include <cstddef>
#include <cstdint>

namespace prism::fuzz {

// Known device defects the interpreter can stay clear of while their fixes
// are pending (PRISM_FUZZ_API_AVOID, a mask of these; 0 in the committed
// build, so every one of them is exercised).
enum AvoidMask : unsigned {
  kAvoidForeignHandles = 1,    // handles of another device
  kAvoidAbsurdFrameSize = 2,   // frames of 100000x100000
  kAvoidExtremeTransforms = 4, // 1e30/NaN/inf in instance transforms
  kAvoidCycles = 8,            // arrays holding themselves or their holder
  kAvoidObjectArrayRemap = 16, // mapping object arrays again
  kAvoidNullMaterial = 32,     // committing surfaces without a material
  kAvoidFreeOnDelete = 64,     // deleters free application memory at the end
};

// Loads the prism library once per process; it is never unloaded, so its
// coverage counters stay mapped (call before fuzzing starts, so libFuzzer
// sees the library's counters from the first input).
void loadDeviceLibrary();
// Runs `program` on fresh devices; everything it made is released before it
// returns.
void runProgram(const uint8_t *data, size_t size, unsigned avoid);

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
