#include "OutputChannels.h"

namespace prism::nsi {

namespace {
const FrameChannel kChannels[] = {
    {"channel.color", ANARI_FLOAT32_VEC4, 4},
    {"channel.depth", ANARI_FLOAT32, 1},
    {"channel.normal", ANARI_FLOAT32_VEC3, 3},
    {"channel.albedo", ANARI_FLOAT32_VEC3, 3},
};
} // namespace

const FrameChannel *channelForVariable(const std::string &variableName)
{
  if (variableName == "Ci")
    return &kChannels[0];
  if (variableName == "z")
    return &kChannels[1];
  if (variableName == "N.world")
    return &kChannels[2];
  if (variableName == "albedo")
    return &kChannels[3];
  return nullptr;
}

image::Image readFrameChannel(
    ANARIDevice device, ANARIFrame frame, const FrameChannel &channel)
{
  uint32_t width = 0, height = 0;
  ANARIDataType type = ANARI_UNKNOWN;
  const auto *values = static_cast<const float *>(
      anariMapFrame(device, frame, channel.name, &width, &height, &type));
  image::Image picture(width, height);
  if (values && type == channel.type) {
    const int n = channel.components;
    for (size_t i = 0; i < picture.pixels.size(); ++i) {
      const float *v = values + n * i;
      if (n == 1)
        picture.pixels[i] = {v[0], v[0], v[0], 1.f};
      else if (n == 3)
        picture.pixels[i] = {v[0], v[1], v[2], 1.f};
      else
        picture.pixels[i] = {v[0], v[1], v[2], v[3]};
    }
  }
  anariUnmapFrame(device, frame, channel.name);
  return picture;
}

} // namespace prism::nsi
