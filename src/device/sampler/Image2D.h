// The image2D sampler (spec 5.10.2): an ARRAY2D of colors filtered at
// the first 2 component(s) of the transformed input attribute.
#pragma once

#include "ImageSampler.h"

namespace prism {

class Image2D : public ImageSampler
{
 public:
  explicit Image2D(DeviceState &device);
};

} // namespace prism
