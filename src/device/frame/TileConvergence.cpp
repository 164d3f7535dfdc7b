#include "TileConvergence.h"

#include <algorithm>
#include <cmath>

namespace prism {

void TileConvergence::reset(uint32_t width, uint32_t height, float threshold)
{
  m_threshold = std::isfinite(threshold) && threshold > 0.f ? threshold : 0.f;
  m_width = width;
  m_height = height;
  m_blocksX = (width + kBlockSize - 1) / kBlockSize;
  m_blocksY = (height + kBlockSize - 1) / kBlockSize;
  if (!enabled()) {
    std::vector<float3>().swap(m_evenHalf);
    std::vector<uint8_t>().swap(m_active);
    return;
  }
  m_evenHalf.assign(size_t(width) * height, float3{0.f, 0.f, 0.f});
  m_active.assign(size_t(m_blocksX) * m_blocksY, 1);
}

void TileConvergence::update(const Tile &span,
    uint32_t ordinal,
    const std::vector<float4> &sample,
    const std::vector<float4> &average)
{
  if (!enabled())
    return;
  if (ordinal % 2 == 0) {
    const float weight = 1.f / float(ordinal / 2 + 1);
    for (uint32_t y = span.y0; y < span.y1; y++) {
      for (size_t i = size_t(y) * m_width + span.x0,
                  end = size_t(y) * m_width + span.x1;
           i < end;
           i++) {
        const float3 s{sample[i].x, sample[i].y, sample[i].z};
        m_evenHalf[i] = m_evenHalf[i] + (s - m_evenHalf[i]) * weight;
      }
    }
    return; // the halves are equal only after an odd ordinal
  }
  if (ordinal + 1 < kMinimumSamples)
    return;
  for (uint32_t by = span.y0 / kBlockSize; by * kBlockSize < span.y1; by++) {
    for (uint32_t bx = span.x0 / kBlockSize; bx * kBlockSize < span.x1; bx++) {
      const Tile block{bx * kBlockSize,
          by * kBlockSize,
          std::min((bx + 1) * kBlockSize, m_width),
          std::min((by + 1) * kBlockSize, m_height)};
      if (errorOf(block, average) < m_threshold)
        m_active[size_t(by) * m_blocksX + bx] = 0;
    }
  }
}

float TileConvergence::errorOf(
    const Tile &block, const std::vector<float4> &average) const
{
  double sum = 0.0;
  for (uint32_t y = block.y0; y < block.y1; y++) {
    for (size_t i = size_t(y) * m_width + block.x0,
                end = size_t(y) * m_width + block.x1;
         i < end;
         i++) {
      // Relative above 1: a highlight of 20 need not be known to 0.01.
      auto error = [](float mean, float even) {
        const double d = double(mean - even) / std::max(1.0, double(mean));
        return d * d;
      };
      sum += error(average[i].x, m_evenHalf[i].x)
             + error(average[i].y, m_evenHalf[i].y)
             + error(average[i].z, m_evenHalf[i].z);
    }
  }
  const double values =
      3.0 * double(block.x1 - block.x0) * double(block.y1 - block.y0);
  // NaN (a NaN sample) compares false: such a block keeps sampling.
  return float(std::sqrt(sum / values));
}

uint64_t TileConvergence::activePixels(
    uint32_t rowHeight, uint32_t rowPart, uint32_t rowParts) const
{
  rowHeight = std::max(rowHeight, 1u);
  rowParts = std::max(rowParts, 1u);
  if (!enabled() && rowParts == 1)
    return uint64_t(m_width) * m_height;
  uint64_t pixels = 0;
  for (uint32_t by = 0; by < m_blocksY; by++) {
    // Tiles start on a block's corner: a block lies in one row of tiles.
    const uint32_t y0 = by * kBlockSize;
    if (y0 >= m_height || (y0 / rowHeight) % rowParts != rowPart)
      continue;
    const uint64_t rows = std::min(y0 + kBlockSize, m_height) - y0;
    for (uint32_t bx = 0; bx < m_blocksX; bx++)
      if (!enabled() || active(bx, by))
        pixels +=
            rows * (std::min((bx + 1) * kBlockSize, m_width) - bx * kBlockSize);
  }
  return pixels;
}

} // namespace prism
