// The image the denoiser's passes walk, row 0 at the bottom, and the loop
// that runs a pass over its rows in parallel.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstddef>
#include <cstdint>

namespace prism::denoising {

struct PixelGrid
{
  int width, height;

  size_t pixels() const
  {
    return size_t(width) * size_t(height);
  }
  size_t index(int x, int y) const
  {
    return size_t(y) * size_t(width) + size_t(x);
  }
  bool contains(int x, int y) const
  {
    return x >= 0 && y >= 0 && x < width && y < height;
  }
};

// Rows in parallel; each pass writes only its own pixels, so any thread
// count gives the same bits.
template <typename F>
void forEachRow(const PixelGrid &grid, const F &rowFunction)
{
  tbb::parallel_for(tbb::blocked_range<int>(0, grid.height),
      [&](const tbb::blocked_range<int> &rows) {
        for (int y = rows.begin(); y < rows.end(); y++)
          rowFunction(y);
      });
}

} // namespace prism::denoising
