#include "Picking.h"

#include <cmath>

namespace prism::viewer {

std::optional<Pick> pickAt(
    const FrameIds &ids, int x, int y, uint32_t width, uint32_t height)
{
  if (ids.width == 0 || ids.height == 0 || width == 0 || height == 0 || x < 0
      || y < 0 || uint32_t(x) >= width || uint32_t(y) >= height)
    return std::nullopt;
  // The frame may render at a reduced scale: map to its pixel.
  const uint32_t fx = uint32_t((uint64_t(x) * ids.width) / width);
  const uint32_t fyTop = uint32_t((uint64_t(y) * ids.height) / height);
  const size_t i = size_t(ids.height - 1 - fyTop) * ids.width + fx;
  const size_t count = size_t(ids.width) * ids.height;
  auto at = [&](const std::vector<uint32_t> &v) {
    return v.size() == count ? v[i] : kNoId;
  };
  Pick pick;
  pick.objectId = at(ids.objectId);
  pick.instanceId = at(ids.instanceId);
  pick.primitiveId = at(ids.primitiveId);
  pick.hit = pick.primitiveId != kNoId || pick.objectId != kNoId
             || pick.instanceId != kNoId;
  if (ids.depth.size() == count && std::isfinite(ids.depth[i]))
    pick.depth = ids.depth[i];
  return pick;
}

std::vector<bool> pickedMask(const FrameIds &ids, const Pick &pick)
{
  const size_t count = size_t(ids.width) * ids.height;
  std::vector<bool> mask(count, false);
  if (!pick.hit || ids.objectId.size() != count)
    return mask;
  const bool byInstance = ids.instanceId.size() == count;
  // Surfaces without an `id` share ~0u with the background: a hit is a
  // pixel with a primitive.
  const bool byPrimitive = ids.primitiveId.size() == count;
  for (size_t i = 0; i < count; ++i)
    mask[i] = ids.objectId[i] == pick.objectId
              && (!byInstance || ids.instanceId[i] == pick.instanceId)
              && (!byPrimitive || ids.primitiveId[i] != kNoId);
  return mask;
}

} // namespace prism::viewer
