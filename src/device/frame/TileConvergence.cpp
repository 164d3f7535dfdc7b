#include "TileConvergence.h"

#include <algorithm>
#include <cmath>

namespace prism {

void TileConvergence::reset(
    uint32_t width, uint32_t height, uint32_t tileSize, float threshold)
{
  m_threshold = std::isfinite(threshold) && threshold > 0.f ? threshold : 0.f;
  m_width = width;
  m_height = height;
  m_tileSize = tileSize;
  if (!enabled()) {
    std::vector<float3>().swap(m_evenHalf);
    std::vector<uint8_t>().swap(m_active);
    return;
  }
  const uint32_t tilesX = (width + tileSize - 1) / tileSize;
  const uint32_t tilesY = (height + tileSize - 1) / tileSize;
  m_evenHalf.assign(size_t(width) * height, float3{0.f, 0.f, 0.f});
  m_active.assign(size_t(tilesX) * tilesY, 1);
}

void TileConvergence::update(uint32_t tileIndex,
    const Tile &tile,
    uint32_t ordinal,
    const std::vector<float4> &sample,
    const std::vector<float4> &average)
{
  if (!enabled() || !m_active[tileIndex])
    return;
  if (ordinal % 2 == 0) {
    const float weight = 1.f / float(ordinal / 2 + 1);
    for (uint32_t y = tile.y0; y < tile.y1; y++) {
      for (size_t i = size_t(y) * m_width + tile.x0,
                  end = size_t(y) * m_width + tile.x1;
           i < end;
           i++) {
        const float3 s{sample[i].x, sample[i].y, sample[i].z};
        m_evenHalf[i] = m_evenHalf[i] + (s - m_evenHalf[i]) * weight;
      }
    }
    return; // the halves are equal only after an odd ordinal
  }
  const uint32_t samples = ordinal + 1;
  if (samples >= kMinimumSamples && errorOf(tile, average) < m_threshold)
    m_active[tileIndex] = 0;
}

float TileConvergence::errorOf(
    const Tile &tile, const std::vector<float4> &average) const
{
  double sum = 0.0;
  for (uint32_t y = tile.y0; y < tile.y1; y++) {
    for (size_t i = size_t(y) * m_width + tile.x0,
                end = size_t(y) * m_width + tile.x1;
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
      3.0 * double(tile.x1 - tile.x0) * double(tile.y1 - tile.y0);
  // NaN (a NaN sample) compares false: such a tile keeps sampling.
  return float(std::sqrt(sum / values));
}

uint64_t TileConvergence::activePixels() const
{
  if (!enabled())
    return uint64_t(m_width) * m_height;
  const uint32_t tilesX = (m_width + m_tileSize - 1) / m_tileSize;
  uint64_t pixels = 0;
  for (size_t t = 0; t < m_active.size(); t++) {
    if (!m_active[t])
      continue;
    const uint32_t tx = uint32_t(t % tilesX), ty = uint32_t(t / tilesX);
    const uint32_t x0 = tx * m_tileSize, y0 = ty * m_tileSize;
    pixels += uint64_t(std::min(x0 + m_tileSize, m_width) - x0)
              * (std::min(y0 + m_tileSize, m_height) - y0);
  }
  return pixels;
}

} // namespace prism
