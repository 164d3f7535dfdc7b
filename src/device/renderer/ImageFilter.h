// Bilinear filtering of float4 images, used to stretch a background image
// over a frame of another size. Images are row-major with the first row at
// the bottom (ANARI's lower-left origin); both sides share it, so no flip.
#pragma once

#include "../math/Vec.h"

#include <cstdint>

namespace prism {

// Bilinear lookup at normalised (u, v) with clamp-to-edge; texel (i, j) has
// its centre at ((i + 0.5) / width, (j + 0.5) / height). An empty image
// gives (0, 0, 0, 0).
float4 sampleBilinear(
    const float4 *texels, uint32_t width, uint32_t height, float u, float v);

// dst pixel (x, y) = the bilinear lookup at ((x + 0.5) / dstW,
// (y + 0.5) / dstH), with positions computed exactly in integers so equal
// sizes copy and texel centres reproduce texels bit for bit. An empty
// source fills dst with (0, 0, 0, 0).
void resizeBilinear(const float4 *src,
    uint32_t srcW,
    uint32_t srcH,
    float4 *dst,
    uint32_t dstW,
    uint32_t dstH);

} // namespace prism
