#include "DistributedTransport.h"

#include <algorithm>
#include <climits>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <type_traits>

namespace prism::mpi {
namespace {

// The closest hit of one ray on one process, as MPI_MINLOC compares it
// (MPI_FLOAT_INT: distance, then the lower rank on a tie).
struct Nearest
{
  float t;
  int rank;
};

// A path this process shaded at a bounce, as the others receive it.
struct ShadedPath
{
  uint32_t tag;
  PathState state;
};

// A ray some process queued while shading (a shadow ray with the light it
// carries if nothing blocks it).
struct QueuedRay
{
  float3 origin;
  float3 direction;
  float tMin;
  float tMax;
  float time;
  uint32_t tag;
  float passedOneSided; // as given (a ray carried on past a layer)
  ShadowContribution contribution;
};

// How many of each this process sends at a bounce.
struct BounceCounts
{
  uint32_t paths;
  uint32_t next;
  uint32_t shadows;
};

static_assert(std::is_trivially_copyable_v<PathState>,
    "path states travel between processes as bytes");
static_assert(sizeof(float3) == 3 * sizeof(float), "float3 travels as floats");

void append(std::vector<unsigned char> &bytes, const void *data, size_t size)
{
  const auto *begin = static_cast<const unsigned char *>(data);
  bytes.insert(bytes.end(), begin, begin + size);
}

QueuedRay queued(
    const rt::RayQueue &queue, size_t i, const ShadowContribution &carried)
{
  return QueuedRay{queue.origin(i),
      queue.direction(i),
      queue.tMin(i),
      queue.tMax(i),
      queue.time(i),
      queue.tag(i),
      queue.passedOneSidedAt(i),
      carried};
}

// Queues `ray` as the process that shaded it had it queued.
void repush(rt::RayQueue &queue, const QueuedRay &ray)
{
  const size_t i = queue.push(
      ray.origin, ray.direction, ray.tMin, ray.tMax, ray.time, ray.tag);
  queue.setPassedOneSidedAt(i, ray.passedOneSided);
}

// Rays of every process in tag order: the order one process shading every
// ray queues them in (each ray queues at most one of each kind).
void sortByTag(std::vector<QueuedRay> &rays)
{
  std::sort(rays.begin(), rays.end(), [](const auto &a, const auto &b) {
    return a.tag < b.tag;
  });
}

int rankIn(MPI_Comm communicator)
{
  int rank = 0;
  MPI_Comm_rank(communicator, &rank);
  return rank;
}

int checkedCount(size_t count)
{
  if (count > size_t(INT_MAX))
    throw std::length_error("a wavefront too large for MPI's int counts");
  return int(count);
}

// Where each ray passed a single-sided surface, nearest over every
// process's part of the world (a minimum is exact: every process agrees).
void sharePassedOneSided(
    rt::RayQueue &queue, MPI_Comm communicator, uint64_t &bytesSent)
{
  const size_t count = queue.size();
  std::vector<float> nearest(count);
  for (size_t i = 0; i < count; i++)
    nearest[i] = queue.passedOneSidedAt(i);
  MPI_Allreduce(MPI_IN_PLACE,
      nearest.data(),
      checkedCount(count),
      MPI_FLOAT,
      MPI_MIN,
      communicator);
  bytesSent += count * sizeof(float);
  for (size_t i = 0; i < count; i++)
    queue.setPassedOneSidedAt(i, nearest[i]);
}

} // namespace

DistributedTransport::DistributedTransport(
    const World &world, MPI_Comm communicator, uint64_t &bytesSent)
    : m_local(world, streamSalt(rankIn(communicator))),
      m_communicator(communicator),
      m_bytesSent(bytesSent)
{
  MPI_Comm_rank(communicator, &m_rank);
  MPI_Comm_size(communicator, &m_ranks);
}

void DistributedTransport::traceClosest(
    rt::RayQueue &queue, const MediaEvents *media) const
{
  m_local.traceClosest(queue, media);
  const size_t count = queue.size();
  std::vector<Nearest> nearest(count);
  for (size_t i = 0; i < count; i++) {
    const rt::Hit hit = queue.hit(i);
    float t = hit.found() ? hit.t : std::numeric_limits<float>::infinity();
    // A collision in this process's volumes before its hit is the ray's
    // event here: the nearest event over every process is shaded.
    if (media)
      t = std::min(t, media->collisionBefore(i, t));
    nearest[i] = Nearest{t, m_rank};
  }
  // A minimum is exact, so every process gets the same owners; a ray no
  // process hits goes to rank 0 (the lowest of equal infinities).
  if (m_ranks > 1) {
    MPI_Allreduce(MPI_IN_PLACE,
        nearest.data(),
        checkedCount(count),
        MPI_FLOAT_INT,
        MPI_MINLOC,
        m_communicator);
    m_bytesSent += count * sizeof(Nearest);
    sharePassedOneSided(queue, m_communicator, m_bytesSent);
  }
  m_shaded.resize(count);
  for (size_t i = 0; i < count; i++)
    m_shaded[i] = nearest[i].rank == m_rank ? 1 : 0;
}

void DistributedTransport::traceOcclusion(rt::RayQueue &queue) const
{
  m_local.traceOcclusion(queue);
  if (m_ranks == 1)
    return;
  sharePassedOneSided(queue, m_communicator, m_bytesSent);
  // Every process's transmittances, multiplied in rank order by each: a
  // reduction may round differently on each process, and paths that differ
  // by a bit would soon queue different rays and stop the lockstep.
  const size_t count = queue.size();
  std::vector<float3> mine(count), all(count * size_t(m_ranks));
  for (size_t i = 0; i < count; i++)
    mine[i] = queue.transmittance(i);
  const int floats = checkedCount(3 * count);
  MPI_Allgather(mine.data(),
      floats,
      MPI_FLOAT,
      all.data(),
      floats,
      MPI_FLOAT,
      m_communicator);
  m_bytesSent += count * sizeof(float3) * size_t(m_ranks - 1);
  for (size_t i = 0; i < count; i++) {
    float3 through = all[i];
    for (int rank = 1; rank < m_ranks; rank++)
      through = through * all[size_t(rank) * count + i];
    queue.setTransmittance(i, through);
  }
}

void DistributedTransport::shareBounce(std::vector<PathState> &paths,
    const rt::RayQueue &rays,
    rt::RayQueue &next,
    rt::RayQueue &shadows,
    std::vector<ShadowContribution> &contributions) const
{
  if (m_ranks == 1)
    return;
  // What this process shaded: its paths, then the rays they queued.
  BounceCounts counts{0, uint32_t(next.size()), uint32_t(shadows.size())};
  std::vector<unsigned char> payload;
  for (size_t r = 0; r < rays.size(); r++) {
    if (rays.untraceable(r) || !m_shaded[r])
      continue;
    const ShadedPath shaded{rays.tag(r), paths[rays.tag(r)]};
    append(payload, &shaded, sizeof(shaded));
    counts.paths++;
  }
  for (size_t i = 0; i < next.size(); i++) {
    const QueuedRay ray = queued(next, i, ShadowContribution{});
    append(payload, &ray, sizeof(ray));
  }
  for (size_t i = 0; i < shadows.size(); i++) {
    const QueuedRay ray = queued(shadows, i, contributions[i]);
    append(payload, &ray, sizeof(ray));
  }

  const size_t ranks = size_t(m_ranks);
  std::vector<BounceCounts> allCounts(ranks);
  MPI_Allgather(&counts,
      3,
      MPI_UINT32_T,
      allCounts.data(),
      3,
      MPI_UINT32_T,
      m_communicator);
  m_bytesSent += sizeof(counts) * (ranks - 1);
  std::vector<int> sizes(ranks), offsets(ranks);
  size_t total = 0;
  for (int rank = 0; rank < m_ranks; rank++) {
    const BounceCounts &c = allCounts[size_t(rank)];
    const size_t size = c.paths * sizeof(ShadedPath)
                        + (size_t(c.next) + c.shadows) * sizeof(QueuedRay);
    offsets[size_t(rank)] = checkedCount(total);
    sizes[size_t(rank)] = checkedCount(size);
    total += size;
  }
  checkedCount(total);
  std::vector<unsigned char> gathered(total);
  MPI_Allgatherv(payload.data(),
      sizes[size_t(m_rank)],
      MPI_BYTE,
      gathered.data(),
      sizes.data(),
      offsets.data(),
      MPI_BYTE,
      m_communicator);
  m_bytesSent += payload.size() * size_t(m_ranks - 1);

  std::vector<QueuedRay> nextRays, shadowRays;
  for (int rank = 0; rank < m_ranks; rank++) {
    const BounceCounts &c = allCounts[size_t(rank)];
    const unsigned char *at = gathered.data() + offsets[size_t(rank)];
    for (uint32_t i = 0; i < c.paths; i++, at += sizeof(ShadedPath)) {
      ShadedPath shaded;
      std::memcpy(&shaded, at, sizeof(shaded));
      if (rank != m_rank && shaded.tag < paths.size())
        paths[shaded.tag] = shaded.state;
    }
    for (uint32_t i = 0; i < c.next + c.shadows; i++, at += sizeof(QueuedRay)) {
      QueuedRay ray;
      std::memcpy(&ray, at, sizeof(ray));
      (i < c.next ? nextRays : shadowRays).push_back(ray);
    }
  }
  sortByTag(nextRays);
  sortByTag(shadowRays);
  next.clear();
  for (const QueuedRay &ray : nextRays)
    repush(next, ray);
  shadows.clear();
  contributions.clear();
  for (const QueuedRay &ray : shadowRays) {
    repush(shadows, ray);
    contributions.push_back(ray.contribution);
  }
}

} // namespace prism::mpi
