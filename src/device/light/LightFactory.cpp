// createLight: every light subtype the device implements, in one place.
#include "Directional.h"
#include "Hdri.h"
#include "Point.h"
#include "Quad.h"
#include "Ring.h"
#include "Spot.h"

namespace prism {

Light *createLight(DeviceState &device, const std::string &subtype)
{
  if (subtype == "directional")
    return new light::Directional(device);
  if (subtype == "hdri")
    return new light::Hdri(device);
  if (subtype == "point")
    return new light::Point(device);
  if (subtype == "quad")
    return new light::Quad(device);
  if (subtype == "ring")
    return new light::Ring(device);
  if (subtype == "spot")
    return new light::Spot(device);
  return nullptr;
}

} // namespace prism
