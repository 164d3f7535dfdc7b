#include "NanoVdbFile.h"

#include "MachineLimits.h"

#include <sys/stat.h>

#include <nanovdb/util/IO.h>

#include <cerrno>
#include <cstring>
#include <fstream>

namespace prism::vdb {
namespace {

using nanovdb::io::Codec;

bool isRegularFile(const std::string &path)
{
  struct stat info;
  return ::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode);
}

// Reads `count` bytes at the stream's position, if the file has them.
bool readBytes(std::ifstream &file, uint64_t remaining, void *out, size_t count)
{
  return count <= remaining && file.read((char *)out, std::streamsize(count));
}

// The on-disk bytes of a compressed grid: NanoVDB writes each compressed
// chunk (one for ZIP, one per GiB for BLOSC) after its 8-byte size.
std::string checkCompressedChunks(std::ifstream &file,
    uint64_t start,
    const NanoVdbGridEntry &grid,
    const std::string &where)
{
  // NanoVDB's BLOSC chunk size (nanovdb::io::MAX_SIZE).
  constexpr uint64_t kBloscChunk = uint64_t(1) << 30;
  const uint64_t end = start + grid.fileBytes;
  uint64_t position = start;
  uint64_t residual = grid.gridBytes;
  do {
    uint64_t chunkBytes = 0;
    file.seekg(std::streamoff(position));
    if (!readBytes(file, end - position, &chunkBytes, sizeof(chunkBytes))
        || chunkBytes > end - position - sizeof(chunkBytes))
      return where + " has a compressed chunk reaching past its end";
    position += sizeof(chunkBytes) + chunkBytes;
    const uint64_t chunk = grid.codec == uint16_t(Codec::ZIP)
                               ? residual
                               : std::min(residual, kBloscChunk);
    residual -= chunk;
  } while (residual > 0);
  if (position != end)
    return where + " has " + std::to_string(end - position)
           + " bytes after its compressed data";
  return {};
}

} // namespace

std::string nanoVdbGridTypeName(uint32_t gridType)
{
  if (gridType >= uint32_t(nanovdb::GridType::End))
    return "unknown type " + std::to_string(gridType);
  return nanovdb::toStr(nanovdb::GridType(gridType));
}

bool isScalarNanoVdbGridType(uint32_t gridType)
{
  switch (nanovdb::GridType(gridType)) {
  case nanovdb::GridType::Float:
  case nanovdb::GridType::Double:
  case nanovdb::GridType::Int32:
  case nanovdb::GridType::Fp4:
  case nanovdb::GridType::Fp8:
  case nanovdb::GridType::Fp16:
  case nanovdb::GridType::FpN:
    return true;
  default:
    return false;
  }
}

std::string readNanoVdbContents(
    const std::string &path, std::vector<NanoVdbGridEntry> &grids)
{
  grids.clear();
  const std::string name = "NanoVDB file '" + path + "'";
  if (!isRegularFile(path))
    return "cannot read " + name + ": not a regular file";
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file)
    return "cannot read " + name + ": " + std::strerror(errno);
  const uint64_t fileBytes = uint64_t(file.tellg());
  file.seekg(0);
  if (fileBytes == 0)
    return name + " is empty";

  uint64_t position = 0;
  while (position < fileBytes) {
    const std::string segment =
        name + " (segment at byte " + std::to_string(position) + ")";
    nanovdb::io::Header header;
    if (!readBytes(file, fileBytes - position, &header, sizeof(header)))
      return segment + " is truncated: its header is cut short";
    position += sizeof(header);
    if (header.magic != NANOVDB_MAGIC_NUMBER)
      return position == sizeof(header)
                 ? name + " is not a NanoVDB file (wrong magic number)"
                 : segment + " is corrupt (wrong magic number)";
    // (Version::c_str() hands out memory nobody frees: spelled out here.)
    if (header.version.getMajor() != NANOVDB_MAJOR_VERSION_NUMBER)
      return name + " is NanoVDB version "
             + std::to_string(header.version.getMajor()) + "."
             + std::to_string(header.version.getMinor()) + "."
             + std::to_string(header.version.getPatch())
             + "; prism-render reads version "
             + std::to_string(NANOVDB_MAJOR_VERSION_NUMBER) + ".x";
    if (uint16_t(header.codec) > uint16_t(Codec::BLOSC))
      return segment + " names an unknown compression codec ("
             + std::to_string(uint16_t(header.codec)) + ")";

    std::vector<NanoVdbGridEntry> segmentGrids;
    for (uint16_t i = 0; i < header.gridCount; i++) {
      nanovdb::io::MetaData meta;
      if (!readBytes(file, fileBytes - position, &meta, sizeof(meta)))
        return segment + " is truncated in the metadata of grid "
               + std::to_string(grids.size() + i);
      position += sizeof(meta);
      if (meta.nameSize == 0 || meta.nameSize > fileBytes - position)
        return segment + " is corrupt: grid name size "
               + std::to_string(meta.nameSize) + " reaches past the file";
      std::string gridName(meta.nameSize, '\0');
      if (!readBytes(file, fileBytes - position, gridName.data(), meta.nameSize)
          || gridName.back() != '\0')
        return segment + " is corrupt: a grid name is not terminated";
      position += meta.nameSize;
      gridName.resize(std::strlen(gridName.c_str()));
      NanoVdbGridEntry grid;
      grid.name = gridName;
      grid.gridType = uint32_t(meta.gridType);
      grid.codec = uint16_t(header.codec);
      grid.gridBytes = meta.gridSize;
      grid.fileBytes = meta.fileSize;
      grid.index = grids.size() + i;
      segmentGrids.push_back(grid);
    }
    for (const NanoVdbGridEntry &grid : segmentGrids) {
      const std::string where = name + ": grid " + std::to_string(grid.index)
                                + " ('" + grid.name + "')";
      if (grid.fileBytes > fileBytes - position)
        return where + " is truncated: it needs "
               + std::to_string(grid.fileBytes) + " bytes, the file has "
               + std::to_string(fileBytes - position) + " left";
      // A grid is at least its 672-byte header and its tree's.
      constexpr uint64_t kSmallestGrid =
          sizeof(nanovdb::GridData) + sizeof(nanovdb::TreeData<3>);
      if (grid.gridBytes < kSmallestGrid
          || grid.gridBytes % NANOVDB_DATA_ALIGNMENT != 0)
        return where + " is corrupt: a grid of "
               + std::to_string(grid.gridBytes) + " bytes";
      if (grid.codec == uint16_t(Codec::NONE)) {
        if (grid.fileBytes != grid.gridBytes)
          return where + " is corrupt: " + std::to_string(grid.fileBytes)
                 + " bytes on disk for a grid of "
                 + std::to_string(grid.gridBytes);
      } else {
        // Inflated, the grid is allocated as claimed: it must fit.
        if (!limits::fitsInMemory(grid.gridBytes))
          return where + " would inflate to " + limits::byteSize(grid.gridBytes)
                 + ", more than " + limits::memoryLimitText();
        // No codec inflates more than ~1000:1; a bigger claim is corrupt
        // (and would be allocated as claimed).
        if (grid.gridBytes / 2048 > grid.fileBytes)
          return where + " is corrupt: " + std::to_string(grid.gridBytes)
                 + " bytes claimed from " + std::to_string(grid.fileBytes)
                 + " compressed";
        const std::string why =
            checkCompressedChunks(file, position, grid, where);
        if (!why.empty())
          return why;
      }
      position += grid.fileBytes;
      grids.push_back(grid);
    }
    file.seekg(std::streamoff(position));
  }
  if (grids.empty())
    return name + " holds no grids";
  return {};
}

} // namespace prism::vdb
