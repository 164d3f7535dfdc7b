#include "VolumeStyle.h"

#include "ColorMaps.h"
#include "Objects.h"

#include <algorithm>
#include <cmath>

namespace prism::render {

scenes::TransferFunction transferFunctionFor(
    const TransferFunctionOptions &options, float dataLo, float dataHi)
{
  scenes::TransferFunction tf;
  const scenes::ColorMap *map = scenes::findColorMap(options.colorMap);
  if (!map) // Options checked the name; a default keeps this total
    map = &scenes::colorMaps().front();
  tf.colors = scenes::linearColors(*map);
  tf.opacities = options.opacities.empty()
                     ? std::vector<float>{0.f, 0.05f, 0.2f, 0.5f, 1.f}
                     : options.opacities;
  if (options.valueRange) {
    tf.valueRange = *options.valueRange;
  } else {
    // A constant field still needs lo < hi.
    tf.valueRange = {dataLo,
        dataHi > dataLo ? dataHi
                        : dataLo + std::max(1e-6f, std::abs(dataLo) * 1e-6f)};
  }
  tf.unitDistance = options.unitDistance;
  return tf;
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

} // namespace prism::render
