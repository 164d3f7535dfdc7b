#include "ChannelView.h"

#include "ImageIO.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace prism::viewer {
namespace {

uint8_t unorm(float v)
{
  return uint8_t(std::lround(std::clamp(v, 0.f, 1.f) * 255.f));
}

void depthToGrey(const float *depth, size_t count, uint8_t *out)
{
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  for (size_t i = 0; i < count; ++i)
    if (std::isfinite(depth[i])) {
      lo = std::min(lo, depth[i]);
      hi = std::max(hi, depth[i]);
    }
  const float span = hi > lo ? hi - lo : 1.f;
  for (size_t i = 0; i < count; ++i) {
    const uint8_t g = std::isfinite(depth[i])
                          ? unorm(1.f - 0.8f * (depth[i] - lo) / span)
                          : 0;
    uint8_t *p = out + 4 * i;
    p[0] = p[1] = p[2] = g;
    p[3] = 255;
  }
}

} // namespace

uint32_t idColor(uint32_t id)
{
  if (id == 0xffffffffu)
    return 0xff000000u;
  // A multiplicative hash spreads neighbouring ids over the hues; the
  // floor of 64 keeps every id visible against black.
  uint32_t h = id * 2654435761u;
  h ^= h >> 15;
  const uint32_t r = 64 + (h & 0xff) % 192, g = 64 + ((h >> 8) & 0xff) % 192,
                 b = 64 + ((h >> 16) & 0xff) % 192;
  return 0xff000000u | (b << 16) | (g << 8) | r;
}

Rgba8Image channelToRgba8(Channel channel,
    const void *pixels,
    ANARIDataType type,
    uint32_t width,
    uint32_t height)
{
  Rgba8Image image;
  if (!pixels || width == 0 || height == 0)
    return image;
  const size_t count = size_t(width) * height;
  image.width = width;
  image.height = height;
  image.pixels.resize(4 * count);
  uint8_t *out = image.pixels.data();
  if (channel == Channel::Color
      && (type == ANARI_UFIXED8_RGBA_SRGB || type == ANARI_UFIXED8_VEC4)) {
    std::memcpy(out, pixels, 4 * count);
  } else if (channel == Channel::Color && type == ANARI_FLOAT32_VEC4) {
    const float *in = (const float *)pixels;
    for (size_t i = 0; i < 4 * count; ++i)
      out[i] = unorm(i % 4 == 3 ? in[i] : image::srgbFromLinear(in[i]));
  } else if (channel == Channel::Depth && type == ANARI_FLOAT32) {
    depthToGrey((const float *)pixels, count, out);
  } else if ((channel == Channel::Normal || channel == Channel::Albedo)
             && type == ANARI_FLOAT32_VEC3) {
    const float *in = (const float *)pixels;
    for (size_t i = 0; i < count; ++i)
      for (int c = 0; c < 4; ++c)
        out[4 * i + c] = c == 3 ? 255
                         : channel == Channel::Normal
                             ? unorm(0.5f + 0.5f * in[3 * i + c])
                             : unorm(image::srgbFromLinear(in[3 * i + c]));
  } else if (type == ANARI_UINT32 && channel != Channel::Color) {
    const uint32_t *in = (const uint32_t *)pixels;
    for (size_t i = 0; i < count; ++i) {
      const uint32_t c = idColor(in[i]);
      std::memcpy(out + 4 * i, &c, 4);
    }
  } else {
    return {};
  }
  return image;
}

void tint(Rgba8Image &image, const std::vector<bool> &mask)
{
  const uint8_t orange[3] = {255, 150, 0};
  for (size_t i = 0; i < mask.size() && 4 * i < image.pixels.size(); ++i)
    if (mask[i])
      for (int c = 0; c < 3; ++c)
        image.pixels[4 * i + c] =
            uint8_t((image.pixels[4 * i + c] + orange[c]) / 2);
}

} // namespace prism::viewer
