// The one tile loop every renderer runs its TileWork through. A template
// over the work's final type, so its hooks are called directly and inline
// into the loop, as a renderer's own loop would have them.
#pragma once

#include "../parallel/Blocks.h"
#include "Renderer.h"

#include <algorithm>
#include <atomic>

namespace prism {

// packet() for the tile's pixels, row by row in packets of up to
// rt::kPacketSize (rows in parallel blocks when the work allows), then
// bounce() until nothing is left to trace, then finish(); stops, storing
// nothing more, once `cancel` is set.
template <typename Work>
void runTile(Work &work, const Tile &tile, const std::atomic<bool> &cancel)
{
  const uint32_t width = tile.x1 - tile.x0;
  auto packetsOfRows = [&](size_t first, size_t rows) {
    const uint32_t end = tile.y0 + uint32_t(first + rows);
    for (uint32_t y = tile.y0 + uint32_t(first); y < end && !cancel; y++) {
      for (uint32_t x = tile.x0; x < tile.x1; x += rt::kPacketSize)
        work.packet(
            x, y, int(std::min<uint32_t>(rt::kPacketSize, tile.x1 - x)));
    }
  };
  const size_t rows = tile.y1 - tile.y0;
  if (work.packetsInParallel())
    forEachBlock(rows, std::max<size_t>(1, 1024 / width), packetsOfRows);
  else
    packetsOfRows(0, rows);
  while (!cancel && work.bounce()) {
  }
  if (!cancel)
    work.finish();
}

} // namespace prism
