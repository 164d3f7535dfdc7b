// The image1D sampler (spec 5.10.1): an ARRAY1D of colors filtered at
// the first 1 component(s) of the transformed input attribute.
#pragma once

#include "ImageSampler.h"

namespace prism {

class Image1D : public ImageSampler
{
 public:
  explicit Image1D(DeviceState &device);
};

} // namespace prism
