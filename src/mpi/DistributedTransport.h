// The ray transport of data-parallel path tracing (`pathtracer` mode). Every
// process runs the same wavefronts in lockstep: it traces each queue against
// its own part of the world, then one reduction over the communicator gives
// every ray its closest hit over all processes and the process owning it
// (the same result as cycling the queue through every process), and shadow
// rays multiply what each process's geometry lets through. The owner alone
// shades a hit (rank 0 a miss); after shading, the processes exchange the
// paths they shaded and the rays those queued, so all hold the same state
// again.
#pragma once

#include "renderer/wavefront/LocalTransport.h"

#include <mpi.h>

#include <cstdint>
#include <vector>

namespace prism::mpi {

class DistributedTransport final : public RayTransport
{
 public:
  // Rank r's salt for random streams of media: 0 for rank 0.
  static uint32_t streamSalt(int rank)
  {
    return uint32_t(rank) * 0x9e3779b9u;
  }

  // `bytesSent` grows by the payload this process hands to each exchange.
  DistributedTransport(
      const World &world, MPI_Comm communicator, uint64_t &bytesSent);

  void traceClosest(
      rt::RayQueue &queue, const MediaEvents *media) const override;
  void traceOcclusion(rt::RayQueue &queue) const override;
  const uint8_t *shadedRays() const override
  {
    return m_shaded.data();
  }
  uint32_t mediaStreamSalt() const override
  {
    return streamSalt(m_rank);
  }
  void shareBounce(std::vector<PathState> &paths,
      const rt::RayQueue &rays,
      rt::RayQueue &next,
      rt::RayQueue &shadows,
      std::vector<ShadowContribution> &contributions) const override;

 private:
  LocalTransport m_local;
  MPI_Comm m_communicator;
  int m_rank{0};
  int m_ranks{1};
  // One thread drives a lockstep render, so the transport's const calls
  // may keep what the last closest trace found.
  uint64_t &m_bytesSent;
  // Whether this process owns each ray of the last closest trace.
  mutable std::vector<uint8_t> m_shaded;
};

} // namespace prism::mpi
