#include "NanoVdbLoader.h"

#include "NanoVdbFile.h"
#include "Objects.h"
#include "VolumeStyle.h"

#ifdef PRISM_RENDER_HAS_ZLIB
#define NANOVDB_USE_ZIP
#endif
#include <nanovdb/util/IO.h>

#include <cmath>
#include <type_traits>

namespace prism::render {
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
           + "' is BLOSC-compressed, which prism-render cannot read "
             "(uncompressed and ZIP-compressed grids are read)";
#ifndef PRISM_RENDER_HAS_ZLIB
  if (chosen->codec == uint16_t(nanovdb::io::Codec::ZIP))
    return file + ": grid '" + chosen->name
           + "' is ZIP-compressed, and this prism-render was built without "
             "zlib (uncompressed grids are read)";
#endif
  return {};
}

struct GridSummary
{
  bool hasValueRange{false};
  float lo{0.f}, hi{1.f}; // the active values' minimum and maximum
  scenes::Bounds worldBounds;
};

// The root's min/max of a grid of build type T; the offsets are checked
// against the buffer first (the file may be corrupt).
template <typename BuildT>
std::string summarize(const uint8_t *bytes, uint64_t size, GridSummary &out)
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
    const uint8_t *bytes, uint64_t size, uint32_t type, GridSummary &out)
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
  out.worldBounds.extend(scenes::Vec3{
      float(box.min()[0]), float(box.min()[1]), float(box.min()[2])});
  out.worldBounds.extend(scenes::Vec3{
      float(box.max()[0]), float(box.max()[1]), float(box.max()[2])});
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

LoadResult loadNanoVdb(ANARIDevice device,
    const std::string &path,
    const std::string &gridName,
    const TransferFunctionOptions &transferFunction)
{
  LoadResult result;
  scenes::Scene &scene = result.scene;
  scene.name = path;
  scene.description = "NanoVDB grid";
  scene.emitsLight = false;
  const std::string file = "NanoVDB file '" + path + "'";
  std::vector<NanoVdbGridEntry> grids;
  result.error = readNanoVdbContents(path, grids);
  if (!result.error.empty())
    return result;
  const NanoVdbGridEntry *entry = nullptr;
  result.error = chooseGrid(grids, gridName, file, entry);
  if (!result.error.empty())
    return result;
  // The file is fine; whether it can be rendered is up to the device.
  result.error = whyVolumesCannotRender(
      device, "nanovdb", "KHR_SPATIAL_FIELD_NANOVDB", file);
  if (!result.error.empty())
    return result;

  nanovdb::GridHandle<nanovdb::HostBuffer> handle;
  try {
    handle = nanovdb::io::readGrid<nanovdb::HostBuffer>(path, entry->index);
  } catch (const std::bad_alloc &) {
    throw;
  } catch (const std::exception &e) {
    // NanoVDB's messages are its own ("UNZIP failed on byte size").
    result.error = "cannot read " + file + ": grid '" + entry->name
                   + "': " + e.what()
                   + (entry->codec != uint16_t(nanovdb::io::Codec::NONE)
                           ? " (corrupt compressed data)"
                           : "");
    return result;
  }
  const std::string where = file + ": grid '" + entry->name + "' is corrupt: ";
  if (!handle || handle.size() != entry->gridBytes) {
    result.error = where + "NanoVDB read " + std::to_string(handle.size())
                   + " of its " + std::to_string(entry->gridBytes) + " bytes";
    return result;
  }
  GridSummary summary;
  const std::string why =
      summarizeGrid(handle.data(), handle.size(), entry->gridType, summary);
  if (!why.empty()) {
    result.error = where + why;
    return result;
  }
  if (!summary.hasValueRange && !transferFunction.valueRange)
    scene.notes.push_back(file + ": grid '" + entry->name
                          + "' has no min/max statistics; the transfer "
                            "function spans 0 to 1 (--tf-range sets it)");
  scene.bounds = summary.worldBounds;

  ANARIArray1D data =
      scenes::newArray1D(device, ANARI_UINT8, handle.data(), handle.size(), 1);
  ANARISpatialField field = anariNewSpatialField(device, "nanovdb");
  scenes::setObject(device, field, "data", ANARI_ARRAY1D, data);
  anariRelease(device, data);
  anariCommitParameters(device, field);
  scene.world = newVolumeWorld(device,
      field,
      transferFunctionFor(transferFunction, summary.lo, summary.hi));
  return result;
}

} // namespace prism::render
