// The image3D sampler (spec 5.10.3): an ARRAY3D of colors filtered at
// the first 3 component(s) of the transformed input attribute.
#pragma once

#include "ImageSampler.h"

namespace prism {

class Image3D : public ImageSampler
{
 public:
  explicit Image3D(DeviceState &device);
};

} // namespace prism
