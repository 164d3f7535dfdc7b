#include "EmitterExchange.h"
#include "LightExchange.h"

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
// center and radius (4 floats); then, only when the processes' declared
// lights differ, whether its lights could be described (a count) and
// their descriptions (LightExchange.h).
void describeOwnEmitters(const World &world, bool withEmitters, ByteWriter &out)
{
  const box3 bounds = world.bounds();
  out.add(bounds.lower);
  out.add(bounds.upper);
  const size_t count = withEmitters ? world.ownEmitterCount() : 0;
  out.add(uint32_t(count));
  for (size_t e = 0; e < count; e++) {
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
}

// One process's part: its bounds and its emitters, appended to `lights`.
// False (and nothing appended) when the bytes are not such a description.
bool readEmitters(ByteReader &in,
    box3 &bounds,
    std::vector<std::unique_ptr<PlacedLight>> &lights)
{
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
  if (!in.ok())
    return false;
  for (auto &light : read)
    lights.push_back(std::move(light));
  return true;
}

// Whether every process declares the same lights (count and
// World::declaredLightsHash()): then each keeps its own, as they are.
bool sameDeclaredLights(const World &world, MPI_Comm communicator)
{
  const uint64_t count = world.ownDeclaredLights().size();
  const uint64_t hash = world.declaredLightsHash();
  uint64_t least[4] = {count, ~count, hash, ~hash};
  MPI_Allreduce(MPI_IN_PLACE, least, 4, MPI_UINT64_T, MPI_MIN, communicator);
  return least[0] == ~least[1] && least[2] == ~least[3];
}

// The declared lights of every process, each light once: a light whose
// key a lower rank sent too is that rank's (declared on every process, it
// is one light), the others in rank order, each process's in its order.
std::vector<LightDescription> distinctLights(
    std::vector<std::vector<LightDescription>> &ofRank)
{
  std::vector<LightDescription> lights;
  std::vector<uint64_t> keys;
  for (auto &fromRank : ofRank) {
    const size_t earlier = keys.size();
    for (LightDescription &light : fromRank) {
      if (std::find(keys.begin(), keys.begin() + long(earlier), light.key)
          != keys.begin() + long(earlier))
        continue;
      keys.push_back(light.key);
      lights.push_back(std::move(light));
    }
  }
  return lights;
}

// This process's part: its emissive surfaces (or only its bounds) and, if
// `sendLights`, its declared lights (with a flag: they could be described).
std::vector<unsigned char> ownPart(const World &world,
    bool withEmitters,
    bool sendLights,
    std::string &ownProblem)
{
  ByteWriter out;
  describeOwnEmitters(world, withEmitters, out);
  if (sendLights) {
    ByteWriter lights;
    const bool described = writeDeclaredLights(world, lights, ownProblem);
    out.add(uint32_t(described ? 1 : 0));
    if (described)
      out.append(lights.bytes.data(), lights.bytes.size());
  }
  return std::move(out.bytes);
}

// Every process's part, in rank order.
struct GatheredParts
{
  std::vector<unsigned char> all;
  std::vector<int> sizes;
  std::vector<int> offsets;
  int ownSize{0};
  bool fits{true}; // false: some part, or all of them, exceeds MPI's ints
};

GatheredParts gatherParts(
    const std::vector<unsigned char> &own, MPI_Comm communicator, int ranks)
{
  GatheredParts g;
  // A part too large for MPI's int counts is sent as nothing, and every
  // process then keeps its own emitters (all see the same sizes).
  g.ownSize = own.size() <= size_t(INT_MAX) ? int(own.size()) : -1;
  g.sizes.assign(size_t(ranks), 0);
  MPI_Allgather(
      &g.ownSize, 1, MPI_INT, g.sizes.data(), 1, MPI_INT, communicator);
  g.offsets.assign(size_t(ranks), 0);
  int64_t total = 0;
  for (int r = 0; r < ranks; r++) {
    g.fits = g.fits && g.sizes[size_t(r)] >= 0;
    g.offsets[size_t(r)] = int(std::min<int64_t>(total, INT_MAX));
    total += std::max(g.sizes[size_t(r)], 0);
  }
  g.fits = g.fits && total <= INT_MAX;
  if (!g.fits)
    return g;
  g.all.resize(size_t(std::max<int64_t>(total, 1)));
  MPI_Allgatherv(own.data(),
      g.ownSize,
      MPI_BYTE,
      g.all.data(),
      g.sizes.data(),
      g.offsets.data(),
      MPI_BYTE,
      communicator);
  return g;
}

// What the parts say, read back on every process alike.
struct ReadParts
{
  std::vector<std::unique_ptr<PlacedLight>> emitters;
  std::vector<std::vector<LightDescription>> declared; // by rank
  box3 together = emptyBox3(); // the bounds of every process's world
  size_t firstOwn{0};          // this process's first emitter
  bool understood{true};
  int undescribed{-1}; // a rank whose lights could not be described
};

void extend(box3 &box, const box3 &other)
{
  box.lower.x = std::min(box.lower.x, other.lower.x);
  box.lower.y = std::min(box.lower.y, other.lower.y);
  box.lower.z = std::min(box.lower.z, other.lower.z);
  box.upper.x = std::max(box.upper.x, other.upper.x);
  box.upper.y = std::max(box.upper.y, other.upper.y);
  box.upper.z = std::max(box.upper.z, other.upper.z);
}

ReadParts readParts(
    const GatheredParts &g, int rank, int ranks, bool sendLights)
{
  ReadParts read;
  read.declared.resize(size_t(ranks));
  for (int r = 0; r < ranks && read.understood; r++) {
    if (r == rank)
      read.firstOwn = read.emitters.size();
    ByteReader in(
        g.all.data() + g.offsets[size_t(r)], size_t(g.sizes[size_t(r)]));
    box3 bounds;
    read.understood = readEmitters(in, bounds, read.emitters);
    if (read.understood && sendLights) {
      const uint32_t described = in.readCount();
      if (described == 1)
        read.understood = readDeclaredLights(in, read.declared[size_t(r)]);
      else if (read.undescribed < 0)
        read.undescribed = r;
    }
    read.understood = read.understood && in.ok() && in.left() == 0;
    extend(read.together, bounds);
  }
  return read;
}

// Places what was read in `world`: every process's emitters (if
// `withEmitters`) and, when every process's could be sent, the distinct
// declared lights.
void placeShared(World &world,
    ReadParts &read,
    bool withEmitters,
    bool sendLights,
    const std::string &ownProblem,
    EmitterExchangeResult &result)
{
  const float radius = World::sceneRadius(read.together);
  if (!sendLights || read.undescribed >= 0) {
    if (read.undescribed >= 0) {
      result.problem =
          "the processes declare different lights, and those of rank "
          + std::to_string(read.undescribed) + " cannot be sent to the others ("
          + (ownProblem.empty() ? std::string("see that process's report")
                                : ownProblem)
          + "); each process samples its own declared lights only";
    }
    if (withEmitters)
      world.shareEmitters(std::move(read.emitters), read.firstOwn, radius);
    else
      world.keepOwnEmitters();
    return;
  }
  // Every process rebuilds the same lights from the same bytes.
  std::vector<std::unique_ptr<PlacedLight>> lights;
  for (const LightDescription &light : distinctLights(read.declared)) {
    if (auto placed = placeDescribedLight(world.device(), light))
      lights.push_back(std::move(placed));
  }
  if (withEmitters) {
    world.shareLights(
        std::move(lights), std::move(read.emitters), read.firstOwn, radius);
  } else {
    world.shareDeclaredLights(std::move(lights), radius);
  }
  result.lightsShared = true;
}

} // namespace

EmitterExchangeResult shareLights(
    World &world, MPI_Comm communicator, bool withEmitters)
{
  EmitterExchangeResult result;
  int rank = 0, ranks = 1;
  MPI_Comm_rank(communicator, &rank);
  MPI_Comm_size(communicator, &ranks);
  if (ranks == 1)
    return result;
  if (!withEmitters && world.sharesEmitters())
    world.keepOwnEmitters(); // shared for another kind of render
  int changed =
      (withEmitters ? world.sharesEmitters() : world.sharesDeclaredLights())
          ? 0
          : 1;
  MPI_Allreduce(MPI_IN_PLACE, &changed, 1, MPI_INT, MPI_MAX, communicator);
  if (!changed)
    return result;
  const bool sendLights = !sameDeclaredLights(world, communicator);
  if (!withEmitters && !sendLights) {
    world.keepOwnEmitters();
    return result;
  }
  std::string ownProblem;
  const GatheredParts gathered =
      gatherParts(ownPart(world, withEmitters, sendLights, ownProblem),
          communicator,
          ranks);
  if (!gathered.fits) {
    world.keepOwnEmitters();
    result.problem =
        "the emissive surfaces and lights of the processes are too large to "
        "send (more than 2 GiB); each process samples its own only";
    return result;
  }
  result.exchanged = true;
  result.bytesSent = uint64_t(gathered.ownSize) * uint64_t(ranks - 1);
  ReadParts read = readParts(gathered, rank, ranks, sendLights);
  if (!read.understood) {
    // Every process read the same bytes, so all decide alike.
    world.keepOwnEmitters();
    result.problem =
        "the emissive surfaces or lights another process sent could not be "
        "read; each process samples its own only";
    return result;
  }
  placeShared(world, read, withEmitters, sendLights, ownProblem, result);
  return result;
}

} // namespace prism::mpi
