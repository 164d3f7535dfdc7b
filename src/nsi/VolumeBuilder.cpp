#include "VolumeBuilder.h"

#include "NanoVdbGrid.h"

#include <nsi.h>

#include <algorithm>
#include <cmath>

namespace prism::nsi {

namespace {

bool endsWith(const std::string &text, const std::string &suffix)
{
  return text.size() >= suffix.size()
         && text.compare(text.size() - suffix.size(), suffix.size(), suffix)
                == 0;
}

} // namespace

ANARIVolume newNanoVdbVolume(
    ANARIDevice device, const VolumeItem &item, const ReportFunction &report)
{
  const std::string node = "volume '" + item.handle + "'";
  if (item.fileName.empty()) {
    report(NSIErrWarning, node + " has no vdbfilename; not rendered");
    return nullptr;
  }
  if (endsWith(item.fileName, ".vdb")) {
    report(NSIErrError,
        node + ": '" + item.fileName
            + "' is an OpenVDB file, which Prism cannot read (convert it "
              "to NanoVDB, .nvdb); not rendered");
    return nullptr;
  }
  vdb::NanoVdbGrid grid;
  const std::string error =
      vdb::readNanoVdbGrid(item.fileName, item.densityGrid, grid);
  if (!error.empty()) {
    report(NSIErrError, node + ": " + error + "; not rendered");
    return nullptr;
  }

  ANARIArray1D data = anariNewArray1D(
      device, nullptr, nullptr, nullptr, ANARI_UINT8, grid.handle.size());
  if (void *mapped = anariMapArray(device, data))
    std::copy_n(grid.handle.data(), grid.handle.size(), (uint8_t *)mapped);
  anariUnmapArray(device, data);
  ANARISpatialField field = anariNewSpatialField(device, "nanovdb");
  anariSetParameter(device, field, "data", ANARI_ARRAY1D, &data);
  anariRelease(device, data);
  anariCommitParameters(device, field);

  ANARIVolume volume = anariNewVolume(device, "transferFunction1D");
  anariSetParameter(device, volume, "value", ANARI_SPATIAL_FIELD, &field);
  anariRelease(device, field);
  anariSetParameter(
      device, volume, "color", ANARI_FLOAT32_VEC3, item.shader.color.data());
  // Clear at zero; at the grid's largest value an extinction of `density`
  // per unit length (an opacity of 1 - 1/e over `unitDistance`).
  const float opacity[2] = {0.f, 1.f - std::exp(-1.f)};
  ANARIArray1D opacities =
      anariNewArray1D(device, nullptr, nullptr, nullptr, ANARI_FLOAT32, 2);
  if (void *mapped = anariMapArray(device, opacities))
    std::copy_n(opacity, 2, (float *)mapped);
  anariUnmapArray(device, opacities);
  anariSetParameter(device, volume, "opacity", ANARI_ARRAY1D, &opacities);
  anariRelease(device, opacities);
  const float range[2] = {
      std::min(grid.lo, 0.f), grid.hi > std::min(grid.lo, 0.f) ? grid.hi : 1.f};
  anariSetParameter(device, volume, "valueRange", ANARI_FLOAT32_BOX1, range);
  const float unitDistance =
      item.shader.density > 0 ? 1.f / item.shader.density : 1e30f;
  anariSetParameter(
      device, volume, "unitDistance", ANARI_FLOAT32, &unitDistance);
  anariCommitParameters(device, volume);
  return volume;
}

} // namespace prism::nsi
