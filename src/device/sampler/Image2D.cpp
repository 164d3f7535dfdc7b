#include "Image2D.h"

namespace prism {
namespace {

// The image2D JSON adds signed FIXED8_VEC3/VEC4 (e.g. normal maps) to the
// color types.
bool acceptsElementType(ANARIDataType type)
{
  return isColorElementType(type) || type == ANARI_FIXED8_VEC3
         || type == ANARI_FIXED8_VEC4;
}

} // namespace

Image2D::Image2D(DeviceState &device)
    : ImageSampler(device,
        "image2D",
        2,
        {"wrapMode1", "wrapMode2", nullptr},
        acceptsElementType)
{}

} // namespace prism
