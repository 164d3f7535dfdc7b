#include "TileRowGather.h"

#include <climits>
#include <cstring>
#include <stdexcept>

namespace prism::mpi {

std::vector<unsigned char> gatherTileRows(MPI_Comm communicator,
    const unsigned char *local,
    uint32_t width,
    uint32_t height,
    size_t bytesPerPixel,
    uint32_t tileSize,
    uint64_t &bytesSent)
{
  int rank = 0, ranks = 1;
  MPI_Comm_rank(communicator, &rank);
  MPI_Comm_size(communicator, &ranks);
  const size_t rowBytes = size_t(width) * bytesPerPixel;
  if (rowBytes * height > size_t(INT_MAX))
    throw std::length_error("frame channel too large to gather with MPI");

  std::vector<int> counts(ranks, 0), offsets(ranks, 0);
  for (uint32_t y = 0; y < height; y++)
    counts[ownerOfRow(y, tileSize, ranks)] += int(rowBytes);
  for (int r = 1; r < ranks; r++)
    offsets[r] = offsets[r - 1] + counts[r - 1];

  std::vector<unsigned char> mine;
  mine.reserve(counts[rank]);
  for (uint32_t y = 0; y < height; y++) {
    if (ownerOfRow(y, tileSize, ranks) == rank)
      mine.insert(mine.end(), local + y * rowBytes, local + (y + 1) * rowBytes);
  }

  std::vector<unsigned char> packed(rank == 0 ? rowBytes * height : 0);
  bytesSent += rank == 0 ? 0 : uint64_t(counts[rank]);
  MPI_Gatherv(mine.data(),
      counts[rank],
      MPI_BYTE,
      packed.data(),
      counts.data(),
      offsets.data(),
      MPI_BYTE,
      0,
      communicator);
  if (rank != 0)
    return {};

  // Rows arrive grouped by rank; put each back at its place in the image.
  std::vector<unsigned char> image(rowBytes * height);
  std::vector<size_t> next(offsets.begin(), offsets.end());
  for (uint32_t y = 0; y < height; y++) {
    const int owner = ownerOfRow(y, tileSize, ranks);
    std::memcpy(
        image.data() + y * rowBytes, packed.data() + next[owner], rowBytes);
    next[owner] += rowBytes;
  }
  return image;
}

} // namespace prism::mpi
