#include "TransferFunction1D.h"

namespace prism {

Volume *createVolume(DeviceState &device, const std::string &subtype)
{
  if (subtype == "transferFunction1D")
    return new TransferFunction1D(device);
  return nullptr;
}

} // namespace prism
