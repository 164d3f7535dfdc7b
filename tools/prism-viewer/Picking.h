// What is under a pixel: the ids of the last frame whose ids were read
// (objectId, instanceId, primitiveId, and depth for focusing), looked up at
// window coordinates counted from the top-left corner, as the mouse and the
// script give them.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

namespace prism::viewer {

constexpr uint32_t kNoId = 0xffffffffu; // ANARI: nothing hit

struct FrameIds
{
  uint32_t width{0}, height{0};
  // Row 0 at the bottom, as mapped; empty where the device has no channel.
  std::vector<uint32_t> objectId, instanceId, primitiveId;
  std::vector<float> depth;
};

struct Pick
{
  bool hit{false};
  uint32_t objectId{kNoId}, instanceId{kNoId}, primitiveId{kNoId};
  std::optional<float> depth; // along the ray, where hit and known
};

// The ids at (x, y) of an image `width` x `height` shown over `ids` (any
// size: coordinates scale); nothing when outside or no ids were read.
std::optional<Pick> pickAt(
    const FrameIds &ids, int x, int y, uint32_t width, uint32_t height);

// Which pixels show the picked object (same objectId and instanceId).
std::vector<bool> pickedMask(const FrameIds &ids, const Pick &pick);

} // namespace prism::viewer
