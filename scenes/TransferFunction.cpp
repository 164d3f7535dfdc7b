#include "TransferFunction.h"

#include "Objects.h"

namespace prism::scenes {

ANARIVolume newTransferFunctionVolume(ANARIDevice device,
    ANARISpatialField field,
    const TransferFunction &transferFunction)
{
  ANARIVolume volume = anariNewVolume(device, "transferFunction1D");
  setObject(device, volume, "value", ANARI_SPATIAL_FIELD, field);
  setArray(
      device, volume, "color", ANARI_FLOAT32_VEC3, transferFunction.colors);
  setArray(
      device, volume, "opacity", ANARI_FLOAT32, transferFunction.opacities);
  anariSetParameter(device,
      volume,
      "valueRange",
      ANARI_FLOAT32_BOX1,
      transferFunction.valueRange.data());
  setFloat(device, volume, "unitDistance", transferFunction.unitDistance);
  anariCommitParameters(device, volume);
  return volume;
}

} // namespace prism::scenes
