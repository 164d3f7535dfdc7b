// Adaptive sampling: which tiles of an accumulating frame still take
// samples. Beside the frame's average I of all of a tile's samples, each
// pixel keeps the average A of its even-numbered samples (0, 2, 4, ...).
// After an even number n of samples, I - A = (B - A) / 2, B being the odd
// half, and E[(B - A)^2] / 4 = sigma^2 / n: the RMS of I - A over a tile's
// pixels and colour components estimates the RMS error of its average
// (taken relative to the value where that exceeds 1, as a display would
// show a highlight's noise).
// A tile whose estimate falls below the threshold takes no more samples
// until the accumulation restarts.
#pragma once

#include "../math/Vec.h"
#include "../renderer/FrameBuffers.h"

#include <cstdint>
#include <vector>

namespace prism {

class TileConvergence
{
 public:
  // Samples a tile takes before its estimate is trusted (each half then
  // has four per pixel).
  static constexpr uint32_t kMinimumSamples = 8;

  // Every tile active; `threshold` 0 turns adaptive sampling off.
  void reset(
      uint32_t width, uint32_t height, uint32_t tileSize, float threshold);
  bool enabled() const
  {
    return m_threshold > 0.f;
  }
  bool active(uint32_t tileIndex) const
  {
    return !enabled() || m_active[tileIndex] != 0;
  }
  // After sample `ordinal` (from 0) of a tile was folded into `average`:
  // folds it into the even half and stops the tile once its estimated
  // error is below the threshold. One thread per tile at a time.
  void update(uint32_t tileIndex,
      const Tile &tile,
      uint32_t ordinal,
      const std::vector<float4> &sample,
      const std::vector<float4> &average);
  // Pixels of the tiles still taking samples (all of them when off).
  uint64_t activePixels() const;

 private:
  float errorOf(const Tile &tile, const std::vector<float4> &average) const;

  float m_threshold{0.f};
  uint32_t m_width{0};
  uint32_t m_height{0};
  uint32_t m_tileSize{1};
  std::vector<float3> m_evenHalf;
  std::vector<uint8_t> m_active; // a byte per tile: tiles update apart
};

} // namespace prism
