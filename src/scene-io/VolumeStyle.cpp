#include "VolumeStyle.h"

#include "ColorMaps.h"
#include "Objects.h"

#include <algorithm>
#include <cmath>

namespace prism::scene_io {

scenes::TransferFunction transferFunctionFor(
    const TransferFunctionOptions &options, float dataLo, float dataHi)
{
  scenes::TransferFunction tf;
  tf.colors = scenes::linearColors(scenes::colorMaps().front()); // coolwarm
  tf.opacities = {0.f, 0.05f, 0.2f, 0.5f, 1.f};
  // A constant field still needs lo < hi.
  tf.valueRange = {dataLo,
      dataHi > dataLo ? dataHi
                      : dataLo + std::max(1e-6f, std::abs(dataLo) * 1e-6f)};
  tf.unitDistance = 1.f;
  applyTransferFunctionOptions(options, tf);
  return tf;
}

void applyTransferFunctionOptions(const TransferFunctionOptions &options,
    scenes::TransferFunction &transferFunction)
{
  if (options.valueRange)
    transferFunction.valueRange = *options.valueRange;
  // Options checked the name: an unknown one cannot get here.
  if (const scenes::ColorMap *map = scenes::findColorMap(options.colorMap))
    transferFunction.colors = scenes::linearColors(*map);
  if (!options.opacities.empty())
    transferFunction.opacities = options.opacities;
  if (options.unitDistance)
    transferFunction.unitDistance = *options.unitDistance;
}

ANARIWorld newVolumeWorld(ANARIDevice device,
    ANARISpatialField field,
    const scenes::TransferFunction &transferFunction)
{
  ANARIVolume volume =
      scenes::newTransferFunctionVolume(device, field, transferFunction);
  anariRelease(device, field);
  ANARIWorld world = anariNewWorld(device);
  scenes::setObjectArray(device, world, "volume", ANARI_VOLUME, {volume});
  anariCommitParameters(device, world);
  anariRelease(device, volume);
  return world;
}

std::string whyVolumesCannotRender(ANARIDevice device,
    const char *fieldSubtype,
    const char *fieldExtension,
    const std::string &what)
{
  if (scenes::hasSubtype(device, ANARI_SPATIAL_FIELD, fieldSubtype)
      && scenes::hasSubtype(device, ANARI_VOLUME, "transferFunction1D"))
    return {};
  return std::string("this device does not implement ") + fieldExtension
         + " with KHR_VOLUME_TRANSFER_FUNCTION1D, so " + what
         + " cannot be rendered with it";
}

} // namespace prism::scene_io
