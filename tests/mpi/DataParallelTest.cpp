// The prism_mpi device under mpirun: `data_parallel_test SCENARIO`, run by
// ctest with 1, 2 and 4 processes. Each scenario compares rank 0's image with
// the plain prism device rendering the whole scene in one process.
#include "BoxGrid.h"
#include "StatusRecorder.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

using namespace prism::scenes;

namespace {

int g_worldRank = 0;
int g_failures = 0;

void check(bool ok, const std::string &what)
{
  if (!ok) {
    std::fprintf(stderr, "[rank %d] FAILED: %s\n", g_worldRank, what.c_str());
    g_failures++;
  }
}

// Errors a device reported, kept for the scenarios that expect some.
class Status
{
 public:
  // The messages of `worst` severity or worse (errors by default).
  std::vector<std::string> take(
      ANARIStatusSeverity worst = ANARI_SEVERITY_ERROR)
  {
    std::vector<std::string> messages;
    for (const StatusMessage &m : m_recorder.take()) {
      if (m.severity <= worst)
        messages.push_back(m.text);
    }
    return messages;
  }
  StatusRecorder m_recorder;
};

// Whether exactly one error arrived (besides, when `unrenderedMaps`, the
// errors of mapping a frame that was not rendered) and it contains every
// fragment and none of `absent`.
bool oneErrorMentioning(Status &status,
    const std::vector<std::string> &fragments,
    bool unrenderedMaps = false,
    const std::vector<std::string> &absent = {})
{
  std::vector<std::string> errors = status.take();
  if (unrenderedMaps) {
    std::erase_if(errors, [](const std::string &e) {
      return e.find("anariMapFrame") != std::string::npos
             && e.find("never rendered") != std::string::npos;
    });
  }
  bool all = errors.size() == 1;
  for (const std::string &fragment : fragments)
    all = all && errors[0].find(fragment) != std::string::npos;
  for (const std::string &fragment : absent)
    all = all && errors[0].find(fragment) == std::string::npos;
  if (!all) {
    for (const std::string &e : errors)
      std::fprintf(stderr, "[rank %d] error: %s\n", g_worldRank, e.c_str());
  }
  return all;
}

// This process's rank in MPI_COMM_WORLD, and its size. (Plain ints, not
// a structured binding: clang 14 cannot capture those in lambdas.)
int worldRank()
{
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

int worldSize()
{
  int ranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  return ranks;
}

struct Device
{
  ANARILibrary library{nullptr};
  ANARIDevice device{nullptr};
  Device(const char *name, Status &status)
  {
    library =
        anariLoadLibrary(name, StatusRecorder::callback, &status.m_recorder);
    device = library ? anariNewDevice(library, "default") : nullptr;
    check(device != nullptr, std::string(name) + " loads");
  }
  ~Device()
  {
    if (device)
      anariRelease(device, device);
    if (library)
      anariUnloadLibrary(library);
  }
};

constexpr uint32_t kSize = 64;
const float kEyeA[3] = {3.2f, 2.6f, 4.6f};
const float kEyeB[3] = {-4.3f, 1.7f, 2.9f};

// Renders `boxes` once with `library`'s device (communicator: the frame's
// and world's mpiCommunicator when given) and returns the image and bounds.
struct Render
{
  Image image;
  float bounds[6]{};
  bool boundsFound{false};
  uint64_t bytesSent{0}; // the frame's mpiBytesSent (prism_mpi only)
};

// How renderBoxes lights and accumulates: unlit single samples by
// default; `lit` adds a directional light from above, the same on every
// process, so upper boxes shadow lower ones (often another process's).
struct Lighting
{
  bool lit{false};
  int samples{1};
  const float *sunDirection{kSunDirection};
  // An emissive quad above the grid, in an instance of its own, glowing
  // `glow`.
  bool emissiveQuad{false};
  const float *glow{nullptr};
  // A grey floor under the grid (addFloor).
  bool floor{false};
  // A sky of an hdri light (addSky), the world's only light.
  bool sky{false};
};

constexpr float kWarmGlow[3] = {6.f, 5.f, 4.f};
constexpr float kColdGlow[3] = {2.f, 3.f, 7.f};

// A surface of the committed `geometry` and `material` (both released),
// in a group of its own placed in `world` by an untransformed instance;
// commits the world.
void placeInOwnInstance(ANARIDevice device,
    ANARIWorld world,
    ANARIGeometry geometry,
    ANARIMaterial material)
{
  ANARISurface surface = anariNewSurface(device);
  anariSetParameter(device, surface, "geometry", ANARI_GEOMETRY, &geometry);
  anariSetParameter(device, surface, "material", ANARI_MATERIAL, &material);
  anariCommitParameters(device, surface);
  ANARIGroup group = anariNewGroup(device);
  ANARIArray1D surfaces =
      anariNewArray1D(device, &surface, nullptr, nullptr, ANARI_SURFACE, 1);
  anariSetParameter(device, group, "surface", ANARI_ARRAY1D, &surfaces);
  anariCommitParameters(device, group);
  ANARIInstance instance = anariNewInstance(device, "transform");
  anariSetParameter(device, instance, "group", ANARI_GROUP, &group);
  anariCommitParameters(device, instance);
  setWorldObjects(device, world, "instance", ANARI_INSTANCE, instance);
  for (ANARIObject o : {(ANARIObject)instance,
           (ANARIObject)surfaces,
           (ANARIObject)group,
           (ANARIObject)surface,
           (ANARIObject)material,
           (ANARIObject)geometry})
    anariRelease(device, o);
}

// A 2x2 quad above the grid (y = 2.2), glowing `glow` on both sides (warm
// white by default): a group of its one surface, placed in `world` by an
// untransformed instance. Returns its material (the caller releases it).
ANARIMaterial addEmissiveQuad(
    ANARIDevice device, ANARIWorld world, const float *glow)
{
  glow = glow ? glow : kWarmGlow;
  const float corners[4][3] = {{-1.f, 2.2f, -1.f},
      {1.f, 2.2f, -1.f},
      {1.f, 2.2f, 1.f},
      {-1.f, 2.2f, 1.f}};
  const uint32_t triangles[2][3] = {{0, 1, 2}, {0, 2, 3}};
  ANARIGeometry geometry = anariNewGeometry(device, "triangle");
  auto setArray = [&](const char *name,
                      ANARIDataType type,
                      const void *data,
                      uint64_t count) {
    ANARIArray1D array =
        anariNewArray1D(device, nullptr, nullptr, nullptr, type, count);
    std::memcpy(
        anariMapArray(device, array), data, count * anari::sizeOf(type));
    anariUnmapArray(device, array);
    anariSetParameter(device, geometry, name, ANARI_ARRAY1D, &array);
    anariRelease(device, array);
  };
  setArray("vertex.position", ANARI_FLOAT32_VEC3, corners, 4);
  setArray("primitive.index", ANARI_UINT32_VEC3, triangles, 2);
  anariCommitParameters(device, geometry);
  ANARIMaterial material = anariNewMaterial(device, "physicallyBased");
  const float black[3] = {0.f, 0.f, 0.f};
  anariSetParameter(device, material, "baseColor", ANARI_FLOAT32_VEC3, black);
  anariSetParameter(device, material, "emissive", ANARI_FLOAT32_VEC3, glow);
  anariCommitParameters(device, material);
  anariRetain(device, material); // the caller's reference
  placeInOwnInstance(device, world, geometry, material);
  return material;
}

// A committed quad geometry of `corners`.
ANARIGeometry newQuad(ANARIDevice device, const float corners[4][3])
{
  ANARIGeometry geometry = anariNewGeometry(device, "quad");
  ANARIArray1D positions =
      anariNewArray1D(device, nullptr, nullptr, nullptr, ANARI_FLOAT32_VEC3, 4);
  std::memcpy(anariMapArray(device, positions), corners, 12 * sizeof(float));
  anariUnmapArray(device, positions);
  anariSetParameter(
      device, geometry, "vertex.position", ANARI_ARRAY1D, &positions);
  anariRelease(device, positions);
  anariCommitParameters(device, geometry);
  return geometry;
}

// A grey matte floor 12 units wide under the grid (y = -2.3), in a
// group of its own placed by an untransformed instance.
void addFloor(ANARIDevice device, ANARIWorld world)
{
  const float corners[4][3] = {{-6.f, -2.3f, -6.f},
      {6.f, -2.3f, -6.f},
      {6.f, -2.3f, 6.f},
      {-6.f, -2.3f, 6.f}};
  ANARIGeometry geometry = newQuad(device, corners);
  ANARIMaterial material = anariNewMaterial(device, "matte");
  const float grey[3] = {0.7f, 0.7f, 0.7f};
  anariSetParameter(device, material, "color", ANARI_FLOAT32_VEC3, grey);
  anariCommitParameters(device, material);
  placeInOwnInstance(device, world, geometry, material);
}

// An hdri light of an 8x4 image, bright blue overhead fading to a dim
// warm horizon band, as `world`'s only light; commits the world.
void addSky(ANARIDevice device, ANARIWorld world)
{
  float texels[4][8][3];
  for (int t = 0; t < 4; t++) {
    for (int s = 0; s < 8; s++) {
      const float height = 1.f - float(t) / 3.f; // 1 at the top row
      texels[t][s][0] = 0.3f + 0.2f * float(s % 3);
      texels[t][s][1] = 0.4f + 0.6f * height;
      texels[t][s][2] = 0.5f + 1.5f * height;
    }
  }
  ANARIArray2D image = anariNewArray2D(
      device, nullptr, nullptr, nullptr, ANARI_FLOAT32_VEC3, 8, 4);
  std::memcpy(anariMapArray(device, image), texels, sizeof(texels));
  anariUnmapArray(device, image);
  ANARILight sky = anariNewLight(device, "hdri");
  const float up[3] = {0.f, 1.f, 0.f};
  anariSetParameter(device, sky, "up", ANARI_FLOAT32_VEC3, up);
  anariSetParameter(device, sky, "radiance", ANARI_ARRAY2D, &image);
  anariCommitParameters(device, sky);
  setWorldObjects(device, world, "light", ANARI_LIGHT, sky);
  anariRelease(device, sky);
  anariRelease(device, image);
}

// What a scenario changes on the camera and renderer after they are made,
// before the frame is (it commits what it changes).
using Adjustment = std::function<void(ANARICamera, ANARIRenderer)>;

Render renderBoxes(ANARIDevice device,
    const std::vector<int> &boxes,
    const float eye[3],
    const char *rendererSubtype,
    MPI_Comm *communicator,
    uint32_t width = kSize,
    uint32_t height = kSize,
    Lighting lighting = {},
    const Adjustment &adjust = {})
{
  Render result;
  ANARIWorld world = newBoxesWorld(device, boxes);
  if (lighting.lit)
    addSunlight(device, world, lighting.sunDirection);
  if (lighting.emissiveQuad)
    anariRelease(device, addEmissiveQuad(device, world, lighting.glow));
  if (lighting.floor)
    addFloor(device, world);
  if (lighting.sky)
    addSky(device, world);
  if (communicator) {
    anariSetParameter(
        device, world, "mpiCommunicator", ANARI_VOID_POINTER, communicator);
    anariCommitParameters(device, world);
  }
  ANARICamera camera = newCamera(device, eye, float(width) / float(height));
  ANARIRenderer renderer = newRenderer(device, rendererSubtype);
  if (adjust)
    adjust(camera, renderer);
  ANARIFrame frame = newFrame(device, world, camera, renderer, width, height);
  if (communicator) {
    anariSetParameter(
        device, frame, "mpiCommunicator", ANARI_VOID_POINTER, communicator);
    anariCommitParameters(device, frame);
  }
  if (lighting.samples > 1) {
    const bool accumulate = true;
    anariSetParameter(device, frame, "accumulation", ANARI_BOOL, &accumulate);
    anariCommitParameters(device, frame);
  }
  for (int sample = 0; sample < lighting.samples; sample++) {
    anariRenderFrame(device, frame);
    anariFrameReady(device, frame, ANARI_WAIT);
  }
  result.image = readFrame(device, frame);
  result.boundsFound = anariGetProperty(device,
      world,
      "bounds",
      ANARI_FLOAT32_BOX3,
      result.bounds,
      sizeof(result.bounds),
      ANARI_WAIT);
  anariGetProperty(device,
      frame,
      "mpiBytesSent",
      ANARI_UINT64,
      &result.bytesSent,
      sizeof(result.bytesSent),
      ANARI_WAIT);
  anariRelease(device, frame);
  anariRelease(device, renderer);
  anariRelease(device, camera);
  anariRelease(device, world);
  return result;
}

size_t countHits(const Image &image)
{
  size_t hits = 0;
  for (float d : image.depth)
    hits += std::isfinite(d) ? 1 : 0;
  return hits;
}

// Rank 0's composited image against one process rendering every box, and
// rank 0's own boxes alone (which must differ when others hold boxes).
void checkComposite(const Render &composited,
    const std::vector<int> &owners,
    const float eye[3],
    const std::string &label)
{
  Status status;
  Device prism("prism", status);
  const Render whole =
      renderBoxes(prism.device, boxesOf(owners, -1), eye, "raycast", nullptr);
  const Render mine =
      renderBoxes(prism.device, boxesOf(owners, 0), eye, "raycast", nullptr);
  const Image &got = composited.image;
  const Image &want = whole.image;
  check(want.depth.size() == size_t(kSize) * kSize, label + ": reference");
  check(got.width == kSize && got.height == kSize
            && got.depth.size() == want.depth.size()
            && got.color.size() == want.color.size(),
      label + ": rank 0 maps color and depth of the frame's size");
  if (g_failures)
    return;
  // Enough of the grid is in view that a wrong composite cannot pass.
  const size_t hits = countHits(want);
  check(hits > want.depth.size() / 4 && hits < want.depth.size(),
      label + ": the view shows boxes and background (" + std::to_string(hits)
          + " of " + std::to_string(want.depth.size()) + " pixels hit)");
  check(got.normal.size() == want.normal.size()
            && got.albedo.size() == want.albedo.size()
            && want.normal.size() == 3 * want.depth.size(),
      label + ": rank 0 maps normal and albedo of the frame's size");
  if (g_failures)
    return;
  size_t depthMismatches = 0, colorMismatches = 0, vectorMismatches = 0,
         ownDiffers = 0;
  for (size_t i = 0; i < want.depth.size(); i++) {
    // Bitwise: equal infinities, and no tolerance for finite depths.
    depthMismatches +=
        std::memcmp(&got.depth[i], &want.depth[i], sizeof(float)) != 0;
    colorMismatches +=
        std::memcmp(&got.color[4 * i], &want.color[4 * i], 4 * sizeof(float))
        != 0;
    vectorMismatches +=
        std::memcmp(&got.normal[3 * i], &want.normal[3 * i], 3 * sizeof(float))
            != 0
        || std::memcmp(
               &got.albedo[3 * i], &want.albedo[3 * i], 3 * sizeof(float))
               != 0;
    ownDiffers +=
        std::memcmp(&mine.image.depth[i], &want.depth[i], sizeof(float)) != 0;
  }
  check(depthMismatches == 0,
      label + ": depth equals the single-process depth ("
          + std::to_string(depthMismatches) + " pixels differ)");
  check(colorMismatches == 0,
      label + ": color equals the single-process raycast color ("
          + std::to_string(colorMismatches) + " pixels differ)");
  check(vectorMismatches == 0,
      label + ": normal and albedo are the nearest process's, as in the"
              " single-process render ("
          + std::to_string(vectorMismatches) + " pixels differ)");
  int ranks = 1;
  for (int owner : owners)
    ranks = std::max(ranks, owner + 1);
  if (ranks > 1) {
    check(ownDiffers > 0,
        label + ": rank 0's own boxes alone give another image, so the other"
                " ranks' fragments were composited");
  }
  check(
      composited.boundsFound && whole.boundsFound
          && std::memcmp(composited.bounds, whole.bounds, sizeof(whole.bounds))
                 == 0,
      label + ": world bounds are the union over every rank");
}

// A frame with channel.color alone still composites by depth (the device
// keeps the depth buffer without the channel): rank 0's color equals the
// single-process color.
void compositeColorOnly(ANARIDevice device,
    const std::vector<int> &owners,
    int rank,
    MPI_Comm communicator,
    const std::string &label)
{
  ANARIWorld world = newBoxesWorld(device, boxesOf(owners, rank));
  ANARICamera camera = newCamera(device, kEyeB, 1.f);
  ANARIRenderer renderer = newRenderer(device, "raycast");
  ANARIFrame frame = newFrame(device, world, camera, renderer, kSize, kSize);
  for (const char *channel :
      {"channel.depth", "channel.normal", "channel.albedo"})
    anariUnsetParameter(device, frame, channel);
  anariSetParameter(
      device, frame, "mpiCommunicator", ANARI_VOID_POINTER, &communicator);
  anariCommitParameters(device, frame);
  anariRenderFrame(device, frame);
  anariFrameReady(device, frame, ANARI_WAIT);
  uint32_t width = 0, height = 0;
  ANARIDataType type = ANARI_UNKNOWN;
  const float *color = (const float *)anariMapFrame(
      device, frame, "channel.color", &width, &height, &type);
  if (rank == 0) {
    Status status;
    Device prism("prism", status);
    const Render whole = renderBoxes(
        prism.device, boxesOf(owners, -1), kEyeB, "raycast", nullptr);
    const std::vector<float> &want = whole.image.color;
    check(color && type == ANARI_FLOAT32_VEC4 && width == kSize
              && height == kSize && want.size() == size_t(kSize) * kSize * 4
              && std::memcmp(color, want.data(), want.size() * sizeof(float))
                     == 0,
        label + ": a color-only frame composites to the single-process color");
  }
  anariUnmapFrame(device, frame, "channel.color");
  anariRelease(device, frame);
  anariRelease(device, renderer);
  anariRelease(device, camera);
  anariRelease(device, world);
}

// Every process renders its share of the boxes on `communicator`; the
// communicator's rank 0 checks the result, for two views in turn.
// The boxes are dealt to the first `holders` ranks (all when 0); the others'
// worlds are empty.
void compositeOn(MPI_Comm communicator,
    uint32_t seed,
    const std::string &label,
    int holders = 0,
    const char *wrappedLibrary = nullptr)
{
  int rank = 0, ranks = 1;
  MPI_Comm_rank(communicator, &rank);
  MPI_Comm_size(communicator, &ranks);
  const std::vector<int> owners =
      boxOwners(holders > 0 ? holders : ranks, seed);
  Status status;
  {
    Device mpi("prism_mpi", status);
    if (!mpi.device)
      return;
    const char *mode = "composite";
    anariSetParameter(mpi.device, mpi.device, "mode", ANARI_STRING, mode);
    if (wrappedLibrary) {
      anariSetParameter(mpi.device,
          mpi.device,
          "wrappedLibrary",
          ANARI_STRING,
          wrappedLibrary);
    }
    anariCommitParameters(mpi.device, mpi.device);
    for (const float *eye : {kEyeA, kEyeB}) {
      MPI_Comm comm = communicator;
      const Render composited =
          renderBoxes(mpi.device, boxesOf(owners, rank), eye, "raycast", &comm);
      // Rank 0 sends every other band its fragments (RGBA and depth, 20
      // bytes) and its normal and albedo (12 bytes each), and gathers.
      const uint64_t band0 = uint64_t(kSize / ranks) * kSize;
      const uint64_t expected =
          (uint64_t(kSize) * kSize - band0) * (20 + 12 + 12);
      if (rank == 0) {
        check(composited.bytesSent == expected,
            label + ": rank 0 sent " + std::to_string(composited.bytesSent)
                + " bytes, expected " + std::to_string(expected));
      }
      if (rank == 0)
        checkComposite(composited,
            owners,
            eye,
            label + (eye == kEyeA ? " view A" : " view B"));
    }
    compositeColorOnly(mpi.device, owners, rank, communicator, label);
  }
  for (const std::string &e : status.take())
    check(false, label + ": unexpected error: " + e);
}

// Path traced boxes: small, lit, a few accumulated samples.
constexpr uint32_t kTracedSize = 96;
constexpr Lighting kSunlit{true, 4};

// Path traces `boxes` from kEyeA, kTracedSize pixels wide and `height` high.
Render traceBoxes(ANARIDevice device,
    const std::vector<int> &boxes,
    MPI_Comm *communicator,
    Lighting lighting,
    uint32_t height = kTracedSize)
{
  return renderBoxes(device,
      boxes,
      kEyeA,
      "pathtracer",
      communicator,
      kTracedSize,
      height,
      lighting);
}

// The prism device's single-process path traced image of every box.
Render traceWhole(const std::vector<int> &owners, Lighting lighting)
{
  Status status;
  Device prism("prism", status);
  return traceBoxes(prism.device, boxesOf(owners, -1), nullptr, lighting);
}

// This process's share of `owners`' boxes path traced by prism_mpi on
// `communicator` (in `mode`, or the default), errors reported as failures.
Render traceShare(MPI_Comm communicator,
    const std::vector<int> &owners,
    const char *mode,
    const std::string &label)
{
  int rank = 0;
  MPI_Comm_rank(communicator, &rank);
  Status status;
  Render traced;
  {
    Device mpi("prism_mpi", status);
    if (!mpi.device)
      return traced;
    if (mode)
      anariSetParameter(mpi.device, mpi.device, "mode", ANARI_STRING, mode);
    MPI_Comm comm = communicator;
    traced = traceBoxes(mpi.device, boxesOf(owners, rank), &comm, kSunlit);
  }
  for (const std::string &e : status.take())
    check(false, label + ": unexpected error: " + e);
  return traced;
}

// Peak signal to noise ratio of b's RGB against a's (peak 1); infinite
// when they are equal.
double psnr(const std::vector<float> &a, const std::vector<float> &b)
{
  double squared = 0.0;
  size_t count = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); i++) {
    if (i % 4 == 3)
      continue; // alpha
    const double d = double(a[i]) - double(b[i]);
    squared += d * d;
    count++;
  }
  if (squared == 0.0)
    return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(double(count) / squared);
}

size_t differingPixels(
    const std::vector<float> &a, const std::vector<float> &b, size_t components)
{
  size_t differing = 0;
  for (size_t i = 0; i + components <= a.size() && i < b.size();
       i += components)
    differing +=
        std::memcmp(&a[i], &b[i], components * sizeof(float)) != 0 ? 1 : 0;
  return differing;
}

// Every process traces its share of the lit boxes on `communicator`; the
// communicator's rank 0 checks that the image is the single-process path
// traced image of every box, shadows across processes included, and every
// other process that it ended with the same pixels (the lockstep held).
void checkPathTraced(const Render &traced,
    const std::vector<int> &owners,
    MPI_Comm communicator,
    const std::string &label,
    Lighting lighting);

void pathTraceOn(MPI_Comm communicator, uint32_t seed, const std::string &label)
{
  int ranks = 1;
  MPI_Comm_size(communicator, &ranks);
  const std::vector<int> owners = boxOwners(ranks, seed);
  const Render traced = traceShare(communicator, owners, nullptr, label);
  checkPathTraced(traced, owners, communicator, label, kSunlit);
}

// Collective over `communicator`: `traced`, this process's render of its
// share of `owners`' boxes, against the single-process render of all.
void checkPathTraced(const Render &traced,
    const std::vector<int> &owners,
    MPI_Comm communicator,
    const std::string &label,
    Lighting lighting)
{
  int rank = 0, ranks = 1;
  MPI_Comm_rank(communicator, &rank);
  MPI_Comm_size(communicator, &ranks);
  // What rank 0 holds, on every process.
  std::vector<float> color0 = traced.image.color;
  color0.resize(size_t(kTracedSize) * kTracedSize * 4);
  MPI_Bcast(color0.data(), int(color0.size()), MPI_FLOAT, 0, communicator);
  check(traced.image.color == color0,
      label + ": this process ends with rank 0's pixels");
  if (ranks > 1)
    check(traced.bytesSent > 0, label + ": mpiBytesSent counts the exchanges");
  else
    check(traced.bytesSent == 0, label + ": one process sends nothing");
  if (rank != 0)
    return;
  const Render whole = traceWhole(owners, lighting);
  const Image &got = traced.image, &want = whole.image;
  check(got.color.size() == want.color.size()
            && got.depth.size() == want.depth.size()
            && want.depth.size() == size_t(kTracedSize) * kTracedSize,
      label + ": rank 0 maps color and depth of the frame's size");
  if (g_failures)
    return;
  const size_t hits = countHits(want);
  check(hits > want.depth.size() / 4 && hits < want.depth.size(),
      label + ": the view shows boxes and background");
  const double quality = psnr(want.color, got.color);
  const size_t colorDiffers = differingPixels(want.color, got.color, 4);
  std::printf(
      "%s: %zu of %zu pixels differ from the single-process image,"
      " PSNR %.2f dB\n",
      label.c_str(),
      colorDiffers,
      want.depth.size(),
      quality);
  check(quality >= 40.0,
      label + ": color within 40 dB of the single-process image (got "
          + std::to_string(quality) + " dB)");
  check(differingPixels(want.depth, got.depth, 1) == 0,
      label + ": depth equals the single-process depth");
  check(differingPixels(want.albedo, got.albedo, 3) == 0
            && differingPixels(want.normal, got.normal, 3) == 0,
      label + ": albedo and normal equal the single-process ones");
}

// Composite mode path traces each process's boxes alone: visibility is the
// whole scene's (depth identical), but a box lit through a gap of its own
// world is shadowed by another process's box in the whole scene, so the
// color differs where shadows cross processes; pathtracer mode has them.
void compositeShadows(uint32_t seed)
{
  const int rank = worldRank(), ranks = worldSize();
  const std::vector<int> owners = boxOwners(ranks, seed);
  const Render composited =
      traceShare(MPI_COMM_WORLD, owners, "composite", "composite shadows");
  if (rank != 0)
    return;
  const Render whole = traceWhole(owners, kSunlit);
  const Image &got = composited.image, &want = whole.image;
  check(got.depth.size() == want.depth.size()
            && got.color.size() == want.color.size() && !want.depth.empty(),
      "composite shadows: rank 0 maps color and depth");
  if (g_failures)
    return;
  check(differingPixels(want.depth, got.depth, 1) == 0,
      "composite shadows: depth equals the single-process depth");
  // Pixels lit in composite mode that the whole scene keeps in shadow.
  size_t brighter = 0;
  for (size_t i = 0; i < want.depth.size(); i++) {
    const float gain = got.color[4 * i] + got.color[4 * i + 1]
                       + got.color[4 * i + 2] - want.color[4 * i]
                       - want.color[4 * i + 1] - want.color[4 * i + 2];
    brighter += gain > 0.3f ? 1 : 0;
  }
  const double quality = psnr(want.color, got.color);
  std::printf(
      "composite shadows: %zu pixels lit that the whole scene"
      " shadows, PSNR %.2f dB\n",
      brighter,
      quality);
  if (ranks > 1) {
    check(brighter > want.depth.size() / 100,
        "composite shadows: shadows across processes are missing ("
            + std::to_string(brighter) + " pixels brighter)");
  } else {
    // Equal to float rounding: composite mode adds the background after
    // accumulating, the single-process render inside each sample.
    check(quality >= 100.0,
        "composite shadows: one process composites the whole image");
  }
}

void scenarioPathTracer()
{
  pathTraceOn(MPI_COMM_WORLD, 7, "pathtracer");
  compositeShadows(7);
}

// This process's share of `owners`' boxes lit by `share`, path traced by
// prism_mpi on MPI_COMM_WORLD (in `mode`, or the default); any warning or
// error is a failure.
Render traceLitShare(const std::vector<int> &owners,
    const Lighting &share,
    const std::string &label,
    const char *mode = nullptr)
{
  Status status;
  Render traced;
  {
    Device mpi("prism_mpi", status);
    if (!mpi.device)
      return traced;
    if (mode)
      anariSetParameter(mpi.device, mpi.device, "mode", ANARI_STRING, mode);
    MPI_Comm comm = MPI_COMM_WORLD;
    traced = traceBoxes(mpi.device, boxesOf(owners, worldRank()), &comm, share);
  }
  for (const std::string &e : status.take(ANARI_SEVERITY_WARNING))
    check(false, label + ": unexpected report: " + e);
  return traced;
}

// One world, three frames: the holder's quad changes color between the
// first two renders (its world places its emitters anew, the others' do
// not), so every process must sample the new quad; the third render
// changes nothing, so no emitters are sent again.
void emissiveChange(const std::vector<int> &owners, int holder)
{
  const int rank = worldRank(), ranks = worldSize();
  Status status;
  Render before, after, again;
  {
    Device mpi("prism_mpi", status);
    if (!mpi.device)
      return;
    ANARIDevice device = mpi.device;
    ANARIWorld world = newBoxesWorld(device, boxesOf(owners, rank));
    addSunlight(device, world);
    ANARIMaterial glow =
        rank == holder ? addEmissiveQuad(device, world, kWarmGlow) : nullptr;
    ANARICamera camera = newCamera(device, kEyeA, 1.f);
    ANARIRenderer renderer = newRenderer(device, "pathtracer");
    MPI_Comm comm = MPI_COMM_WORLD;
    auto renderOnce = [&] {
      Render result;
      ANARIFrame frame =
          newFrame(device, world, camera, renderer, kTracedSize, kTracedSize);
      anariSetParameter(
          device, frame, "mpiCommunicator", ANARI_VOID_POINTER, &comm);
      anariCommitParameters(device, frame);
      anariRenderFrame(device, frame);
      anariFrameReady(device, frame, ANARI_WAIT);
      result.image = readFrame(device, frame);
      anariGetProperty(device,
          frame,
          "mpiBytesSent",
          ANARI_UINT64,
          &result.bytesSent,
          sizeof(result.bytesSent),
          ANARI_WAIT);
      anariRelease(device, frame);
      return result;
    };
    before = renderOnce();
    if (glow) {
      anariSetParameter(
          device, glow, "emissive", ANARI_FLOAT32_VEC3, kColdGlow);
      anariCommitParameters(device, glow);
      anariRelease(device, glow);
    }
    after = renderOnce();
    again = renderOnce();
    anariRelease(device, renderer);
    anariRelease(device, camera);
    anariRelease(device, world);
  }
  for (const std::string &e : status.take())
    check(false, "emissive change: unexpected error: " + e);
  Lighting warm{true, 1};
  warm.emissiveQuad = true;
  warm.glow = kWarmGlow;
  Lighting cold = warm;
  cold.glow = kColdGlow;
  checkPathTraced(before, owners, MPI_COMM_WORLD, "emissive, before", warm);
  checkPathTraced(after, owners, MPI_COMM_WORLD, "emissive, changed", cold);
  checkPathTraced(again, owners, MPI_COMM_WORLD, "emissive, again", cold);
  if (rank == 0)
    check(before.image.color != after.image.color,
        "emissive change: the new color shows");
  // What each process sends of its emitters: its bounds and emitter count
  // (28 bytes), and the holder 92 bytes for its quad (radiance, counts,
  // two triangles), to each other process.
  if (ranks > 1) {
    const uint64_t emitterBytes =
        uint64_t(rank == holder ? 28 + 92 : 28) * uint64_t(ranks - 1);
    check(after.bytesSent == again.bytesSent + emitterBytes,
        "emissive change: the emitters are sent after the change ("
            + std::to_string(after.bytesSent) + " bytes) and not again ("
            + std::to_string(again.bytesSent) + " bytes)");
  }
}

// An emissive quad held by one process (rank 1, or rank 0 alone) lights
// the boxes of every process: every process samples it in next-event
// estimation as one process holding the whole scene would, so rank 0's
// image is the single-process one. Lit by the quad alone, then by the quad
// and the sun (declared on every process), so light selection weighs a
// light at infinity by the radius of all the processes' worlds together.
void scenarioEmissive()
{
  const int rank = worldRank(), ranks = worldSize();
  const std::vector<int> owners = boxOwners(ranks, 5);
  const int holder = ranks > 1 ? 1 : 0;
  for (const bool sun : {false, true}) {
    Lighting whole{sun, 4};
    whole.emissiveQuad = true;
    Lighting share = whole;
    share.emissiveQuad = rank == holder;
    const std::string label =
        sun ? "emissive quad and sun" : "emissive quad alone";
    const Render traced = traceLitShare(owners, share, label);
    checkPathTraced(traced, owners, MPI_COMM_WORLD, label, whole);
  }
  emissiveChange(owners, holder);
}

// Composite mode path traces each process's part alone, but with every
// process's declared lights: the sun on rank 0 lights the boxes of the
// others, so the boxes rank 0 composites hold at least half the light
// they hold in the whole scene (the rest is what the compositing model
// cannot have: light bounced off the floor and the other processes'
// boxes; shadows from them), where with rank 0's sun unknown to the
// others they would be black.
void compositeLights(const std::vector<int> &owners)
{
  const int rank = worldRank();
  Lighting whole{true, 4};
  whole.floor = true;
  Lighting share = whole;
  share.lit = rank == 0;
  share.floor = rank == 0;
  const Render composited =
      traceLitShare(owners, share, "composite, sun on rank 0", "composite");
  if (rank != 0 || g_failures)
    return;
  Status status;
  Render all, floor;
  {
    Device prism("prism", status);
    all = traceBoxes(prism.device, boxesOf(owners, -1), nullptr, whole);
    floor = traceBoxes(prism.device, {}, nullptr, whole);
  }
  const Image &got = composited.image, &want = all.image;
  check(got.depth == want.depth && !want.depth.empty(),
      "composite, sun on rank 0: depth equals the single-process depth");
  if (g_failures)
    return;
  double gotSum = 0.0, wantSum = 0.0;
  size_t boxPixels = 0;
  for (size_t i = 0; i < want.depth.size(); i++) {
    // A box, not the floor nor the background.
    if (!std::isfinite(want.depth[i]) || want.depth[i] == floor.image.depth[i])
      continue;
    boxPixels++;
    for (int c = 0; c < 3; c++) {
      gotSum += got.color[4 * i + c];
      wantSum += want.color[4 * i + c];
    }
  }
  std::printf(
      "composite, sun on rank 0: %zu box pixels, %.1f of the whole scene's "
      "%.1f\n",
      boxPixels,
      gotSum,
      wantSum);
  check(boxPixels > want.depth.size() / 10 && gotSum >= 0.5 * wantSum,
      "composite, sun on rank 0: the other processes' boxes are lit");
}

// The paper's model: a light is globally visible wherever it is declared.
// Rank 0 holds the floor and the world's only light; the other processes
// hold the boxes (on one process, rank 0 all). Every process samples the
// light as one process holding the whole scene would, so rank 0's image is
// the single-process one: lit by the sun, whose shadows the other
// processes' boxes cast on rank 0's floor are there (floor pixels, where
// the floor alone is seen at the same depth, at under half the brightness
// of the floor rendered alone); then by an hdri sky, whose image travels
// with it.
void scenarioLights()
{
  const int rank = worldRank(), ranks = worldSize();
  std::vector<int> owners = boxOwners(std::max(ranks - 1, 1), 9);
  for (int &owner : owners)
    owner += ranks > 1 ? 1 : 0;
  for (const bool sky : {false, true}) {
    const std::string label = sky ? "sky on rank 0" : "sun on rank 0";
    Lighting whole{!sky, 4};
    whole.floor = true;
    whole.sky = sky;
    Lighting share = whole;
    share.lit = whole.lit && rank == 0;
    share.sky = whole.sky && rank == 0;
    share.floor = rank == 0;
    const Render traced = traceLitShare(owners, share, label);
    checkPathTraced(traced, owners, MPI_COMM_WORLD, label, whole);
    if (rank != 0 || g_failures || sky)
      continue;
    // The floor alone, lit by the sun, in one process.
    Status status;
    Render floor;
    {
      Device prism("prism", status);
      floor = traceBoxes(prism.device, {}, nullptr, whole);
    }
    const Image &got = traced.image, &alone = floor.image;
    size_t floorSeen = 0, shadowed = 0;
    for (size_t i = 0; i < alone.depth.size() && i < got.depth.size(); i++) {
      if (!std::isfinite(alone.depth[i]) || got.depth[i] != alone.depth[i])
        continue;
      floorSeen++;
      const float lit =
          alone.color[4 * i] + alone.color[4 * i + 1] + alone.color[4 * i + 2];
      const float seen =
          got.color[4 * i] + got.color[4 * i + 1] + got.color[4 * i + 2];
      shadowed += seen < 0.5f * lit ? 1 : 0;
    }
    std::printf("%s: %zu of %zu floor pixels in shadow\n",
        label.c_str(),
        shadowed,
        floorSeen);
    check(floorSeen > alone.depth.size() / 10 && shadowed > floorSeen / 100,
        label + ": the boxes of the other processes shadow the floor ("
            + std::to_string(shadowed) + " of " + std::to_string(floorSeen)
            + " floor pixels)");
  }
  compositeLights(owners);
}

// Accumulating, the last process commits its world again (its content
// unchanged): that restarts its accumulation, and every process must
// restart with it, or their paths would start from different samples and
// the lockstep break. Two samples after the commit make the single-process
// image of two samples.
void releaseFrameAndScene(ANARIDevice d,
    ANARIFrame frame,
    ANARIRenderer renderer,
    ANARICamera camera,
    ANARIWorld world)
{
  for (ANARIObject o : {(ANARIObject)frame,
           (ANARIObject)renderer,
           (ANARIObject)camera,
           (ANARIObject)world})
    anariRelease(d, o);
}

void scenarioAccumulationRestart()
{
  const int rank = worldRank(), ranks = worldSize();
  const std::vector<int> owners = boxOwners(ranks, 7);
  Status status;
  Render traced;
  {
    Device mpi("prism_mpi", status);
    if (!mpi.device)
      return;
    const ANARIDevice d = mpi.device;
    ANARIWorld world = newBoxesWorld(d, boxesOf(owners, rank));
    addSunlight(d, world);
    ANARICamera camera = newCamera(d, kEyeA, 1.f);
    ANARIRenderer renderer = newRenderer(d, "pathtracer");
    ANARIFrame frame =
        newFrame(d, world, camera, renderer, kTracedSize, kTracedSize);
    const bool accumulate = true;
    anariSetParameter(d, frame, "accumulation", ANARI_BOOL, &accumulate);
    anariCommitParameters(d, frame);
    auto render = [&] {
      anariRenderFrame(d, frame);
      anariFrameReady(d, frame, ANARI_WAIT);
    };
    for (int sample = 0; sample < 3; sample++)
      render();
    if (rank == ranks - 1)
      anariCommitParameters(d, world);
    render();
    render();
    traced.image = readFrame(d, frame);
    anariGetProperty(d,
        frame,
        "mpiBytesSent",
        ANARI_UINT64,
        &traced.bytesSent,
        sizeof(traced.bytesSent),
        ANARI_WAIT);
    releaseFrameAndScene(d, frame, renderer, camera, world);
  }
  for (const std::string &e : status.take())
    check(false, "accumulation restart: unexpected error: " + e);
  checkPathTraced(traced,
      owners,
      MPI_COMM_WORLD,
      "accumulation restarted by one process",
      Lighting{true, 2});
}

// Adaptive sampling in replicated mode: each process samples its own rows
// of tiles and knows only their blocks, so the frame's activePixels is
// the sum over the processes. With a threshold every estimate meets, every
// block stops after the minimum of eight samples: all pixels are active
// before, none after, as every process reads it (rank 0 once counted the
// others' rows as active for ever).
void scenarioAdaptiveReplicated()
{
  const int ranks = worldSize();
  const std::vector<int> owners = boxOwners(ranks, 7);
  Status status;
  {
    Device mpi("prism_mpi", status);
    if (!mpi.device)
      return;
    const ANARIDevice d = mpi.device;
    anariSetParameter(d, d, "mode", ANARI_STRING, "replicated");
    anariCommitParameters(d, d);
    ANARIWorld world = newBoxesWorld(d, boxesOf(owners, -1));
    addSunlight(d, world);
    ANARICamera camera = newCamera(d, kEyeA, 1.f);
    ANARIRenderer renderer = newRenderer(d, "pathtracer");
    const float threshold = 1e30f;
    anariSetParameter(d, renderer, "errorThreshold", ANARI_FLOAT32, &threshold);
    anariCommitParameters(d, renderer);
    // Three rows of 32-pixel tiles: every process of up to three has some.
    ANARIFrame frame =
        newFrame(d, world, camera, renderer, kTracedSize, kTracedSize);
    const bool accumulate = true;
    anariSetParameter(d, frame, "accumulation", ANARI_BOOL, &accumulate);
    anariCommitParameters(d, frame);
    auto activeAfter = [&](int renders) {
      for (int i = 0; i < renders; i++) {
        anariRenderFrame(d, frame);
        anariFrameReady(d, frame, ANARI_WAIT);
      }
      uint64_t active = ~0ull;
      check(anariGetProperty(d,
                frame,
                "activePixels",
                ANARI_UINT64,
                &active,
                sizeof(active),
                ANARI_WAIT)
                == 1,
          "adaptive replicated: activePixels is answered");
      return active;
    };
    const uint64_t all = uint64_t(kTracedSize) * kTracedSize;
    const uint64_t afterSeven = activeAfter(7);
    check(afterSeven == all,
        "adaptive replicated: every pixel active after 7 samples, not "
            + std::to_string(afterSeven));
    const uint64_t afterEight = activeAfter(1);
    check(afterEight == 0,
        "adaptive replicated: no pixel active after 8 samples, not "
            + std::to_string(afterEight));
    releaseFrameAndScene(d, frame, renderer, camera, world);
  }
  for (const std::string &e : status.take())
    check(false, "adaptive replicated: unexpected error: " + e);
}

// Runs `scenario(communicator, half)` on the even and the odd ranks of
// MPI_COMM_WORLD at once, each half on a communicator of its own.
template <typename Scenario>
void onHalves(Scenario scenario)
{
  const int rank = worldRank();
  MPI_Comm group;
  MPI_Comm_split(MPI_COMM_WORLD, rank % 2, rank, &group);
  scenario(group, uint32_t(rank % 2));
  MPI_Comm_free(&group);
}

// Two groups of processes path trace different interleavings at once.
void scenarioPathTracerSubcommunicator()
{
  onHalves([](MPI_Comm group, uint32_t half) {
    pathTraceOn(group,
        21 + half,
        "pathtracer subcommunicator group " + std::to_string(half));
  });
}

void scenarioComposite()
{
  compositeOn(MPI_COMM_WORLD, 7, "composite");
  const int ranks = worldSize();
  if (ranks > 1)
    compositeOn(MPI_COMM_WORLD, 8, "composite, last rank empty", ranks - 1);
}

// Rank 0's channels of two renders, bit for bit; the number of pixels that
// differ in any channel.
size_t differingChannels(const Image &a, const Image &b)
{
  if (a.color.size() != b.color.size() || a.depth.size() != b.depth.size()
      || a.normal.size() != b.normal.size()
      || a.albedo.size() != b.albedo.size())
    return ~size_t(0);
  size_t differing = 0;
  for (size_t i = 0; i < a.depth.size(); i++) {
    differing +=
        std::memcmp(&a.color[4 * i], &b.color[4 * i], 4 * sizeof(float)) != 0
        || std::memcmp(&a.depth[i], &b.depth[i], sizeof(float)) != 0
        || std::memcmp(&a.normal[3 * i], &b.normal[3 * i], 3 * sizeof(float))
               != 0
        || std::memcmp(&a.albedo[3 * i], &b.albedo[3 * i], 3 * sizeof(float))
               != 0;
  }
  return differing;
}

// A prism_mpi device whose objects live on a device of `wrappedLibrary`,
// chosen before any object (NULL: the built-in core), in `mode`.
struct WrappingDevice : Device
{
  WrappingDevice(Status &status, const char *wrappedLibrary, const char *mode)
      : Device("prism_mpi", status)
  {
    if (!device)
      return;
    anariSetParameter(device, device, "mode", ANARI_STRING, mode);
    if (wrappedLibrary) {
      anariSetParameter(
          device, device, "wrappedLibrary", ANARI_STRING, wrappedLibrary);
    }
    anariCommitParameters(device, device);
  }
};

// wrappedLibrary "prism": the plain prism library, loaded by prism_mpi as
// any other library, renders each process's boxes; rank 0's composite
// equals the single-process render (depth, raycast color, normal, albedo,
// bytes sent, bounds) and the built-in composite mode's image bit for bit.
void scenarioWrapped()
{
  const int ranks = worldSize();
  compositeOn(MPI_COMM_WORLD, 7, "wrapped prism", 0, "prism");
  if (ranks > 1) {
    compositeOn(MPI_COMM_WORLD,
        8,
        "wrapped prism, last rank empty",
        ranks - 1,
        "prism");
  }
  const int rank = worldRank();
  const std::vector<int> owners = boxOwners(ranks, 9);
  MPI_Comm comm = MPI_COMM_WORLD;
  Status status;
  Render builtIn, passedThrough;
  {
    WrappingDevice mpi(status, nullptr, "composite");
    builtIn =
        renderBoxes(mpi.device, boxesOf(owners, rank), kEyeA, "raycast", &comm);
  }
  {
    WrappingDevice mpi(status, "prism", "composite");
    passedThrough =
        renderBoxes(mpi.device, boxesOf(owners, rank), kEyeA, "raycast", &comm);
  }
  if (rank == 0) {
    const size_t differing =
        differingChannels(builtIn.image, passedThrough.image);
    check(differing == 0 && !builtIn.image.depth.empty(),
        "wrapped prism: rank 0's channels equal the built-in composite"
        " mode's ("
            + std::to_string(differing) + " pixels differ)");
    check(builtIn.bytesSent == passedThrough.bytesSent,
        "wrapped prism: the same bytes are sent as by the built-in"
        " composite mode");
  }
  for (const std::string &e : status.take())
    check(false, "wrapped prism: unexpected error: " + e);

  // Another background and an sRGB color channel: the application's
  // background goes under the composite once, in the type it asked for.
  {
    WrappingDevice mpi(status, "prism", "composite");
    WrappingDevice core(status, nullptr, "composite");
    std::vector<std::vector<uint8_t>> images;
    for (ANARIDevice d : {mpi.device, core.device}) {
      ANARIWorld world = newBoxesWorld(d, boxesOf(owners, rank));
      ANARICamera camera = newCamera(d, kEyeB, 1.f);
      ANARIRenderer renderer = newRenderer(d, "raycast");
      const float background[3] = {0.9f, 0.5f, 0.1f};
      anariSetParameter(
          d, renderer, "background", ANARI_FLOAT32_VEC3, background);
      anariCommitParameters(d, renderer);
      ANARIFrame frame = newFrame(d, world, camera, renderer, kSize, kSize);
      const ANARIDataType srgb = ANARI_UFIXED8_RGBA_SRGB;
      anariSetParameter(d, frame, "channel.color", ANARI_DATA_TYPE, &srgb);
      anariSetParameter(d, frame, "mpiCommunicator", ANARI_VOID_POINTER, &comm);
      anariCommitParameters(d, frame);
      anariRenderFrame(d, frame);
      anariFrameReady(d, frame, ANARI_WAIT);
      uint32_t width = 0, height = 0;
      ANARIDataType type = ANARI_UNKNOWN;
      const auto *pixels = (const uint8_t *)anariMapFrame(
          d, frame, "channel.color", &width, &height, &type);
      std::vector<uint8_t> image;
      if (pixels && type == ANARI_UFIXED8_RGBA_SRGB && width == kSize
          && height == kSize)
        image.assign(pixels, pixels + size_t(kSize) * kSize * 4);
      images.push_back(image);
      anariUnmapFrame(d, frame, "channel.color");
      anariRelease(d, frame);
      anariRelease(d, renderer);
      anariRelease(d, camera);
      anariRelease(d, world);
    }
    check(images[0].size() == size_t(kSize) * kSize * 4,
        "wrapped prism: every rank maps channel.color in its sRGB type");
    if (rank == 0) {
      size_t backgroundPixels = 0;
      for (size_t i = 0; i + 3 < images[0].size(); i += 4) {
        backgroundPixels += images[0][i] == 243 && images[0][i + 1] == 188
                            && images[0][i + 2] == 89
                            && images[0][i + 3] == 255;
      }
      check(images[0] == images[1] && backgroundPixels > 0,
          "wrapped prism: an sRGB frame with an RGB background equals the"
          " built-in composite mode's ("
              + std::to_string(backgroundPixels)
              + " pixels show the background)");
    }
  }
  for (const std::string &e : status.take())
    check(false, "wrapped prism, sRGB: unexpected error: " + e);

  // Another mode is composited all the same, with one warning.
  {
    WrappingDevice mpi(status, "prism", "pathtracer");
    Render render;
    for (int i = 0; i < 2; i++) {
      render = renderBoxes(
          mpi.device, boxesOf(owners, rank), kEyeA, "raycast", &comm);
    }
    const std::vector<std::string> warnings =
        status.take(ANARI_SEVERITY_WARNING);
    check(warnings.size() == 1
              && warnings[0].find("mode 'pathtracer'") != std::string::npos
              && warnings[0].find("composited instead") != std::string::npos,
        "wrapped prism in pathtracer mode: composited, warned about once");
    if (rank == 0) {
      check(differingChannels(render.image, passedThrough.image) == 0,
          "wrapped prism in pathtracer mode: the composite mode's image");
    }
  }
}

// A wrappedLibrary that cannot be loaded, a device subtype the library
// does not have, and a wrappedLibrary set too late are reported; the
// device renders with the built-in core, correctly.
void scenarioWrappedErrors()
{
  const int rank = worldRank(), ranks = worldSize();
  const std::vector<int> owners = boxOwners(ranks, 10);
  MPI_Comm comm = MPI_COMM_WORLD;
  Status status;
  {
    WrappingDevice mpi(status, "no_such_library", "composite");
    check(status.take().empty(), "nothing is reported before the first object");
    const Render render =
        renderBoxes(mpi.device, boxesOf(owners, rank), kEyeA, "raycast", &comm);
    check(oneErrorMentioning(status,
              {"cannot load wrappedLibrary 'no_such_library'",
                  "built-in prism core renders instead"}),
        "an unloadable wrappedLibrary is reported");
    if (rank == 0)
      checkComposite(render, owners, kEyeA, "after an unloadable library");
  }
  {
    WrappingDevice mpi(status, "prism", "composite");
    anariSetParameter(
        mpi.device, mpi.device, "wrappedDevice", ANARI_STRING, "nonsense");
    const Render render =
        renderBoxes(mpi.device, boxesOf(owners, rank), kEyeB, "raycast", &comm);
    check(oneErrorMentioning(status,
              {"wrappedLibrary 'prism' has no device of subtype 'nonsense'"}),
        "an unknown wrappedDevice is reported");
    if (rank == 0)
      checkComposite(render, owners, kEyeB, "after an unknown device subtype");
  }
  {
    // Released and foreign handles are reported, never forwarded.
    WrappingDevice mpi(status, "prism", "composite");
    ANARICamera camera = anariNewCamera(mpi.device, "perspective");
    ANARIFrame frame = anariNewFrame(mpi.device);
    anariRelease(mpi.device, camera);
    anariCommitParameters(mpi.device, camera);
    check(oneErrorMentioning(status, {"anariCommitParameters", "no live"}),
        "committing a released object is reported");
    anariSetParameter(mpi.device, frame, "camera", ANARI_CAMERA, &camera);
    check(oneErrorMentioning(status, {"anariSetParameter (its value)"}),
        "a released object as a parameter value is reported");
    uint32_t width = 1, height = 1;
    ANARIDataType type = ANARI_FLOAT32;
    check(!anariMapFrame(mpi.device,
              (ANARIFrame)camera,
              "channel.color",
              &width,
              &height,
              &type)
              && width == 0 && type == ANARI_UNKNOWN,
        "mapping a released handle gives nothing");
    check(oneErrorMentioning(status, {"anariMapFrame", "no live"}),
        "mapping a released handle is reported");
    anariRelease(mpi.device, frame);
    anariRelease(mpi.device, frame);
    check(oneErrorMentioning(status, {"anariRelease", "no live"}),
        "releasing twice is reported");
  }
  {
    Device mpi("prism_mpi", status);
    anariSetParameter(
        mpi.device, mpi.device, "wrappedLibrary", ANARI_STRING, "prism_mpi");
    const int notAString = 3;
    anariSetParameter(
        mpi.device, mpi.device, "wrappedDevice", ANARI_INT32, &notAString);
    check(oneErrorMentioning(status, {"wrappedDevice", "STRING", "INT32"}),
        "a wrappedDevice that is no string is reported");
    ANARICamera camera = anariNewCamera(mpi.device, "perspective");
    check(oneErrorMentioning(status, {"cannot wrap library 'prism_mpi'"}),
        "prism_mpi does not wrap itself");
    anariSetParameter(
        mpi.device, mpi.device, "wrappedLibrary", ANARI_STRING, "prism");
    check(oneErrorMentioning(status,
              {"'wrappedLibrary' must be set before", "built-in prism core"}),
        "a wrappedLibrary set after the first object is reported");
    anariRelease(mpi.device, camera);
  }
  check(
      status.take(ANARI_SEVERITY_WARNING).empty(), "nothing else is reported");
}

// PRISM_MPI_WRAPPED_LIBRARY=prism in the environment (set by ctest) wraps
// prism for a program that sets nothing; the composite is right.
void scenarioWrappedEnvironment()
{
  const int rank = worldRank(), ranks = worldSize();
  const std::vector<int> owners = boxOwners(ranks, 12);
  MPI_Comm comm = MPI_COMM_WORLD;
  Status status;
  Device mpi("prism_mpi", status);
  const Render render =
      renderBoxes(mpi.device, boxesOf(owners, rank), kEyeB, "raycast", &comm);
  if (rank == 0)
    checkComposite(render, owners, kEyeB, "wrapped from the environment");
  anariSetParameter(
      mpi.device, mpi.device, "wrappedLibrary", ANARI_STRING, "prism");
  check(oneErrorMentioning(status, {"render with library 'prism'"}),
      "the environment's wrappedLibrary is in use");
}

// Two groups of processes render different scenes at once, each on its own
// communicator.
void scenarioSubcommunicator()
{
  onHalves([](MPI_Comm group, uint32_t half) {
    compositeOn(
        group, 11 + half, "subcommunicator group " + std::to_string(half));
  });
}

// Disagreements are errors on every process, naming the ranks, and the
// processes stay in step for the next, agreeing, render.
void scenarioMismatch()
{
  const int rank = worldRank(), ranks = worldSize();
  const int odd = ranks - 1;
  const std::vector<int> owners = boxOwners(ranks, 3);
  Status status;
  Device mpi("prism_mpi", status);
  if (!mpi.device)
    return;
  MPI_Comm comm = MPI_COMM_WORLD;

  const Render sizes = renderBoxes(mpi.device,
      boxesOf(owners, rank),
      kEyeA,
      "raycast",
      &comm,
      kSize,
      rank == odd ? kSize / 2 : kSize);
  const std::string odder = "on rank " + std::to_string(odd);
  // The ranks that agree with one another: "on rank 0", "on ranks 0,1,2".
  std::string others = odd > 1 ? "on ranks 0" : "on rank 0";
  for (int r = 1; r < odd; r++) {
    others += ',';
    others += std::to_string(r);
  }
  check(oneErrorMentioning(status,
            {"disagree", "size", "64x32 " + odder, "64x64 on rank"},
            true),
      "a size mismatch is reported naming the ranks");

  // The same in pathtracer mode (the default) with the path tracer: a
  // process that disagrees never enters the collectives of the bounces.
  const Lighting oneSample{true, 1};
  traceBoxes(mpi.device,
      boxesOf(owners, rank),
      &comm,
      oneSample,
      rank == odd ? kTracedSize / 2 : kTracedSize);
  check(oneErrorMentioning(status,
            {"disagree", "size", "96x48 " + odder, "96x96 on rank"},
            true),
      "a size mismatch in pathtracer mode is reported naming the ranks");
  // Lights may differ between the processes: each process's lights are
  // every process's (mpi::lights checks the image), so a process without
  // a light, or with a light of its own, renders with no report.
  traceBoxes(
      mpi.device, boxesOf(owners, rank), &comm, Lighting{rank != odd, 1});
  const float otherSun[3] = {0.3f, -1.f, -0.5f};
  traceBoxes(mpi.device,
      boxesOf(owners, rank),
      &comm,
      Lighting{true, 1, rank == odd ? otherSun : kSunDirection});
  {
    const std::vector<std::string> reports =
        status.take(ANARI_SEVERITY_WARNING);
    check(reports.empty(),
        "lights that differ in pathtracer mode render without a report"
            + (reports.empty() ? std::string() : ": " + reports[0]));
  }
  const Render traced =
      traceBoxes(mpi.device, boxesOf(owners, rank), &comm, oneSample);
  check(
      status.take().empty(), "an agreeing path traced render reports nothing");
  checkPathTraced(traced,
      owners,
      MPI_COMM_WORLD,
      "path traced after a mismatch",
      oneSample);

  renderBoxes(mpi.device,
      boxesOf(owners, rank),
      kEyeA,
      rank == odd ? "ao" : "raycast",
      &comm);
  check(oneErrorMentioning(
            status, {"disagree", "renderer", "'ao' " + odder}, true),
      "a renderer mismatch is reported naming the ranks");

  // Renderer and camera parameters must match too (compared by a hash of
  // each object's committed parameters, in every mode). Here, path
  // tracing: the last rank's renderer has another ambient radiance.
  renderBoxes(mpi.device,
      boxesOf(owners, rank),
      kEyeA,
      "pathtracer",
      &comm,
      kSize,
      kSize,
      Lighting{true, 1},
      [&](ANARICamera, ANARIRenderer renderer) {
        const float radiance = rank == odd ? 0.5f : 0.25f;
        anariSetParameter(
            mpi.device, renderer, "ambientRadiance", ANARI_FLOAT32, &radiance);
        anariCommitParameters(mpi.device, renderer);
      });
  check(oneErrorMentioning(status,
            {"disagree", "renderer parameters (a hash of them)", odder, others},
            true,
            {"camera", "'pathtracer'"}),
      "a renderer parameter that differs in pathtracer mode is reported "
      "naming the ranks");

  // Replicated rendering needs the same world everywhere: rank 0 holding
  // every box and the others their share differ in the fingerprint.
  anariSetParameter(mpi.device, mpi.device, "mode", ANARI_STRING, "replicated");
  renderBoxes(mpi.device,
      boxesOf(owners, rank == 0 ? -1 : rank),
      kEyeA,
      "raycast",
      &comm);
  check(oneErrorMentioning(status,
            {"disagree",
                "world (bounds, primitives, lights, volumes)",
                "768 primitives, 0 lights, 0 volumes on rank 0"},
            true),
      "replicated worlds that differ are reported");
  // Worlds alike in extent and sizes but not in contents: every box but
  // one inner box, another one on the last rank (the same bounds and
  // number of boxes, other vertices and colors).
  auto everyBoxBut = [](int left) {
    std::vector<int> boxes;
    for (int box = 0; box < kBoxesPerSide * kBoxesPerSide * kBoxesPerSide;
         box++) {
      if (box != left)
        boxes.push_back(box);
    }
    return boxes;
  };
  const int kInnerBox = 1 + kBoxesPerSide * (1 + kBoxesPerSide);
  renderBoxes(mpi.device,
      everyBoxBut(rank == odd ? kInnerBox + 1 : kInnerBox),
      kEyeA,
      "raycast",
      &comm);
  check(oneErrorMentioning(status,
            {"disagree", "world contents", odder, others},
            true,
            {"world (bounds"}),
      "replicated worlds of the same extent and sizes whose contents differ "
      "are reported naming the ranks");
  // The same world everywhere but the last rank's background differs.
  renderBoxes(mpi.device,
      boxesOf(owners, -1),
      kEyeA,
      "raycast",
      &comm,
      kSize,
      kSize,
      {},
      [&](ANARICamera, ANARIRenderer renderer) {
        if (rank != odd)
          return;
        const float background[4] = {0.1f, 0.2f, 0.4f, 1.f};
        anariSetParameter(
            mpi.device, renderer, "background", ANARI_FLOAT32_VEC4, background);
        anariCommitParameters(mpi.device, renderer);
      });
  check(oneErrorMentioning(status,
            {"disagree", "renderer parameters (a hash of them)", odder, others},
            true,
            {"camera", "world"}),
      "a renderer background that differs in replicated mode is reported "
      "naming the ranks");
  // The same world everywhere: silent, and rank 0's image is one
  // process's.
  const Render replicated =
      renderBoxes(mpi.device, boxesOf(owners, -1), kEyeA, "raycast", &comm);
  check(status.take().empty(), "an agreeing replicated render reports nothing");
  if (rank == 0)
    checkComposite(replicated, owners, kEyeA, "replicated after mismatches");
  anariSetParameter(mpi.device, mpi.device, "mode", ANARI_STRING, "composite");

  // The last rank's camera stands elsewhere (composite mode).
  renderBoxes(mpi.device,
      boxesOf(owners, rank),
      kEyeA,
      "raycast",
      &comm,
      kSize,
      kSize,
      {},
      [&](ANARICamera camera, ANARIRenderer) {
        if (rank != odd)
          return;
        anariSetParameter(
            mpi.device, camera, "position", ANARI_FLOAT32_VEC3, kEyeB);
        anariCommitParameters(mpi.device, camera);
      });
  check(oneErrorMentioning(status,
            {"disagree",
                "camera (a hash of its subtype and parameters)",
                odder,
                others},
            true,
            {"renderer"}),
      "a camera position that differs is reported naming the ranks");

  // Parameters none had set, set in another order on the last rank (and
  // one of them twice there, the last value the others' one), agree: the
  // next render is silent and right.
  const Render agreed = renderBoxes(mpi.device,
      boxesOf(owners, rank),
      kEyeA,
      "raycast",
      &comm,
      kSize,
      kSize,
      {},
      [&](ANARICamera camera, ANARIRenderer renderer) {
        const float radiance = 0.f, otherRadiance = 2.f;
        const float ambient[3] = {1.f, 1.f, 1.f};
        const float aperture = 0.f, focus = 1.f;
        auto setRadiance = [&](const float *value) {
          anariSetParameter(
              mpi.device, renderer, "ambientRadiance", ANARI_FLOAT32, value);
        };
        auto setAmbient = [&] {
          anariSetParameter(mpi.device,
              renderer,
              "ambientColor",
              ANARI_FLOAT32_VEC3,
              ambient);
        };
        auto setAperture = [&] {
          anariSetParameter(
              mpi.device, camera, "apertureRadius", ANARI_FLOAT32, &aperture);
        };
        auto setFocus = [&] {
          anariSetParameter(
              mpi.device, camera, "focusDistance", ANARI_FLOAT32, &focus);
        };
        if (rank == odd) {
          setRadiance(&otherRadiance);
          setAmbient();
          setRadiance(&radiance);
          setFocus();
          setAperture();
        } else {
          setAmbient();
          setRadiance(&radiance);
          setAperture();
          setFocus();
        }
        anariCommitParameters(mpi.device, renderer);
        anariCommitParameters(mpi.device, camera);
      });
  check(status.take().empty(),
      "an agreeing render (parameters set in another order) reports nothing");
  if (rank == 0)
    checkComposite(agreed, owners, kEyeA, "after mismatches");
}

// A process that does not come to anariRenderFrame is reported, naming it,
// once the device's mpiTimeout passes; the processes then render together.
void scenarioAbsent()
{
  const int rank = worldRank(), ranks = worldSize();
  const int absent = ranks - 1;
  const std::vector<int> owners = boxOwners(ranks, 9);
  Status status;
  Device mpi("prism_mpi", status);
  if (!mpi.device)
    return;
  const float timeout = 1.f;
  anariSetParameter(
      mpi.device, mpi.device, "mpiTimeout", ANARI_FLOAT32, &timeout);
  ANARIDevice d = mpi.device;
  ANARIWorld world = newBoxesWorld(d, boxesOf(owners, rank));
  ANARICamera camera = newCamera(d, kEyeA, 1.f);
  ANARIRenderer renderer = newRenderer(d, "raycast");
  ANARIFrame frame = newFrame(d, world, camera, renderer, kSize, kSize);
  // The present ranks meet together, so only the absent one is late ...
  MPI_Barrier(MPI_COMM_WORLD);
  // ... and they give up on it before it comes: it waits at a barrier they
  // reach only once their render has returned.
  if (rank != absent) {
    anariRenderFrame(d, frame);
    check(oneErrorMentioning(status,
              {"rank " + std::to_string(absent),
                  "did not call anariRenderFrame within 1 s"}),
        "the absent rank is reported");
    uint64_t bytesSent = ~0ull;
    anariGetProperty(d,
        frame,
        "mpiBytesSent",
        ANARI_UINT64,
        &bytesSent,
        sizeof(bytesSent),
        ANARI_WAIT);
    check(bytesSent == 0,
        "the abandoned render sends no pixels (mpiBytesSent "
            + std::to_string(bytesSent) + ")");
  }
  MPI_Barrier(MPI_COMM_WORLD);
  const float patient = 30.f;
  anariSetParameter(
      mpi.device, mpi.device, "mpiTimeout", ANARI_FLOAT32, &patient);
  Render together;
  anariRenderFrame(d, frame);
  anariFrameReady(d, frame, ANARI_WAIT);
  together.image = readFrame(d, frame);
  together.boundsFound = anariGetProperty(d,
      world,
      "bounds",
      ANARI_FLOAT32_BOX3,
      together.bounds,
      sizeof(together.bounds),
      ANARI_WAIT);
  for (const std::string &e : status.take())
    check(false, "rendering together reports nothing, got: " + e);
  if (rank == 0)
    checkComposite(together, owners, kEyeA, "after an absent rank");
  anariRelease(d, frame);
  anariRelease(d, renderer);
  anariRelease(d, camera);
  anariRelease(d, world);
}

// Bad parameters are reported, and the extension is advertised.
void scenarioParameters()
{
  Status status;
  Device mpi("prism_mpi", status);
  if (!mpi.device)
    return;
  const char **extensions = anariGetDeviceExtensions(mpi.library, "default");
  bool advertised = false;
  for (const char **e = extensions; e && *e; e++)
    advertised = advertised || std::string(*e) == "ANARI_KHR_DATA_PARALLEL_MPI";
  check(advertised, "the library lists ANARI_KHR_DATA_PARALLEL_MPI");
  const char **property = nullptr;
  anariGetProperty(mpi.device,
      mpi.device,
      "extension",
      ANARI_STRING_LIST,
      &property,
      sizeof(property),
      ANARI_WAIT);
  advertised = false;
  for (const char **e = property; e && *e; e++)
    advertised = advertised || std::string(*e) == "ANARI_KHR_DATA_PARALLEL_MPI";
  check(advertised, "the device's extension property lists it");

  anariSetParameter(mpi.device, mpi.device, "mode", ANARI_STRING, "sideways");
  check(
      oneErrorMentioning(status, {"mode", "'sideways'", "stays 'pathtracer'"}),
      "an unknown mode is reported");
  const int notAString = 1;
  anariSetParameter(mpi.device, mpi.device, "mode", ANARI_INT32, &notAString);
  check(oneErrorMentioning(status, {"mode", "INT32"}),
      "a mode that is no string is reported");

  const float negative = -1.f;
  anariSetParameter(
      mpi.device, mpi.device, "mpiTimeout", ANARI_FLOAT32, &negative);
  check(oneErrorMentioning(status, {"mpiTimeout", "0 or more"}),
      "a negative mpiTimeout is reported");
  anariSetParameter(mpi.device, mpi.device, "mpiTimeout", ANARI_STRING, "5");
  check(oneErrorMentioning(status, {"mpiTimeout", "STRING"}),
      "an mpiTimeout that is no number is reported");

  ANARIFrame frame = anariNewFrame(mpi.device);
  anariSetParameter(
      mpi.device, frame, "mpiCommunicator", ANARI_VOID_POINTER, nullptr);
  check(oneErrorMentioning(status, {"mpiCommunicator", "NULL"}),
      "a NULL mpiCommunicator is reported");
  MPI_Comm comm = MPI_COMM_WORLD;
  anariSetParameter(mpi.device, frame, "mpiCommunicator", ANARI_INT32, &comm);
  check(oneErrorMentioning(status, {"mpiCommunicator", "INT32"}),
      "an mpiCommunicator of another type is reported");
  anariRelease(mpi.device, frame);

  const int32_t negativeThreads = -2;
  anariSetParameter(
      mpi.device, mpi.device, "numThreads", ANARI_INT32, &negativeThreads);
  check(oneErrorMentioning(status, {"numThreads", "-2"}),
      "a negative numThreads is reported");
  // Counts past the machine's limit never reach TBB (2^30 crashed it).
  const int32_t tooManyThreads = 1 << 30;
  anariSetParameter(
      mpi.device, mpi.device, "numThreads", ANARI_INT32, &tooManyThreads);
  check(oneErrorMentioning(status, {"numThreads", "1073741824", "limit"}),
      "numThreads 2^30 is refused, naming the limit");
  const uint32_t millionThreads = 1000000;
  anariSetParameter(
      mpi.device, mpi.device, "numThreads", ANARI_UINT32, &millionThreads);
  check(oneErrorMentioning(status, {"numThreads", "1000000", "limit"}),
      "numThreads 10^6 is refused, naming the limit");
  const uint32_t wrapsNegative = 0x80000000u;
  anariSetParameter(
      mpi.device, mpi.device, "numThreads", ANARI_UINT32, &wrapsNegative);
  check(oneErrorMentioning(status, {"numThreads", "2147483648"}),
      "a UINT32 numThreads of 2^31 is read as unsigned and refused");
  // One thread per process from here on (the image must not change).
  const int32_t oneThread = 1;
  anariSetParameter(
      mpi.device, mpi.device, "numThreads", ANARI_INT32, &oneThread);

  // The device still renders correctly after all that.
  const std::vector<int> owners = boxOwners(1, 5);
  const Render render =
      renderBoxes(mpi.device, boxesOf(owners, 0), kEyeB, "raycast", &comm);
  checkComposite(render, owners, kEyeB, "after bad parameters");
  check(status.take().empty(), "rendering reports nothing");

  // A denoising renderer: rank 0's assembled image is not denoised, which
  // is said once per frame.
  ANARIWorld world = newBoxesWorld(mpi.device, boxesOf(owners, 0));
  ANARICamera camera = newCamera(mpi.device, kEyeA, 1.f);
  ANARIRenderer renderer = newRenderer(mpi.device, "raycast");
  const bool denoise = true;
  anariSetParameter(mpi.device, renderer, "denoise", ANARI_BOOL, &denoise);
  anariCommitParameters(mpi.device, renderer);
  ANARIFrame denoised =
      newFrame(mpi.device, world, camera, renderer, kSize, kSize);
  for (int i = 0; i < 2; i++) {
    anariRenderFrame(mpi.device, denoised);
    anariFrameReady(mpi.device, denoised, ANARI_WAIT);
  }
  const std::vector<std::string> warnings = status.take(ANARI_SEVERITY_WARNING);
  check(
      warnings.size() == 1
          && warnings[0].find("'denoise' is not applied") != std::string::npos,
      "a denoising renderer is warned about once");
  anariRelease(mpi.device, denoised);
  anariRelease(mpi.device, renderer);
  anariRelease(mpi.device, camera);
  anariRelease(mpi.device, world);
}

} // namespace

// A square of half size `half` at height z, normal up (+z) or down, of a
// matte `grey` (black, two-sided or see-through as asked).
ANARISurface newSquare(ANARIDevice device,
    float half,
    float z,
    bool up,
    float grey,
    bool doubleSided,
    float opacity = 1.f)
{
  float corners[4][3] = {
      {-half, -half, z}, {half, -half, z}, {half, half, z}, {-half, half, z}};
  if (!up)
    std::swap(corners[1], corners[3]);
  ANARIGeometry geometry = newQuad(device, corners);
  ANARIMaterial material = anariNewMaterial(device, "matte");
  const float color[3] = {grey, grey, grey};
  const uint8_t sided = doubleSided;
  anariSetParameter(device, material, "color", ANARI_FLOAT32_VEC3, color);
  anariSetParameter(device, material, "doubleSided", ANARI_BOOL, &sided);
  if (opacity < 1.f) {
    anariSetParameter(device, material, "opacity", ANARI_FLOAT32, &opacity);
    anariSetParameter(device, material, "alphaMode", ANARI_STRING, "blend");
  }
  anariCommitParameters(device, material);
  ANARISurface surface = anariNewSurface(device);
  anariSetParameter(device, surface, "geometry", ANARI_GEOMETRY, &geometry);
  anariSetParameter(device, surface, "material", ANARI_MATERIAL, &material);
  anariCommitParameters(device, surface);
  anariRelease(device, geometry);
  anariRelease(device, material);
  return surface;
}

// Rank 0 holds a white receiver, over it a black single-sided occluder
// facing up and over that a black see-through sheet (opacity 0.5); a quad
// light above shines down on all, declared by every process. Light meets
// the occluder's front: the receiver under it is black. A bounce ray
// passes the occluder's back, then the sheet, and is carried on by the
// process that shaded the sheet; every process must still know it passed
// the occluder, or the light it finds counts (the shadow was lit from two
// processes on when only that process knew).
void scenarioSheetOverSingleSided()
{
  const int rank = worldRank();
  Status status;
  float brightest = -1.f;
  {
    Device mpi("prism_mpi", status);
    if (!mpi.device)
      return;
    ANARIDevice d = mpi.device;
    ANARIWorld world = anariNewWorld(d);
    if (rank == 0) {
      ANARISurface surfaces[3] = {newSquare(d, 20.f, 0.f, true, 0.6f, true),
          newSquare(d, 3.f, 1.f, true, 0.f, false),
          newSquare(d, 3.f, 1.5f, true, 0.f, true, 0.5f)};
      ANARIArray1D array =
          anariNewArray1D(d, surfaces, nullptr, nullptr, ANARI_SURFACE, 3);
      anariSetParameter(d, world, "surface", ANARI_ARRAY1D, &array);
      anariRelease(d, array);
      for (ANARISurface surface : surfaces)
        anariRelease(d, surface);
    }
    ANARILight light = anariNewLight(d, "quad");
    const float position[3] = {-2.f, -2.f, 2.f}, edge1[3] = {4, 0, 0},
                edge2[3] = {0, 4, 0}, intensity = 5.f;
    anariSetParameter(d, light, "position", ANARI_FLOAT32_VEC3, position);
    anariSetParameter(d, light, "edge1", ANARI_FLOAT32_VEC3, edge1);
    anariSetParameter(d, light, "edge2", ANARI_FLOAT32_VEC3, edge2);
    anariSetParameter(d, light, "intensity", ANARI_FLOAT32, &intensity);
    anariCommitParameters(d, light);
    setWorldObjects(d, world, "light", ANARI_LIGHT, light);
    anariRelease(d, light);
    // Straight down from under the occluder, on the receiver only.
    ANARICamera camera = anariNewCamera(d, "orthographic");
    const float eye[3] = {0.f, 0.f, 0.5f}, down[3] = {0.f, 0.f, -1.f},
                up[3] = {0.f, 1.f, 0.f}, height = 0.5f;
    anariSetParameter(d, camera, "position", ANARI_FLOAT32_VEC3, eye);
    anariSetParameter(d, camera, "direction", ANARI_FLOAT32_VEC3, down);
    anariSetParameter(d, camera, "up", ANARI_FLOAT32_VEC3, up);
    anariSetParameter(d, camera, "height", ANARI_FLOAT32, &height);
    anariCommitParameters(d, camera);
    ANARIRenderer renderer = anariNewRenderer(d, "pathtracer");
    const int32_t vertices = 4, samples = 64;
    anariSetParameter(d, renderer, "maxPathLength", ANARI_INT32, &vertices);
    anariSetParameter(d, renderer, "pixelSamples", ANARI_INT32, &samples);
    anariCommitParameters(d, renderer);
    ANARIFrame frame = newFrame(d, world, camera, renderer, 16, 16);
    anariRenderFrame(d, frame);
    anariFrameReady(d, frame, ANARI_WAIT);
    const Image image = readFrame(d, frame);
    for (size_t i = 0; i < image.color.size(); i++)
      if (i % 4 != 3)
        brightest = std::max(brightest, image.color[i]);
    for (ANARIObject o : {(ANARIObject)frame,
             (ANARIObject)renderer,
             (ANARIObject)camera,
             (ANARIObject)world})
      anariRelease(d, o);
  }
  for (const std::string &e : status.take())
    check(false, "sheet over single-sided: unexpected error: " + e);
  if (rank != 0)
    return;
  std::printf("sheet over single-sided: brightest %g\n", brightest);
  check(brightest == 0.f,
      "sheet over single-sided: the shadow is black (brightest "
          + std::to_string(brightest) + ")");
}

int main(int argc, char **argv)
{
  // The application initialises MPI here; the device must leave it be.
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &g_worldRank);
  const std::string scenario = argc > 1 ? argv[1] : "";
  if (scenario == "composite")
    scenarioComposite();
  else if (scenario == "pathtracer")
    scenarioPathTracer();
  else if (scenario == "pathtracer-subcommunicator")
    scenarioPathTracerSubcommunicator();
  else if (scenario == "subcommunicator")
    scenarioSubcommunicator();
  else if (scenario == "emissive")
    scenarioEmissive();
  else if (scenario == "lights")
    scenarioLights();
  else if (scenario == "accumulation-restart")
    scenarioAccumulationRestart();
  else if (scenario == "adaptive-replicated")
    scenarioAdaptiveReplicated();
  else if (scenario == "mismatch")
    scenarioMismatch();
  else if (scenario == "absent")
    scenarioAbsent();
  else if (scenario == "parameters")
    scenarioParameters();
  else if (scenario == "wrapped")
    scenarioWrapped();
  else if (scenario == "wrapped-errors")
    scenarioWrappedErrors();
  else if (scenario == "wrapped-environment")
    scenarioWrappedEnvironment();
  else if (scenario == "sheet-over-single-sided")
    scenarioSheetOverSingleSided();
  else
    check(false, "unknown scenario '" + scenario + "'");
  int failures = g_failures, total = 0;
  MPI_Allreduce(&failures, &total, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  MPI_Finalize();
  if (g_worldRank == 0)
    std::printf("%s: %d failure(s) over all ranks\n", scenario.c_str(), total);
  return total == 0 ? 0 : 1;
}
