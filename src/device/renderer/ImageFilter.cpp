// Bilinear filtering with clamp-to-edge addressing.
#include "ImageFilter.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace prism {

namespace {

// The two texels a coordinate falls between and the weight of the second.
struct Tap
{
  uint32_t i0, i1;
  float f;
};

// `x` in texel units (texel centres at integers), clamped to the edges.
Tap tapAt(float x, uint32_t size)
{
  // Clamping first keeps the cast defined; NaN goes to the first texel.
  const float limit = float(size);
  x = x > -1.f ? (x < limit ? x : limit) : -1.f;
  const float base = std::floor(x);
  const int64_t i = int64_t(base);
  const int64_t last = int64_t(size) - 1;
  return {uint32_t(std::clamp<int64_t>(i, 0, last)),
      uint32_t(std::clamp<int64_t>(i + 1, 0, last)),
      x - base};
}

// Exact tap for dst pixel `x`: the source position (x + 0.5) * srcSize /
// dstSize - 0.5 is the fraction n / d below, kept in integers.
Tap exactTap(uint32_t x, uint32_t srcSize, uint32_t dstSize)
{
  const int64_t n = (2 * int64_t(x) + 1) * srcSize - int64_t(dstSize);
  const int64_t d = 2 * int64_t(dstSize);
  const int64_t i = n >= 0 ? n / d : -((-n + d - 1) / d);
  const int64_t last = int64_t(srcSize) - 1;
  return {uint32_t(std::clamp<int64_t>(i, 0, last)),
      uint32_t(std::clamp<int64_t>(i + 1, 0, last)),
      float(double(n - i * d) / double(d))};
}

float4 blend(const float4 *row0, const float4 *row1, const Tap &tx, float fy)
{
  const float4 bottom = lerp(row0[tx.i0], row0[tx.i1], tx.f);
  const float4 top = lerp(row1[tx.i0], row1[tx.i1], tx.f);
  return lerp(bottom, top, fy);
}

} // namespace

float4 sampleBilinear(
    const float4 *texels, uint32_t width, uint32_t height, float u, float v)
{
  if (width == 0 || height == 0)
    return {0.f, 0.f, 0.f, 0.f};
  const Tap tx = tapAt(u * float(width) - 0.5f, width);
  const Tap ty = tapAt(v * float(height) - 0.5f, height);
  return blend(
      texels + size_t(ty.i0) * width, texels + size_t(ty.i1) * width, tx, ty.f);
}

void resizeBilinear(const float4 *src,
    uint32_t srcW,
    uint32_t srcH,
    float4 *dst,
    uint32_t dstW,
    uint32_t dstH)
{
  if (srcW == 0 || srcH == 0) {
    std::fill_n(dst, size_t(dstW) * dstH, float4{0.f, 0.f, 0.f, 0.f});
    return;
  }
  // Column taps are the same for every row: compute them once.
  std::vector<Tap> columns(dstW);
  for (uint32_t x = 0; x < dstW; x++)
    columns[x] = exactTap(x, srcW, dstW);
  for (uint32_t y = 0; y < dstH; y++) {
    const Tap ty = exactTap(y, srcH, dstH);
    const float4 *row0 = src + size_t(ty.i0) * srcW;
    const float4 *row1 = src + size_t(ty.i1) * srcW;
    float4 *out = dst + size_t(y) * dstW;
    for (uint32_t x = 0; x < dstW; x++)
      out[x] = blend(row0, row1, columns[x], ty.f);
  }
}

} // namespace prism
