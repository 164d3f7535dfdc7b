#include "NanoVdbGrid.h"

#include "NanoVdbFile.h"

#ifdef PRISM_VDB_HAS_ZLIB
#define NANOVDB_USE_ZIP
#endif
#include <nanovdb/util/IO.h>

#include <cmath>
#include <new>
#include <vector>

namespace prism::vdb {
namespace {

// The grid the user asked for, or why there is none.
std::string chooseGrid(const std::vector<NanoVdbGridEntry> &grids,
    const std::string &gridName,
    const std::string &file,
    const NanoVdbGridEntry *&chosen)
{
  chosen = nullptr;
  std::string names;
  for (const NanoVdbGridEntry &grid : grids) {
    names += (names.empty() ? "'" : ", '") + grid.name + "' ("
             + nanoVdbGridTypeName(grid.gridType) + ")";
    const bool wanted = gridName.empty()
                            ? isScalarNanoVdbGridType(grid.gridType)
                            : grid.name == gridName;
    if (wanted && !chosen)
      chosen = &grid;
  }
  if (!chosen)
    return file
           + (gridName.empty() ? " has no scalar grid"
                               : " has no grid '" + gridName + "'")
           + " (grids: " + names + ")";
  if (!isScalarNanoVdbGridType(chosen->gridType))
    return file + ": grid '" + chosen->name + "' holds "
           + nanoVdbGridTypeName(chosen->gridType)
           + " values; only scalar grids (float, double, int32, Fp4, Fp8, "
             "Fp16, FpN) are rendered";
  if (chosen->codec == uint16_t(nanovdb::io::Codec::BLOSC))
    return file + ": grid '" + chosen->name
           + "' is BLOSC-compressed, which Prism cannot read "
             "(uncompressed and ZIP-compressed grids are read)";
#ifndef PRISM_VDB_HAS_ZLIB
  if (chosen->codec == uint16_t(nanovdb::io::Codec::ZIP))
    return file + ": grid '" + chosen->name
           + "' is ZIP-compressed, and this Prism was built without "
             "zlib (uncompressed grids are read)";
#endif
  return {};
}

// The root's min/max of a grid of build type T; the offsets are checked
// against the buffer first (the file may be corrupt).
template <typename BuildT>
std::string summarize(const uint8_t *bytes, uint64_t size, NanoVdbGrid &out)
{
  using GridT = nanovdb::NanoGrid<BuildT>;
  using TreeT = typename GridT::TreeType;
  using RootDataT = typename TreeT::RootType::DataType;
  const uint64_t treeStart = sizeof(nanovdb::GridData);
  const auto *tree =
      reinterpret_cast<const nanovdb::TreeData<3> *>(bytes + treeStart);
  const uint64_t rootOffset = tree->mNodeOffset[3];
  if (rootOffset > size - treeStart
      || sizeof(RootDataT) > size - treeStart - rootOffset
      || rootOffset % NANOVDB_DATA_ALIGNMENT != 0)
    return "its root node lies outside the grid or is misaligned";
  const auto &grid = *reinterpret_cast<const GridT *>(bytes);
  if (grid.hasMinMax()) {
    const auto &root =
        *reinterpret_cast<const RootDataT *>(bytes + treeStart + rootOffset);
    const float lo = float(root.mMinimum), hi = float(root.mMaximum);
    if (std::isfinite(lo) && std::isfinite(hi) && lo <= hi) {
      out.lo = lo;
      out.hi = hi;
      out.hasValueRange = true;
    }
  }
  return {};
}

std::string summarizeGrid(
    const uint8_t *bytes, uint64_t size, uint32_t type, NanoVdbGrid &out)
{
  if (size < sizeof(nanovdb::GridData) + sizeof(nanovdb::TreeData<3>))
    return "it is too small";
  const auto &header = *reinterpret_cast<const nanovdb::GridData *>(bytes);
  if (header.mMagic != NANOVDB_MAGIC_NUMBER || header.mGridSize != size
      || uint32_t(header.mGridType) != type)
    return "its header does not match the file's table of contents";
  const auto &box = header.mWorldBBox;
  for (int i = 0; i < 3; i++) {
    if (!std::isfinite(box.min()[i]) || !std::isfinite(box.max()[i])
        || box.min()[i] > box.max()[i])
      return "its world bounding box is not a finite box";
  }
  for (int i = 0; i < 3; i++) {
    out.worldLower[i] = float(box.min()[i]);
    out.worldUpper[i] = float(box.max()[i]);
  }
  switch (nanovdb::GridType(type)) {
  case nanovdb::GridType::Float:
    return summarize<float>(bytes, size, out);
  case nanovdb::GridType::Double:
    return summarize<double>(bytes, size, out);
  case nanovdb::GridType::Int32:
    return summarize<int32_t>(bytes, size, out);
  case nanovdb::GridType::Fp4:
    return summarize<nanovdb::Fp4>(bytes, size, out);
  case nanovdb::GridType::Fp8:
    return summarize<nanovdb::Fp8>(bytes, size, out);
  case nanovdb::GridType::Fp16:
    return summarize<nanovdb::Fp16>(bytes, size, out);
  case nanovdb::GridType::FpN:
    return summarize<nanovdb::FpN>(bytes, size, out);
  default:
    return "it is not a scalar grid";
  }
}

} // namespace

std::string readNanoVdbGrid(
    const std::string &path, const std::string &gridName, NanoVdbGrid &out)
{
  out = {};
  const std::string file = "NanoVDB file '" + path + "'";
  std::vector<NanoVdbGridEntry> grids;
  std::string error = readNanoVdbContents(path, grids);
  if (!error.empty())
    return error;
  const NanoVdbGridEntry *entry = nullptr;
  error = chooseGrid(grids, gridName, file, entry);
  if (!error.empty())
    return error;
  try {
    out.handle = nanovdb::io::readGrid<nanovdb::HostBuffer>(path, entry->index);
  } catch (const std::bad_alloc &) {
    throw;
  } catch (const std::exception &e) {
    // NanoVDB's messages are its own ("UNZIP failed on byte size").
    return "cannot read " + file + ": grid '" + entry->name + "': " + e.what()
           + (entry->codec != uint16_t(nanovdb::io::Codec::NONE)
                   ? " (corrupt compressed data)"
                   : "");
  }
  out.name = entry->name;
  const std::string where = file + ": grid '" + entry->name + "' is corrupt: ";
  if (!out.handle || out.handle.size() != entry->gridBytes)
    return where + "NanoVDB read " + std::to_string(out.handle.size())
           + " of its " + std::to_string(entry->gridBytes) + " bytes";
  const std::string why =
      summarizeGrid(out.handle.data(), out.handle.size(), entry->gridType, out);
  return why.empty() ? why : where + why;
}

} // namespace prism::vdb
