#include "EmitterExchange.h"

#include "light/EmissiveSurface.h"
#include "world/World.h"

#include <algorithm>
#include <climits>
#include <cstring>
#include <memory>
#include <vector>

namespace prism::mpi {
namespace {

// What one process sends: its world's bounds (6 floats), its emitter
// count, and for each emitter its radiance (3 floats), its triangle and
// sphere counts, then each triangle's corners (9 floats) and each sphere's
// center and radius (4 floats). Floats travel as their bits, so every
// process rebuilds exactly the lights the sender placed.
class Writer
{
 public:
  void add(float value)
  {
    append(&value, sizeof(value));
  }
  void add(uint32_t value)
  {
    append(&value, sizeof(value));
  }
  void add(const float3 &v)
  {
    add(v.x);
    add(v.y);
    add(v.z);
  }
  std::vector<unsigned char> bytes;

 private:
  void append(const void *data, size_t size)
  {
    const auto *p = static_cast<const unsigned char *>(data);
    bytes.insert(bytes.end(), p, p + size);
  }
};

class Reader
{
 public:
  Reader(const unsigned char *data, size_t size) : m_data(data), m_size(size) {}
  // False once a read went past the end (then values read are 0).
  bool ok() const
  {
    return m_ok;
  }
  size_t left() const
  {
    return m_size - m_offset;
  }
  float readFloat()
  {
    float value = 0.f;
    take(&value, sizeof(value));
    return value;
  }
  uint32_t readCount()
  {
    uint32_t value = 0;
    take(&value, sizeof(value));
    return value;
  }
  float3 readFloat3()
  {
    float3 v;
    v.x = readFloat();
    v.y = readFloat();
    v.z = readFloat();
    return v;
  }

 private:
  void take(void *out, size_t size)
  {
    if (!m_ok || left() < size) {
      m_ok = false;
      return;
    }
    std::memcpy(out, m_data + m_offset, size);
    m_offset += size;
  }
  const unsigned char *m_data;
  size_t m_size;
  size_t m_offset{0};
  bool m_ok{true};
};

std::vector<unsigned char> describeOwnEmitters(const World &world)
{
  Writer out;
  const box3 bounds = world.bounds();
  out.add(bounds.lower);
  out.add(bounds.upper);
  out.add(uint32_t(world.ownEmitterCount()));
  for (size_t e = 0; e < world.ownEmitterCount(); e++) {
    const EmissiveSurface &emitter = world.ownEmitter(e);
    const EmitterShape &shape = emitter.shape();
    out.add(emitter.radiance());
    out.add(uint32_t(shape.triangles.size() / 3));
    out.add(uint32_t(shape.spheres.size()));
    const size_t corners = shape.triangles.size() / 3 * 3;
    for (size_t i = 0; i < corners; i++)
      out.add(shape.triangles[i]);
    for (const float4 &s : shape.spheres) {
      out.add(s.x);
      out.add(s.y);
      out.add(s.z);
      out.add(s.w);
    }
  }
  return out.bytes;
}

// One process's part: its bounds and its emitters, appended to `lights`.
// False (and nothing appended) when the bytes are not such a description.
bool readEmitters(const unsigned char *data,
    size_t size,
    box3 &bounds,
    std::vector<std::unique_ptr<PlacedLight>> &lights)
{
  Reader in(data, size);
  bounds.lower = in.readFloat3();
  bounds.upper = in.readFloat3();
  const uint32_t count = in.readCount();
  std::vector<std::unique_ptr<PlacedLight>> read;
  for (uint32_t e = 0; e < count && in.ok(); e++) {
    const float3 radiance = in.readFloat3();
    const uint32_t triangles = in.readCount();
    const uint32_t spheres = in.readCount();
    // Counts that the bytes left cannot hold are not believed (no
    // allocation beyond what arrived).
    if (!in.ok()
        || uint64_t(triangles) * 36u + uint64_t(spheres) * 16u > in.left())
      return false;
    EmitterShape shape;
    shape.triangles.resize(size_t(triangles) * 3);
    for (float3 &corner : shape.triangles)
      corner = in.readFloat3();
    shape.spheres.resize(spheres);
    for (float4 &s : shape.spheres) {
      s.x = in.readFloat();
      s.y = in.readFloat();
      s.z = in.readFloat();
      s.w = in.readFloat();
    }
    read.push_back(
        std::make_unique<EmissiveSurface>(std::move(shape), radiance));
  }
  if (!in.ok() || in.left() != 0)
    return false;
  for (auto &light : read)
    lights.push_back(std::move(light));
  return true;
}

} // namespace

EmitterExchangeResult shareEmitters(World &world, MPI_Comm communicator)
{
  EmitterExchangeResult result;
  int rank = 0, ranks = 1;
  MPI_Comm_rank(communicator, &rank);
  MPI_Comm_size(communicator, &ranks);
  if (ranks == 1)
    return result;
  int changed = world.sharesEmitters() ? 0 : 1;
  MPI_Allreduce(MPI_IN_PLACE, &changed, 1, MPI_INT, MPI_MAX, communicator);
  if (!changed)
    return result;

  std::vector<unsigned char> own = describeOwnEmitters(world);
  // A part too large for MPI's int counts is sent as nothing, and every
  // process then keeps its own emitters (all see the same sizes).
  int ownSize = own.size() <= size_t(INT_MAX) ? int(own.size()) : -1;
  std::vector<int> sizes(size_t(ranks), 0);
  MPI_Allgather(&ownSize, 1, MPI_INT, sizes.data(), 1, MPI_INT, communicator);
  std::vector<int> offsets(size_t(ranks), 0);
  int64_t total = 0;
  bool fits = true;
  for (int r = 0; r < ranks; r++) {
    fits = fits && sizes[size_t(r)] >= 0;
    offsets[size_t(r)] = int(std::min<int64_t>(total, INT_MAX));
    total += std::max(sizes[size_t(r)], 0);
  }
  fits = fits && total <= INT_MAX;
  if (!fits) {
    world.keepOwnEmitters();
    result.problem =
        "the emissive surfaces of the processes are too large to send (more "
        "than 2 GiB); each process samples its own only";
    return result;
  }
  std::vector<unsigned char> all(size_t(std::max<int64_t>(total, 1)));
  MPI_Allgatherv(own.data(),
      ownSize,
      MPI_BYTE,
      all.data(),
      sizes.data(),
      offsets.data(),
      MPI_BYTE,
      communicator);
  result.exchanged = true;
  result.bytesSent = uint64_t(ownSize) * uint64_t(ranks - 1);

  std::vector<std::unique_ptr<PlacedLight>> emitters;
  box3 together = emptyBox3();
  size_t firstOwn = 0;
  bool understood = true;
  for (int r = 0; r < ranks && understood; r++) {
    if (r == rank)
      firstOwn = emitters.size();
    box3 bounds;
    understood = readEmitters(all.data() + offsets[size_t(r)],
        size_t(sizes[size_t(r)]),
        bounds,
        emitters);
    together.lower.x = std::min(together.lower.x, bounds.lower.x);
    together.lower.y = std::min(together.lower.y, bounds.lower.y);
    together.lower.z = std::min(together.lower.z, bounds.lower.z);
    together.upper.x = std::max(together.upper.x, bounds.upper.x);
    together.upper.y = std::max(together.upper.y, bounds.upper.y);
    together.upper.z = std::max(together.upper.z, bounds.upper.z);
  }
  if (!understood) {
    // Every process read the same bytes, so all decide alike.
    world.keepOwnEmitters();
    result.problem =
        "the emissive surfaces another process sent could not be read; each "
        "process samples its own only";
    return result;
  }
  world.shareEmitters(
      std::move(emitters), firstOwn, World::sceneRadius(together));
  return result;
}

} // namespace prism::mpi
