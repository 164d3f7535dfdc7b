#include "NanoVdbLoader.h"

#include "NanoVdbGrid.h"
#include "Objects.h"
#include "VolumeStyle.h"

namespace prism::scene_io {

LoadResult loadNanoVdb(ANARIDevice device,
    const std::string &path,
    const std::string &gridName,
    const TransferFunctionOptions &transferFunction)
{
  LoadResult result;
  scenes::Scene &scene = result.scene;
  scene.name = path;
  scene.description = "NanoVDB grid";
  scene.expectsEnvironment = true;
  const std::string file = "NanoVDB file '" + path + "'";
  vdb::NanoVdbGrid grid;
  result.error = vdb::readNanoVdbGrid(path, gridName, grid);
  if (!result.error.empty())
    return result;
  // The file is fine; whether it can be rendered is up to the device.
  result.error = whyVolumesCannotRender(
      device, "nanovdb", "KHR_SPATIAL_FIELD_NANOVDB", file);
  if (!result.error.empty())
    return result;
  if (!grid.hasValueRange && !transferFunction.valueRange)
    scene.notes.push_back(file + ": grid '" + grid.name
                          + "' has no min/max statistics; the transfer "
                            "function spans 0 to 1 (--tf-range sets it)");
  scene.bounds.extend(
      scenes::Vec3{grid.worldLower[0], grid.worldLower[1], grid.worldLower[2]});
  scene.bounds.extend(
      scenes::Vec3{grid.worldUpper[0], grid.worldUpper[1], grid.worldUpper[2]});

  ANARIArray1D data = scenes::newArray1D(
      device, ANARI_UINT8, grid.handle.data(), grid.handle.size(), 1);
  ANARISpatialField field = anariNewSpatialField(device, "nanovdb");
  scenes::setObject(device, field, "data", ANARI_ARRAY1D, data);
  anariRelease(device, data);
  anariCommitParameters(device, field);
  scene.world = newVolumeWorld(
      device, field, transferFunctionFor(transferFunction, grid.lo, grid.hi));
  return result;
}

} // namespace prism::scene_io
