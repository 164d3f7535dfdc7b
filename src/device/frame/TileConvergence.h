// Adaptive sampling: which blocks of an accumulating frame still take
// samples. Beside the frame's average I of all of a block's samples, each
// pixel keeps the average A of its even-numbered samples (0, 2, 4, ...).
// After an even number n of samples, I - A = (B - A) / 2, B being the odd
// half, and E[(B - A)^2] / 4 = sigma^2 / n: the RMS of I - A over a block's
// pixels and colour components estimates the RMS error of its average
// (taken relative to the value where that exceeds 1, as a display would
// show a highlight's noise).
// A block whose estimate falls below the threshold takes no more samples
// until the accumulation restarts. Blocks are smaller than the frame's
// tiles, so a tile's quiet wall stops while its noisy shadow goes on; a
// tile renders the runs of active blocks along each row of blocks.
#pragma once

#include "../math/Vec.h"
#include "../renderer/FrameBuffers.h"

#include <cstdint>
#include <vector>

namespace prism {

class TileConvergence
{
 public:
  // Samples a block takes before its estimate is trusted (each half then
  // has four per pixel).
  static constexpr uint32_t kMinimumSamples = 8;
  // Pixels on a side of a block: 64 pixels, 192 values give the estimate
  // about 10 % noise, and a run of one block is still a wavefront of 64.
  static constexpr uint32_t kBlockSize = 8;

  // Every block active; `threshold` 0 turns adaptive sampling off.
  void reset(uint32_t width, uint32_t height, float threshold);
  bool enabled() const
  {
    return m_threshold > 0.f;
  }
  // Calls `render(span)` for the parts of `tile` still taking samples:
  // the whole tile while all of it is (and always when off), otherwise
  // each run of active blocks along a row of blocks. `tile` starts on a
  // block's corner.
  template <typename Render>
  void forEachActiveSpan(const Tile &tile, Render &&render) const;
  // After sample `ordinal` (from 0) of `span` (a span forEachActiveSpan
  // gave) was folded into `average`: folds it into the even half and stops
  // the span's blocks whose estimated error is below the threshold. One
  // thread per tile at a time.
  void update(const Tile &span,
      uint32_t ordinal,
      const std::vector<float4> &sample,
      const std::vector<float4> &average);
  // Pixels of the blocks still taking samples (all of them when off).
  uint64_t activePixels() const
  {
    return activePixels(kBlockSize, 0, 1);
  }
  // The same in the rows of `rowHeight`-pixel tiles whose index modulo
  // `rowParts` is `rowPart`: the rows this process renders when processes
  // share a frame.
  uint64_t activePixels(
      uint32_t rowHeight, uint32_t rowPart, uint32_t rowParts) const;

 private:
  bool active(uint32_t bx, uint32_t by) const
  {
    return m_active[size_t(by) * m_blocksX + bx] != 0;
  }
  float errorOf(const Tile &block, const std::vector<float4> &average) const;

  float m_threshold{0.f};
  uint32_t m_width{0};
  uint32_t m_height{0};
  uint32_t m_blocksX{0};
  uint32_t m_blocksY{0};
  std::vector<float3> m_evenHalf;
  std::vector<uint8_t> m_active; // a byte per block: tiles update apart
};

template <typename Render>
void TileConvergence::forEachActiveSpan(const Tile &tile, Render &&render) const
{
  if (!enabled()) {
    render(tile);
    return;
  }
  const uint32_t bx0 = tile.x0 / kBlockSize, by0 = tile.y0 / kBlockSize;
  const uint32_t bx1 = (tile.x1 + kBlockSize - 1) / kBlockSize;
  const uint32_t by1 = (tile.y1 + kBlockSize - 1) / kBlockSize;
  bool all = true;
  for (uint32_t by = by0; by < by1 && all; by++)
    for (uint32_t bx = bx0; bx < bx1 && all; bx++)
      all = active(bx, by);
  if (all) {
    render(tile);
    return;
  }
  for (uint32_t by = by0; by < by1; by++) {
    const uint32_t y0 = by * kBlockSize;
    const uint32_t y1 = std::min(y0 + kBlockSize, tile.y1);
    for (uint32_t bx = bx0; bx < bx1;) {
      if (!active(bx, by)) {
        bx++;
        continue;
      }
      const uint32_t first = bx;
      while (bx < bx1 && active(bx, by))
        bx++;
      render(
          Tile{first * kBlockSize, y0, std::min(bx * kBlockSize, tile.x1), y1});
    }
  }
}

} // namespace prism
