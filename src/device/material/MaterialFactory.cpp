// createMaterial: every material subtype the device implements, in one place.
#include "Matte.h"
#include "PhysicallyBased.h"

namespace prism {

Material *createMaterial(DeviceState &device, const std::string &subtype)
{
  if (subtype == "matte")
    return new Matte(device);
  if (subtype == "physicallyBased")
    return new PhysicallyBased(device);
  return nullptr;
}

} // namespace prism
