// Depth compositing by direct send: each process of a communicator owns a
// band of pixel rows, receives every process's fragment (linear RGBA and
// depth) for its band, blends them front to back, and rank 0 gathers the
// bands. No process order is needed: depth alone orders the fragments.
#pragma once

#include "math/Vec.h"

#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace prism::mpi {

struct CompositedImage
{
  std::vector<float4> color; // linear premultiplied RGBA, row 0 at the bottom
  std::vector<float> depth;  // nearest depth over every process; +inf: none
};

// One frame's compositing over `communicator`; every call is collective.
// Throws std::length_error when the frame is too large for MPI's int counts.
class DepthCompositor
{
 public:
  DepthCompositor(MPI_Comm communicator, uint32_t width, uint32_t height);

  // `color` and `depth` hold this process's width x height render, made
  // without background (either empty: it rendered nothing). Rank 0 gets
  // the composited image, still without background; the others get empty
  // vectors.
  CompositedImage composite(
      const std::vector<float4> &color, const std::vector<float> &depth);

  // For channels that do not blend (normal, albedo, ids): rank 0 gets, at
  // each pixel, the value of the process whose fragment was nearest in the
  // last composite(). `local` holds width x height pixels of
  // `bytesPerPixel` bytes (NULL: zeros); the others get an empty vector.
  std::vector<unsigned char> takeNearest(
      const unsigned char *local, size_t bytesPerPixel);

  // Bytes this process has sent to the others so far.
  uint64_t bytesSent() const
  {
    return m_bytesSent;
  }

 private:
  // Every process's band to its owner, then the bands to rank 0, of
  // `unit`-byte pixels.
  std::vector<unsigned char> exchangeBands(
      const unsigned char *image, size_t unit) const;
  std::vector<unsigned char> gatherBands(
      const unsigned char *band, size_t unit) const;

  MPI_Comm m_communicator;
  int m_rank{0};
  int m_ranks{1};
  uint32_t m_width;
  uint32_t m_height;
  std::vector<size_t> m_bandBegin; // first pixel of each rank's band, + end
  std::vector<int> m_nearestRank;  // per pixel of this process's band
  mutable uint64_t m_bytesSent{0};
};

// Adds a background under composited premultiplied color (the processes
// rendered without it, so it is added once, behind everything);
// `backgroundAt(x, y)` is the background at pixel (x, y) of `width`-pixel
// rows.
template <typename BackgroundAt>
void addBackground(
    uint32_t width, std::vector<float4> &color, BackgroundAt backgroundAt)
{
  for (size_t i = 0; i < color.size(); i++) {
    const float4 background =
        backgroundAt(uint32_t(i % width), uint32_t(i / width));
    float4 &c = color[i];
    const float rest = 1.f - c.w;
    c = float4{c.x + rest * background.x,
        c.y + rest * background.y,
        c.z + rest * background.z,
        c.w + rest * background.w};
  }
}

} // namespace prism::mpi
