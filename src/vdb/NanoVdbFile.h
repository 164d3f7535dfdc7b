// The table of contents of a NanoVDB file (.nvdb): segments of a 16-byte
// header, one metadata record per grid and the grids' bytes. Every size in
// it is checked against the file's size before NanoVDB's reader sees the
// file: that reader trusts them (a corrupt name or grid size becomes an
// allocation of that many bytes, a name without its NUL an over-read).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace prism::vdb {

struct NanoVdbGridEntry
{
  std::string name;
  uint32_t gridType{0};  // nanovdb::GridType
  uint16_t codec{0};     // nanovdb::io::Codec: 0 none, 1 ZIP, 2 BLOSC
  uint64_t gridBytes{0}; // in memory, once read
  uint64_t fileBytes{0}; // on disk, compressed or not
  uint64_t index{0};     // its position in the file, as readGrid counts
};

// The grids of the NanoVDB file at `path`, in file order; an error (one
// line, naming the file and what is wrong) for anything that does not add
// up: a bad magic number or version, sizes past the end of the file, a
// truncated file, trailing bytes.
std::string readNanoVdbContents(
    const std::string &path, std::vector<NanoVdbGridEntry> &grids);

// "float", "Vec3f", ... for messages.
std::string nanoVdbGridTypeName(uint32_t gridType);

// Whether a nanovdb field renders grids of this type as scalars.
bool isScalarNanoVdbGridType(uint32_t gridType);

} // namespace prism::vdb
