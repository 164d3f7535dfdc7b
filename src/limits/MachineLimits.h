// What this machine can hold and run: the one place that turns numbers a
// user or a file gives (array sizes, thread counts, sizes read from files)
// into "fits" or "refused, because the limit is ...". The device, the MPI
// device, libnsi, the NanoVDB reader and anari-replay all ask here, so a
// limit is stated once and every refusal names the same one.
#pragma once

#include <cstdint>
#include <string>

namespace prism::limits {

// This machine's physical memory in bytes; 0 when the system does not say.
uint64_t physicalMemoryBytes();

// Whether `bytes` fit in physical memory (true when it is unknown): more
// could only be served by swapping, and a zero-filled allocation that large
// takes minutes before failing.
bool fitsInMemory(uint64_t bytes);

// Hardware threads of this machine (at least 1).
unsigned hardwareThreads();

// The largest thread count a task pool takes: a few times the hardware
// threads (oversubscribing helps tests and uneven work; TBB dies building
// an arena of millions of slots).
unsigned maxPoolThreads();

// `bytes` for a message: "512 B", "3.0 MiB", "22.9 GiB".
std::string byteSize(uint64_t bytes);

// "the machine's 22.9 GiB of memory", for messages naming the limit.
std::string memoryLimitText();

// The product of `count` sizes in elements of `elementBytes` bytes, false
// when it overflows 64 bits.
bool checkedBytes(
    const uint64_t *sizes, int count, uint64_t elementBytes, uint64_t &bytes);

} // namespace prism::limits
