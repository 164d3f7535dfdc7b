// How much memory a frame of the requested size takes (the device's
// buffers and prism-render's copies), so absurd sizes are refused with a
// message instead of aborting in an allocation or swapping for minutes.
#pragma once

#include "Options.h"

#include <cstdint>
#include <string>

namespace prism::render {

// Bytes a render of `options` needs, estimated for a CPU device.
uint64_t estimatedFrameBytes(const Options &options);

// The machine's physical memory in bytes (0 if unknown).
uint64_t physicalMemoryBytes();

// Why `options` cannot be rendered on this machine, or empty.
std::string whyFrameDoesNotFit(const Options &options);

} // namespace prism::render
