#include "Image3D.h"

namespace prism {

Image3D::Image3D(DeviceState &device)
    : ImageSampler(device,
        "image3D",
        3,
        {"wrapMode1", "wrapMode2", "wrapMode3"},
        isColorElementType)
{}

} // namespace prism
