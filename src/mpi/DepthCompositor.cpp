#include "DepthCompositor.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace prism::mpi {
namespace {

// One process's contribution to one pixel, sent as plain floats.
struct Fragment
{
  float4 color;
  float depth;
};
constexpr int kFloatsPerFragment = 5;
static_assert(sizeof(Fragment) == kFloatsPerFragment * sizeof(float));

// First pixel of the band of rows `rank` composites.
size_t bandBegin(int rank, int ranks, uint32_t width, uint32_t height)
{
  return size_t(uint64_t(height) * uint64_t(rank) / uint64_t(ranks)) * width;
}

// Front to back with the "under" operator on premultiplied color (what
// prism's renderers write); background (infinite depth) is the same on every
// process, so only the first one counts, after every surface.
Fragment blend(Fragment *fragments, int count)
{
  std::stable_sort(fragments,
      fragments + count,
      [](const Fragment &a, const Fragment &b) { return a.depth < b.depth; });
  Fragment result{float4{0.f, 0.f, 0.f, 0.f}, fragments[0].depth};
  for (int i = 0; i < count && result.color.w < 1.f; i++) {
    const Fragment &f = fragments[i];
    const float rest = 1.f - result.color.w;
    result.color.x += rest * f.color.x;
    result.color.y += rest * f.color.y;
    result.color.z += rest * f.color.z;
    result.color.w += rest * f.color.w;
    if (std::isinf(f.depth))
      break;
  }
  return result;
}

int checkedCount(size_t count)
{
  if (count > size_t(INT_MAX))
    throw std::length_error("frame too large to composite with MPI");
  return int(count);
}

} // namespace

CompositedImage compositeByDepth(MPI_Comm communicator,
    uint32_t width,
    uint32_t height,
    const std::vector<float4> &color,
    const std::vector<float> &depth)
{
  int rank = 0, ranks = 1;
  MPI_Comm_rank(communicator, &rank);
  MPI_Comm_size(communicator, &ranks);
  const size_t pixels = size_t(width) * height;
  checkedCount(pixels * kFloatsPerFragment);

  // NaN depths sort as nothing hit, so the order stays strict.
  const float infinity = std::numeric_limits<float>::infinity();
  const bool rendered = color.size() == pixels && depth.size() == pixels;
  std::vector<Fragment> outgoing(pixels);
  for (size_t i = 0; i < pixels; i++) {
    outgoing[i] = rendered ? Fragment{color[i],
                      std::isnan(depth[i]) ? infinity : depth[i]}
                           : Fragment{float4{0.f, 0.f, 0.f, 0.f}, infinity};
  }

  const size_t myBegin = bandBegin(rank, ranks, width, height);
  const size_t myPixels = bandBegin(rank + 1, ranks, width, height) - myBegin;
  std::vector<int> sendCounts(ranks), sendOffsets(ranks), receiveCounts(ranks),
      receiveOffsets(ranks);
  for (int r = 0; r < ranks; r++) {
    const size_t begin = bandBegin(r, ranks, width, height);
    const size_t end = bandBegin(r + 1, ranks, width, height);
    sendCounts[r] = int((end - begin) * kFloatsPerFragment);
    sendOffsets[r] = int(begin * kFloatsPerFragment);
    receiveCounts[r] = int(myPixels * kFloatsPerFragment);
    receiveOffsets[r] = checkedCount(r * myPixels * kFloatsPerFragment);
  }
  std::vector<Fragment> incoming(myPixels * ranks);
  MPI_Alltoallv(outgoing.data(),
      sendCounts.data(),
      sendOffsets.data(),
      MPI_FLOAT,
      incoming.data(),
      receiveCounts.data(),
      receiveOffsets.data(),
      MPI_FLOAT,
      communicator);

  std::vector<Fragment> band(myPixels);
  std::vector<Fragment> perPixel(ranks);
  for (size_t p = 0; p < myPixels; p++) {
    // Gathered in rank order, so equal depths resolve to the lowest rank.
    for (int r = 0; r < ranks; r++)
      perPixel[r] = incoming[r * myPixels + p];
    band[p] = blend(perPixel.data(), ranks);
  }

  std::vector<int> bandCounts(ranks), bandOffsets(ranks);
  for (int r = 0; r < ranks; r++) {
    bandCounts[r] = sendCounts[r];
    bandOffsets[r] = sendOffsets[r];
  }
  std::vector<Fragment> image(rank == 0 ? pixels : 0);
  MPI_Gatherv(band.data(),
      int(myPixels * kFloatsPerFragment),
      MPI_FLOAT,
      image.data(),
      bandCounts.data(),
      bandOffsets.data(),
      MPI_FLOAT,
      0,
      communicator);

  CompositedImage result;
  if (rank == 0) {
    result.color.resize(pixels);
    result.depth.resize(pixels);
    for (size_t i = 0; i < pixels; i++) {
      result.color[i] = image[i].color;
      result.depth[i] = image[i].depth;
    }
  }
  return result;
}

} // namespace prism::mpi
