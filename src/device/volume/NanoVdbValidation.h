// Checks that a NanoVDB grid buffer can be read without leaving it: header,
// version, grid type and class, map, and every node offset the tree's
// accessors follow. NanoVDB itself trusts its buffers; fields call this
// before touching anything else in application data.
#pragma once

#include <cstdint>
#include <string>

namespace prism {

// Why the grid at `grid` (32-byte aligned, `size` bytes readable) cannot be
// sampled, or an empty string when every offset and count in it is sound.
std::string whyNanoVdbGridIsUnreadable(const uint8_t *grid, uint64_t size);

} // namespace prism
