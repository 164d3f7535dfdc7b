// The linear working buffers a frame renders into (one entry per pixel,
// row 0 at the bottom), before conversion to the channels' mapped types.
#pragma once

#include "../math/Vec.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace prism {

// The identifier written where nothing was hit (spec: ~0u).
constexpr uint32_t kNoId = 0xffffffffu;

struct FrameBuffers
{
  uint32_t width{0};
  uint32_t height{0};
  std::vector<float4> color;
  std::vector<float> depth; // distance to the camera; +inf for background
  std::vector<float3> normal;
  std::vector<float3> albedo;
  std::vector<uint32_t> primitiveId;
  std::vector<uint32_t> objectId;
  std::vector<uint32_t> instanceId;

  void resize(uint32_t w, uint32_t h)
  {
    width = w;
    height = h;
    const size_t n = size_t(w) * h;
    color.assign(n, float4{0, 0, 0, 0});
    depth.assign(n, std::numeric_limits<float>::infinity());
    normal.assign(n, float3{0, 0, 0});
    albedo.assign(n, float3{0, 0, 0});
    primitiveId.assign(n, kNoId);
    objectId.assign(n, kNoId);
    instanceId.assign(n, kNoId);
  }
};

// One pixel's worth of results, written by renderers.
struct PixelSample
{
  float4 color{0, 0, 0, 0};
  float depth{std::numeric_limits<float>::infinity()};
  float3 normal{0, 0, 0};
  float3 albedo{0, 0, 0};
  uint32_t primitiveId{kNoId};
  uint32_t objectId{kNoId};
  uint32_t instanceId{kNoId};
};

// A rectangle of pixels [x0, x1) x [y0, y1).
struct Tile
{
  uint32_t x0, y0, x1, y1;
};

} // namespace prism
