// One scalar grid of a NanoVDB file, read for a `nanovdb` spatial field:
// chosen by name (or the first scalar grid), read by NanoVDB's own reader
// once the file's layout is checked (NanoVdbFile.*), its header checked
// against the table of contents and its value range and bounds taken.
#pragma once

#include <nanovdb/util/GridHandle.h>

#include <array>
#include <string>

namespace prism::vdb {

struct NanoVdbGrid
{
  nanovdb::GridHandle<nanovdb::HostBuffer> handle;
  std::string name;
  bool hasValueRange{false}; // the grid has min/max statistics
  float lo{0.f}, hi{1.f};    // the active values' minimum and maximum
  std::array<float, 3> worldLower{}, worldUpper{};
};

// `gridName` empty: the first scalar grid. Uncompressed and (where zlib was
// found at build time) ZIP-compressed grids are read; BLOSC ones are
// refused by name. The error names the file and the grid.
std::string readNanoVdbGrid(
    const std::string &path, const std::string &gridName, NanoVdbGrid &out);

} // namespace prism::vdb
