// createSampler: every sampler subtype the device implements, in one place.
#include "Image1D.h"
#include "Image2D.h"
#include "Image3D.h"
#include "Primitive.h"
#include "Transform.h"

namespace prism {

Sampler *createSampler(DeviceState &device, const std::string &subtype)
{
  if (subtype == "image1D")
    return new Image1D(device);
  if (subtype == "image2D")
    return new Image2D(device);
  if (subtype == "image3D")
    return new Image3D(device);
  if (subtype == "primitive")
    return new Primitive(device);
  if (subtype == "transform")
    return new Transform(device);
  return nullptr;
}

} // namespace prism
