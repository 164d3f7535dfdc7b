// Depth compositing by direct send: each process of a communicator owns a
// band of pixel rows, receives every process's fragment (linear RGBA and
// depth) for its band, blends them front to back, and rank 0 gathers the
// bands. No process order is needed: depth alone orders the fragments.
#pragma once

#include "math/Vec.h"

#include <mpi.h>

#include <cstdint>
#include <vector>

namespace prism::mpi {

struct CompositedImage
{
  std::vector<float4> color; // linear RGBA, row 0 at the bottom
  std::vector<float> depth;  // nearest depth over every process; +inf: none
};

// Collective over `communicator`. `color` and `depth` hold this process's
// width x height render (either empty: it rendered nothing, so it adds only
// background). Rank 0 gets the composited image, the others empty vectors.
// Throws std::length_error when the frame is too large for MPI's int counts.
CompositedImage compositeByDepth(MPI_Comm communicator,
    uint32_t width,
    uint32_t height,
    const std::vector<float4> &color,
    const std::vector<float> &depth);

} // namespace prism::mpi
