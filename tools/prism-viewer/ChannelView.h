// Mapped frame channels as 8-bit RGBA for the window and screenshots (rows
// bottom first, as ANARI maps them): color as the device encoded it (sRGB),
// depth as grey from near (white) to far (black) over the finite depths,
// normals as 0.5 + 0.5 n, albedo sRGB-encoded, ids as a stable color per
// id (no id: black). The picked object is tinted in place.
#pragma once

#include "Channel.h"

#include <anari/anari.h>

#include <cstdint>
#include <vector>

namespace prism::viewer {

struct Rgba8Image
{
  uint32_t width{0}, height{0};
  std::vector<uint8_t> pixels; // 4 bytes a pixel, row 0 at the bottom
};

// The channel's mapped pixels (`type` as mapped) as RGBA8; empty when the
// type is not one the channel maps to.
Rgba8Image channelToRgba8(Channel channel,
    const void *pixels,
    ANARIDataType type,
    uint32_t width,
    uint32_t height);

// The color an id is shown in (alpha 255); black for ~0u.
uint32_t idColor(uint32_t id);

// Mixes the pixels where `mask` is true halfway to orange.
void tint(Rgba8Image &image, const std::vector<bool> &mask);

} // namespace prism::viewer
