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

  // Which buffers besides color a frame needs (its enabled channels).
  struct Needs
  {
    bool depth, normal, albedo, primitiveId, objectId, instanceId;
    bool operator==(const Needs &) const = default;
  };

  // Allocates color and the needed buffers; the others stay empty, so
  // renderers skip writing channels nobody maps.
  void resize(uint32_t w, uint32_t h, const Needs &needs)
  {
    width = w;
    height = h;
    const size_t n = size_t(w) * h;
    auto size = [n](auto &buffer, bool needed, auto value) {
      buffer.clear();
      if (needed)
        buffer.assign(n, value);
      buffer.shrink_to_fit();
    };
    size(color, true, float4{0, 0, 0, 0});
    size(depth, needs.depth, std::numeric_limits<float>::infinity());
    size(normal, needs.normal, float3{0, 0, 0});
    size(albedo, needs.albedo, float3{0, 0, 0});
    size(primitiveId, needs.primitiveId, kNoId);
    size(objectId, needs.objectId, kNoId);
    size(instanceId, needs.instanceId, kNoId);
    this->needs = needs;
  }
  Needs needs{};
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
