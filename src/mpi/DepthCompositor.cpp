#include "DepthCompositor.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace prism::mpi {
namespace {

// One process's contribution to one pixel.
struct Fragment
{
  float4 color;
  float depth;
};

std::vector<int> countsOf(
    const std::vector<size_t> &pixels, size_t unit, bool offsets)
{
  std::vector<int> out(pixels.size() - 1);
  for (size_t r = 0; r + 1 < pixels.size(); r++) {
    const size_t value =
        (offsets ? pixels[r] : pixels[r + 1] - pixels[r]) * unit;
    if (value > size_t(INT_MAX))
      throw std::length_error("frame too large to composite with MPI");
    out[r] = int(value);
  }
  return out;
}

} // namespace

DepthCompositor::DepthCompositor(
    MPI_Comm communicator, uint32_t width, uint32_t height)
    : m_communicator(communicator), m_width(width), m_height(height)
{
  MPI_Comm_rank(communicator, &m_rank);
  MPI_Comm_size(communicator, &m_ranks);
  // Rank r composites rows height*r/ranks up to height*(r+1)/ranks.
  for (int r = 0; r <= m_ranks; r++) {
    m_bandBegin.push_back(
        size_t(uint64_t(height) * uint64_t(r) / uint64_t(m_ranks)) * width);
  }
  // Fragments are the largest unit exchanged: check the counts once.
  countsOf(m_bandBegin, sizeof(Fragment), true);
}

std::vector<unsigned char> DepthCompositor::exchangeBands(
    const unsigned char *image, size_t unit) const
{
  const size_t bandPixels = m_bandBegin[m_rank + 1] - m_bandBegin[m_rank];
  const std::vector<int> sendCounts = countsOf(m_bandBegin, unit, false);
  const std::vector<int> sendOffsets = countsOf(m_bandBegin, unit, true);
  std::vector<int> receiveCounts(m_ranks), receiveOffsets(m_ranks);
  for (int r = 0; r < m_ranks; r++) {
    receiveCounts[r] = int(bandPixels * unit);
    receiveOffsets[r] = int(r * bandPixels * unit);
  }
  std::vector<unsigned char> incoming(bandPixels * unit * m_ranks);
  for (int r = 0; r < m_ranks; r++)
    m_bytesSent += r == m_rank ? 0 : uint64_t(sendCounts[r]);
  MPI_Alltoallv(image,
      sendCounts.data(),
      sendOffsets.data(),
      MPI_BYTE,
      incoming.data(),
      receiveCounts.data(),
      receiveOffsets.data(),
      MPI_BYTE,
      m_communicator);
  return incoming;
}

std::vector<unsigned char> DepthCompositor::gatherBands(
    const unsigned char *band, size_t unit) const
{
  const std::vector<int> counts = countsOf(m_bandBegin, unit, false);
  const std::vector<int> offsets = countsOf(m_bandBegin, unit, true);
  std::vector<unsigned char> image(
      m_rank == 0 ? size_t(m_width) * m_height * unit : 0);
  m_bytesSent += m_rank == 0 ? 0 : uint64_t(counts[m_rank]);
  MPI_Gatherv(band,
      counts[m_rank],
      MPI_BYTE,
      image.data(),
      counts.data(),
      offsets.data(),
      MPI_BYTE,
      0,
      m_communicator);
  return image;
}

CompositedImage DepthCompositor::composite(
    const std::vector<float4> &color, const std::vector<float> &depth)
{
  const size_t pixels = size_t(m_width) * m_height;
  // NaN depths sort as nothing hit, so the order stays strict.
  const float infinity = std::numeric_limits<float>::infinity();
  const bool rendered = color.size() == pixels && depth.size() == pixels;
  std::vector<Fragment> outgoing(pixels);
  for (size_t i = 0; i < pixels; i++) {
    outgoing[i] = rendered ? Fragment{color[i],
                      std::isnan(depth[i]) ? infinity : depth[i]}
                           : Fragment{float4{0.f, 0.f, 0.f, 0.f}, infinity};
  }
  const std::vector<unsigned char> incoming =
      exchangeBands((const unsigned char *)outgoing.data(), sizeof(Fragment));
  const size_t bandPixels = m_bandBegin[m_rank + 1] - m_bandBegin[m_rank];
  auto fragment = [&](int rank, size_t pixel) {
    Fragment f;
    std::memcpy(&f,
        incoming.data() + (rank * bandPixels + pixel) * sizeof(Fragment),
        sizeof(Fragment));
    return f;
  };

  std::vector<Fragment> band(bandPixels);
  m_nearestRank.assign(bandPixels, 0);
  std::vector<int> order(m_ranks);
  std::vector<Fragment> perRank(m_ranks);
  for (size_t p = 0; p < bandPixels; p++) {
    for (int r = 0; r < m_ranks; r++)
      perRank[r] = fragment(r, p);
    // Front to back; equal depths go to the lower rank.
    // Insertion sort: stable, and no allocation for a handful of ranks.
    for (int r = 0; r < m_ranks; r++) {
      int i = r;
      for (; i > 0 && perRank[order[i - 1]].depth > perRank[r].depth; i--)
        order[i] = order[i - 1];
      order[i] = r;
    }
    m_nearestRank[p] = order[0];
    // The "under" operator on premultiplied color (what prism's renderers
    // write; the processes render without background, which the device
    // adds under the result). What reaches infinity (lights seen there) is
    // the same on every process, so only the first one counts.
    Fragment result{float4{0.f, 0.f, 0.f, 0.f}, perRank[order[0]].depth};
    for (int i = 0; i < m_ranks && result.color.w < 1.f; i++) {
      const Fragment &f = perRank[order[i]];
      const float rest = 1.f - result.color.w;
      result.color.x += rest * f.color.x;
      result.color.y += rest * f.color.y;
      result.color.z += rest * f.color.z;
      result.color.w += rest * f.color.w;
      if (std::isinf(f.depth))
        break;
    }
    band[p] = result;
  }

  const std::vector<unsigned char> image =
      gatherBands((const unsigned char *)band.data(), sizeof(Fragment));
  CompositedImage result;
  if (m_rank == 0) {
    result.color.resize(pixels);
    result.depth.resize(pixels);
    for (size_t i = 0; i < pixels; i++) {
      Fragment f;
      std::memcpy(&f, image.data() + i * sizeof(Fragment), sizeof(Fragment));
      result.color[i] = f.color;
      result.depth[i] = f.depth;
    }
  }
  return result;
}

std::vector<unsigned char> DepthCompositor::takeNearest(
    const unsigned char *local, size_t bytesPerPixel)
{
  std::vector<unsigned char> zeros;
  if (!local) {
    zeros.assign(size_t(m_width) * m_height * bytesPerPixel, 0);
    local = zeros.data();
  }
  const std::vector<unsigned char> incoming =
      exchangeBands(local, bytesPerPixel);
  const size_t bandPixels = m_bandBegin[m_rank + 1] - m_bandBegin[m_rank];
  std::vector<unsigned char> band(bandPixels * bytesPerPixel);
  for (size_t p = 0; p < bandPixels; p++) {
    std::memcpy(band.data() + p * bytesPerPixel,
        incoming.data() + (m_nearestRank[p] * bandPixels + p) * bytesPerPixel,
        bytesPerPixel);
  }
  return gatherBands(band.data(), bytesPerPixel);
}

} // namespace prism::mpi
