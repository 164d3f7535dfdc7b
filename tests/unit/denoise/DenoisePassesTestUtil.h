// Small images for the denoiser's passes: flat guides (every pixel one
// surface) unless a test says otherwise.
#pragma once

#include "denoise/Guides.h"

#include <vector>

namespace prism::denoising {

// A hit without a normal at depth 0: every pair blends with weight 1.
inline Guide flatGuide()
{
  return {{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f}, Guide::kHit};
}

inline NeighbourWeights flatNeighbourWeights(
    const PixelGrid &grid, int x, int y)
{
  NeighbourWeights weights{};
  for (int dy = -1; dy <= 1; dy++)
    for (int dx = -1; dx <= 1; dx++)
      weights[size_t(3 * (dy + 1) + dx + 1)] =
          grid.contains(x + dx, y + dy) ? 1.f : 0.f;
  return weights;
}

// Per-pixel 3x3 weights of flat guides: 1 inside the image, 0 outside.
inline std::vector<NeighbourWeights> flatNeighbourWeights(const PixelGrid &grid)
{
  std::vector<NeighbourWeights> weights(grid.pixels());
  for (int y = 0; y < grid.height; y++)
    for (int x = 0; x < grid.width; x++)
      weights[grid.index(x, y)] = flatNeighbourWeights(grid, x, y);
  return weights;
}

} // namespace prism::denoising
