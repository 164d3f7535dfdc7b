#include "Image1D.h"

namespace prism {

Image1D::Image1D(DeviceState &device)
    : ImageSampler(device,
        "image1D",
        1,
        {"wrapMode", nullptr, nullptr},
        isColorElementType)
{}

} // namespace prism
