// Replicated rendering's gather: each process of a communicator rendered the
// rows of tiles whose index modulo the process count is its rank (so bright
// and empty parts of an image spread over every process); rank 0 assembles
// the whole image from everyone's rows.
#pragma once

#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace prism::mpi {

// Which rank renders pixel row `y` of a frame split into rows of tiles.
inline int ownerOfRow(uint32_t y, uint32_t tileSize, int ranks)
{
  return int((y / tileSize) % uint32_t(ranks));
}

// Collective over `communicator`: `local` holds this process's width x height
// pixels of `bytesPerPixel` bytes, correct in the rows it owns. Rank 0 gets
// the assembled image, the others an empty vector; `bytesSent` grows by what
// this process sent. Throws std::length_error when a channel is too large
// for MPI's int counts.
std::vector<unsigned char> gatherTileRows(MPI_Comm communicator,
    const unsigned char *local,
    uint32_t width,
    uint32_t height,
    size_t bytesPerPixel,
    uint32_t tileSize,
    uint64_t &bytesSent);

} // namespace prism::mpi
