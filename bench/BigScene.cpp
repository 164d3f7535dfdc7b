// prism-bench-big-scene: memory and start-up on big generated scenes, prism
// against raw Embree on the same data in the same run. For 4M triangles
// (a rippled grid), 4M spheres (a random cloud), 1M round curve segments
// (a field of hairs) and, with --instances, 10M instances of 100 meshes
// (as instance transform arrays), each side runs in a child process of
// its own (peak RSS is per process): it makes the data in its own memory,
// hands it over (prism: shared arrays; Embree: shared geometry buffers),
// builds and traces one 256x256 frame of camera rays. Spheres and curves
// reach prism in Embree's xyzr layout (vertex.positionRadius,
// PRISM_GEOMETRY_POSITION_RADIUS) unless --layout apart gives them as
// ANARI's positions and radii, which prism converts. Printed per side:
// peak RSS per primitive (data included) and above the process's start
// (library and device loaded), Embree's bytes from its memory monitor
// (prism: the world's prism.embreePeakBytes), and the time to first pixel
// (handing the data over to the frame being ready). Never a test.
#include <anari/anari.h>
#include <embree3/rtcore.h>
#include <tbb/parallel_for.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;
constexpr uint32_t kFrameSize = 256;

double secondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}
double peakRssBytes()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) * 1024.0; // kilobytes on Linux
}

// The data both sides read: what an application would hand over.
struct SceneData
{
  std::string kind;
  size_t primitives{0};
  size_t vertices{0};
  std::vector<float> positions; // xyz (triangles, spheres), xyzr (curves)
  std::vector<uint32_t> indices;
  std::vector<float> radii; // curves for prism: per vertex
  float radius{0.f};
  bool packed{false}; // spheres and curves: xyzr, vertex.positionRadius
  // Instances: 100 small meshes (positions + indices above, 1 per mesh
  // range) and per mesh a transform array.
  size_t meshes{0};
  size_t trianglesPerMesh{0};
  std::vector<float> transforms; // 12 floats (3x4, column-major) each
};

// An n x n grid of quads (2 n^2 triangles) over [0, 1]^2, rippled in z.
void makeTriangles(SceneData &data, size_t triangles)
{
  const size_t n = size_t(std::sqrt(double(triangles) / 2.0));
  const size_t m = n + 1;
  // One spare vertex: Embree reads 4 bytes past the last.
  data.positions.resize(3 * (m * m + 1));
  for (size_t y = 0; y < m; y++)
    for (size_t x = 0; x < m; x++) {
      float *p = &data.positions[3 * (y * m + x)];
      p[0] = float(x) / float(n);
      p[1] = float(y) / float(n);
      p[2] = 0.02f * std::sin(40.f * p[0]) * std::cos(37.f * p[1]);
    }
  data.indices.resize(6 * n * n);
  for (size_t y = 0; y < n; y++)
    for (size_t x = 0; x < n; x++) {
      const uint32_t a = uint32_t(y * m + x), b = a + 1, c = uint32_t(a + m),
                     d = c + 1;
      uint32_t *t = &data.indices[6 * (y * n + x)];
      t[0] = a, t[1] = b, t[2] = d, t[3] = a, t[4] = d, t[5] = c;
    }
  data.primitives = 2 * n * n;
  data.vertices = m * m;
}

// Spheres at random in [0, 1]^3 (a fixed sequence), one radius.
void makeSpheres(SceneData &data, size_t count, bool withRadius)
{
  const size_t stride = withRadius ? 4 : 3;
  data.positions.resize(stride * count + 4);
  uint64_t state = 0x9e3779b97f4a7c15ull;
  auto next = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return float(state >> 40) / float(1 << 24);
  };
  data.radius = 0.5f / std::cbrt(float(count));
  for (size_t i = 0; i < count; i++) {
    float *p = &data.positions[stride * i];
    p[0] = next(), p[1] = next(), p[2] = next();
    if (withRadius)
      p[3] = data.radius;
  }
  data.primitives = count;
  data.vertices = count;
}

// Hairs of 100 round linear segments each standing on [0, 1]^2, xyzr per
// vertex for Embree, xyz and r apart for ANARI; index i starts the segment
// from vertex i to i + 1.
void makeCurves(SceneData &data, size_t segments, bool forEmbree)
{
  constexpr size_t kPerHair = 100;
  const size_t hairs = std::max<size_t>(1, segments / kPerHair);
  const size_t side = size_t(std::ceil(std::sqrt(double(hairs))));
  data.positions.resize(4 * (hairs * (kPerHair + 1) + 1));
  data.indices.clear();
  data.indices.reserve(hairs * kPerHair);
  for (size_t h = 0; h < hairs; h++) {
    const float x = (float(h % side) + 0.5f) / float(side);
    const float y = (float(h / side) + 0.5f) / float(side);
    const uint32_t first = uint32_t(h * (kPerHair + 1));
    for (size_t v = 0; v <= kPerHair; v++) {
      const float t = float(v) / float(kPerHair);
      float *p = &data.positions[4 * (first + v)];
      p[0] = x + 0.02f * std::sin(7.f * t + float(h));
      p[1] = y + 0.02f * std::cos(5.f * t + float(h));
      p[2] = 0.3f * t;
      p[3] = 0.2f / float(side) * (1.f - 0.8f * t);
      if (v < kPerHair)
        data.indices.push_back(first + uint32_t(v));
    }
  }
  data.primitives = hairs * kPerHair;
  data.vertices = hairs * (kPerHair + 1);
  if (forEmbree)
    return;
  const size_t vertices = data.vertices;
  data.radii.resize(vertices);
  for (size_t v = 0; v < vertices; v++) {
    data.radii[v] = data.positions[4 * v + 3];
    std::memmove(&data.positions[3 * v], &data.positions[4 * v], 12);
  }
  data.positions.resize(3 * vertices + 1);
  data.positions.shrink_to_fit();
}

// 100 small grids (the first `trianglesPerMesh` of a triangle grid each,
// one shared vertex array) and `instances` transforms spread over them:
// translations on a square lattice, scaled to its cell.
void makeInstances(SceneData &data,
    size_t instances,
    bool forEmbree,
    size_t trianglesPerMesh = 128)
{
  makeTriangles(data, trianglesPerMesh);
  data.meshes = 100;
  data.trianglesPerMesh = data.indices.size() / 3;
  const size_t side = size_t(std::ceil(std::sqrt(double(instances))));
  const float cell = 1.f / float(side);
  // Column-major 3x4 for Embree, 4x4 (FLOAT32_MAT4) for ANARI.
  const size_t floats = forEmbree ? 12 : 16;
  data.transforms.resize(floats * instances);
  for (size_t i = 0; i < instances; i++) {
    float *m = &data.transforms[floats * i];
    const float s = 0.8f * cell;
    const float x = float(i % side) * cell, y = float(i / side) * cell;
    if (forEmbree) {
      const float t[12] = {s, 0, 0, 0, s, 0, 0, 0, s, x, y, 0.f};
      std::memcpy(m, t, sizeof(t));
    } else {
      const float t[16] = {s, 0, 0, 0, 0, s, 0, 0, 0, 0, s, 0, x, y, 0, 1};
      std::memcpy(m, t, sizeof(t));
    }
  }
  data.primitives = instances;
}

// `forEmbree`: Embree's layouts; `packed`: prism given spheres and curves
// in Embree's xyzr layout too.
SceneData makeData(
    const std::string &kind, double scale, bool forEmbree, bool packed = false)
{
  SceneData data;
  data.kind = kind;
  data.packed = packed && !forEmbree && (kind == "spheres" || kind == "curves");
  forEmbree = forEmbree || data.packed;
  auto count = [&](double n) {
    return size_t(std::max(1.0, n * scale));
  };
  if (kind == "triangles")
    makeTriangles(data, count(4e6));
  else if (kind == "spheres")
    makeSpheres(data, count(4e6), forEmbree);
  else if (kind == "curves")
    makeCurves(data, count(1e6), forEmbree);
  else
    makeInstances(data, count(1e7), forEmbree);
  return data;
}

struct Figures
{
  double primitives{0}, peakRss{0}, startRss{0}, embreeBytes{0}, firstPixel{0};
  bool ok{false};
};

// Camera rays over [0, 1]^2 from above (orthographic, straight down).
void traceFrame(RTCScene scene, std::atomic<uint64_t> &hits)
{
  tbb::parallel_for(uint32_t(0), kFrameSize, [&](uint32_t row) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    uint64_t found = 0;
    for (uint32_t column = 0; column < kFrameSize; column++) {
      RTCRayHit r{};
      r.ray.org_x = (float(column) + 0.5f) / float(kFrameSize);
      r.ray.org_y = (float(row) + 0.5f) / float(kFrameSize);
      r.ray.org_z = 2.f;
      r.ray.dir_z = -1.f;
      r.ray.tfar = 1e30f;
      r.ray.mask = ~0u;
      r.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(scene, &context, &r);
      found += r.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    }
    hits += found;
  });
}

// Raw Embree ///////////////////////////////////////////////////////////////

std::atomic<int64_t> g_embreeBytes{0}, g_embreePeak{0};

bool countEmbreeBytes(void *, ssize_t bytes, bool)
{
  const int64_t now = g_embreeBytes += int64_t(bytes);
  int64_t peak = g_embreePeak.load();
  while (now > peak && !g_embreePeak.compare_exchange_weak(peak, now)) {
  }
  return true;
}

RTCGeometry embreeGeometry(RTCDevice device, const SceneData &data)
{
  const bool spheres = data.kind == "spheres";
  const bool curves = data.kind == "curves";
  RTCGeometry g = rtcNewGeometry(device,
      spheres  ? RTC_GEOMETRY_TYPE_SPHERE_POINT
      : curves ? RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE
               : RTC_GEOMETRY_TYPE_TRIANGLE);
  const size_t stride = spheres || curves ? 16 : 12;
  const size_t vertices = data.vertices;
  rtcSetSharedGeometryBuffer(g,
      RTC_BUFFER_TYPE_VERTEX,
      0,
      spheres || curves ? RTC_FORMAT_FLOAT4 : RTC_FORMAT_FLOAT3,
      data.positions.data(),
      0,
      stride,
      vertices);
  if (!spheres) {
    const bool triangles = !curves;
    rtcSetSharedGeometryBuffer(g,
        RTC_BUFFER_TYPE_INDEX,
        0,
        triangles ? RTC_FORMAT_UINT3 : RTC_FORMAT_UINT,
        data.indices.data(),
        0,
        triangles ? 12 : 4,
        triangles ? data.indices.size() / 3 : data.indices.size());
  }
  rtcCommitGeometry(g);
  return g;
}

// 100 scenes of one mesh each, instanced by every transform in turn.
void addEmbreeInstances(RTCDevice device,
    RTCScene scene,
    const SceneData &data,
    RTCBuildQuality quality)
{
  std::vector<RTCScene> meshes(data.meshes);
  for (RTCScene &mesh : meshes) {
    mesh = rtcNewScene(device);
    rtcSetSceneBuildQuality(mesh, quality);
    RTCGeometry g = embreeGeometry(device, data);
    rtcAttachGeometry(mesh, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(mesh);
  }
  for (size_t i = 0; i < data.primitives; i++) {
    RTCGeometry instance = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(instance, meshes[i % meshes.size()]);
    rtcSetGeometryTransform(instance,
        0,
        RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR,
        &data.transforms[12 * i]);
    rtcCommitGeometry(instance);
    rtcAttachGeometry(scene, instance);
    rtcReleaseGeometry(instance);
  }
  for (RTCScene mesh : meshes)
    rtcReleaseScene(mesh); // the instances hold them
}

Figures runEmbree(
    const std::string &kind, double scale, RTCBuildQuality quality)
{
  Figures figures;
  RTCDevice device = rtcNewDevice(nullptr);
  rtcSetDeviceMemoryMonitorFunction(device, countEmbreeBytes, nullptr);
  figures.startRss = peakRssBytes();
  const SceneData data = makeData(kind, scale, true);
  figures.primitives = double(data.primitives);
  const auto start = Clock::now();
  RTCScene scene = rtcNewScene(device);
  // The flags prism sets (watertight rays through quads' diagonals).
  rtcSetSceneBuildQuality(scene, quality);
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  if (kind == "instances") {
    addEmbreeInstances(device, scene, data, quality);
  } else {
    RTCGeometry g = embreeGeometry(device, data);
    rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
  }
  rtcCommitScene(scene);
  std::atomic<uint64_t> hits{0};
  traceFrame(scene, hits);
  figures.firstPixel = secondsSince(start);
  figures.peakRss = peakRssBytes();
  figures.embreeBytes = double(g_embreePeak.load());
  figures.ok = hits > 0;
  rtcReleaseScene(scene);
  rtcReleaseDevice(device);
  return figures;
}

// Prism //////////////////////////////////////////////////////////////////

class PrismSide
{
 public:
  explicit PrismSide(const char *quality)
  {
    m_library = anariLoadLibrary("prism", nullptr, nullptr);
    if (!m_library)
      return;
    m_device = anariNewDevice(m_library, "default");
    if (quality) {
      anariSetParameter(
          m_device, m_device, "bvhQuality", ANARI_STRING, quality);
      anariCommitParameters(m_device, m_device);
    }
  }
  ~PrismSide()
  {
    // The device takes every object with it: releasing the shared arrays
    // one by one first would have it copy them (they are still in use).
    if (m_device)
      anariRelease(m_device, m_device);
    if (m_library)
      anariUnloadLibrary(m_library);
  }
  bool ok() const
  {
    return m_device != nullptr;
  }

  // The application's memory as a shared array (no deleter: it stays the
  // application's).
  ANARIArray1D shared(const void *memory, ANARIDataType type, size_t count)
  {
    return anariNewArray1D(m_device, memory, nullptr, nullptr, type, count);
  }
  // A managed array of object handles (it takes references of its own).
  ANARIArray1D objectArray(
      const void *handles, ANARIDataType type, size_t count)
  {
    ANARIArray1D a =
        anariNewArray1D(m_device, nullptr, nullptr, nullptr, type, count);
    std::memcpy(
        anariMapArray(m_device, a), handles, count * sizeof(ANARIObject));
    anariUnmapArray(m_device, a);
    return a;
  }
  // Sets `name` to `array`, which the application keeps until the end:
  // releasing a shared array the device still uses makes it copy the data
  // (the application may free its memory then), which an application
  // avoiding copies does not do.
  void setArray(ANARIObject object, const char *name, ANARIArray1D array)
  {
    anariSetParameter(m_device, object, name, ANARI_ARRAY1D, &array);
  }
  ANARIGeometry geometry(const SceneData &data)
  {
    const char *subtype = data.kind == "spheres"  ? "sphere"
                          : data.kind == "curves" ? "curve"
                                                  : "triangle";
    ANARIGeometry g = anariNewGeometry(m_device, subtype);
    const size_t vertices = data.vertices;
    if (data.packed) {
      setArray(g,
          "vertex.positionRadius",
          shared(data.positions.data(), ANARI_FLOAT32_VEC4, vertices));
    } else {
      setArray(g,
          "vertex.position",
          shared(data.positions.data(), ANARI_FLOAT32_VEC3, vertices));
    }
    if (data.kind == "spheres" && !data.packed)
      anariSetParameter(m_device, g, "radius", ANARI_FLOAT32, &data.radius);
    if (data.kind == "curves") {
      if (!data.packed)
        setArray(g,
            "vertex.radius",
            shared(data.radii.data(), ANARI_FLOAT32, vertices));
      setArray(g,
          "primitive.index",
          shared(data.indices.data(), ANARI_UINT32, data.indices.size()));
    } else if (!data.indices.empty()) {
      setArray(g,
          "primitive.index",
          shared(
              data.indices.data(), ANARI_UINT32_VEC3, data.indices.size() / 3));
    }
    anariCommitParameters(m_device, g);
    return g;
  }
  ANARISurface surface(const SceneData &data)
  {
    ANARISurface s = anariNewSurface(m_device);
    ANARIGeometry g = geometry(data);
    ANARIMaterial m = anariNewMaterial(m_device, "matte");
    anariCommitParameters(m_device, m);
    anariSetParameter(m_device, s, "geometry", ANARI_GEOMETRY, &g);
    anariSetParameter(m_device, s, "material", ANARI_MATERIAL, &m);
    anariCommitParameters(m_device, s);
    anariRelease(m_device, g);
    anariRelease(m_device, m);
    return s;
  }
  // One instance per mesh holding its share of the transforms (a
  // transform array, KHR_INSTANCE_TRANSFORM_ARRAY).
  ANARIArray1D instances(const SceneData &data)
  {
    std::vector<ANARIInstance> placed;
    const size_t perMesh = data.primitives / data.meshes;
    for (size_t mesh = 0; mesh < data.meshes; mesh++) {
      ANARISurface s = surface(data);
      ANARIGroup group = anariNewGroup(m_device);
      setArray(group, "surface", objectArray(&s, ANARI_SURFACE, 1));
      anariCommitParameters(m_device, group);
      anariRelease(m_device, s);
      ANARIInstance instance = anariNewInstance(m_device, "transform");
      anariSetParameter(m_device, instance, "group", ANARI_GROUP, &group);
      anariRelease(m_device, group);
      const size_t first = mesh * perMesh;
      const size_t count =
          mesh + 1 == data.meshes ? data.primitives - first : perMesh;
      ANARIArray1D transforms =
          shared(&data.transforms[16 * first], ANARI_FLOAT32_MAT4, count);
      if (mesh == 0) // kept for the edit benchmark
        m_firstTransforms = transforms;
      setArray(instance, "transform", transforms);
      anariCommitParameters(m_device, instance);
      placed.push_back(instance);
    }
    ANARIArray1D array =
        objectArray(placed.data(), ANARI_INSTANCE, placed.size());
    for (ANARIInstance instance : placed)
      anariRelease(m_device, instance);
    return array;
  }
  ANARIWorld world(const SceneData &data)
  {
    ANARIWorld w = anariNewWorld(m_device);
    if (data.kind == "instances") {
      setArray(w, "instance", instances(data));
    } else {
      ANARISurface s = surface(data);
      setArray(w, "surface", objectArray(&s, ANARI_SURFACE, 1));
      anariRelease(m_device, s);
    }
    anariCommitParameters(m_device, w);
    return w;
  }
  // One raycast frame looking straight down on [0, 1]^2; the world's
  // Embree peak bytes out.
  bool renderFrame(ANARIWorld w, double &embreeBytes)
  {
    auto set = [&](ANARIObject o,
                   const char *name,
                   ANARIDataType type,
                   const void *value) {
      anariSetParameter(m_device, o, name, type, value);
    };
    const float position[3] = {0.5f, 0.5f, 2.f}, direction[3] = {0, 0, -1},
                up[3] = {0, 1, 0}, height = 1.f, aspect = 1.f;
    const uint32_t size[2] = {kFrameSize, kFrameSize};
    const ANARIDataType color = ANARI_UFIXED8_RGBA_SRGB;
    ANARICamera camera = anariNewCamera(m_device, "orthographic");
    ANARIRenderer renderer = anariNewRenderer(m_device, "raycast");
    ANARIFrame frame = anariNewFrame(m_device);
    for (const auto &[name, value] : {std::pair{"position", position},
             std::pair{"direction", direction},
             std::pair{"up", up}})
      set(camera, name, ANARI_FLOAT32_VEC3, value);
    set(camera, "height", ANARI_FLOAT32, &height);
    set(camera, "aspect", ANARI_FLOAT32, &aspect);
    set(frame, "world", ANARI_WORLD, &w);
    set(frame, "camera", ANARI_CAMERA, &camera);
    set(frame, "renderer", ANARI_RENDERER, &renderer);
    set(frame, "size", ANARI_UINT32_VEC2, size);
    set(frame, "channel.color", ANARI_DATA_TYPE, &color);
    for (ANARIObject o :
        {(ANARIObject)camera, (ANARIObject)renderer, (ANARIObject)frame})
      anariCommitParameters(m_device, o);
    anariRenderFrame(m_device, frame);
    anariFrameReady(m_device, frame, ANARI_WAIT);
    uint64_t bytes = 0;
    const bool known = anariGetProperty(m_device,
        w,
        "prism.embreePeakBytes",
        ANARI_UINT64,
        &bytes,
        sizeof(bytes),
        ANARI_WAIT);
    embreeBytes = double(bytes);
    for (ANARIObject o :
        {(ANARIObject)frame, (ANARIObject)renderer, (ANARIObject)camera})
      anariRelease(m_device, o);
    return known;
  }

  // Moves the first instance a little, as an application edits one
  // transform in place (map, write, unmap).
  void moveFirstInstance()
  {
    auto *matrix = (float *)anariMapArray(m_device, m_firstTransforms);
    matrix[12] += 1e-3f; // x of the translation column
    anariUnmapArray(m_device, m_firstTransforms);
  }

 private:
  ANARILibrary m_library{nullptr};
  ANARIDevice m_device{nullptr};
  ANARIArray1D m_firstTransforms{nullptr};
};

Figures runPrism(
    const std::string &kind, double scale, const char *quality, bool packed)
{
  Figures figures;
  SceneData data; // the application's memory outlives the device
  PrismSide prism(quality);
  if (!prism.ok())
    return figures;
  figures.startRss = peakRssBytes();
  data = makeData(kind, scale, false, packed);
  figures.primitives = double(data.primitives);
  const auto start = Clock::now();
  ANARIWorld w = prism.world(data);
  figures.ok = prism.renderFrame(w, figures.embreeBytes);
  figures.firstPixel = secondsSince(start);
  figures.peakRss = peakRssBytes();
  return figures;
}

// One transform changed in a world of instances: the time to the next
// frame (the instance and the top-level BVH rebuilt, no group's) against
// the first frame's (every BVH built).
void runEdit(double scale)
{
  SceneData data; // the application's memory outlives the device
  PrismSide prism(nullptr);
  if (!prism.ok())
    return;
  // Meshes of 20k triangles (2M in all): rebuilding the groups would cost
  // as much as the top level, as in production scenes.
  data.kind = "instances";
  makeInstances(data, size_t(std::max(1.0, 1e7 * scale)), false, 20000);
  double bytes = 0;
  auto start = Clock::now();
  ANARIWorld w = prism.world(data);
  prism.renderFrame(w, bytes);
  const double full = secondsSince(start);
  start = Clock::now();
  prism.renderFrame(w, bytes);
  const double unchanged = secondsSince(start);
  std::vector<double> edits;
  for (int run = 0; run < 5; run++) {
    start = Clock::now();
    prism.moveFirstInstance();
    prism.renderFrame(w, bytes);
    edits.push_back(secondsSince(start));
  }
  std::sort(edits.begin(), edits.end());
  std::printf(
      "edit: %zu instances of %zu meshes of %zu triangles (transform "
      "arrays)\n"
      "  first frame (everything built) %.3f s, a frame with no "
      "change %.3f s,\n  one transform moved %.3f s (median of 5): "
      "%.1fx faster than building everything\n",
      data.primitives,
      data.meshes,
      data.trianglesPerMesh,
      full,
      unchanged,
      edits[2],
      full / edits[2]);
  std::fflush(stdout); // the child leaves through _exit
}

// Driver ///////////////////////////////////////////////////////////////////

// Runs `side` in a child process and reads its figures back through a pipe.
template <typename Side>
Figures inChild(Side &&side)
{
  int channel[2];
  Figures figures;
  if (pipe(channel) != 0)
    return figures;
  std::fflush(stdout);
  const pid_t child = fork();
  if (child == 0) {
    close(channel[0]);
    const Figures result = side();
    const ssize_t written = write(channel[1], &result, sizeof(result));
    _exit(written == ssize_t(sizeof(result)) ? 0 : 1);
  }
  close(channel[1]);
  if (child > 0) {
    if (read(channel[0], &figures, sizeof(figures)) != ssize_t(sizeof(figures)))
      figures = Figures{};
    int status = 0;
    waitpid(child, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
      std::fprintf(stderr,
          "a measuring process failed (%s %d)\n",
          WIFSIGNALED(status) ? "signal" : "exit status",
          WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status));
  }
  close(channel[0]);
  return figures;
}

void print(const char *side, const Figures &f, double primitives)
{
  std::printf(
      "  %-7s peak RSS %7.1f B/prim (%7.1f above start), Embree "
      "%6.1f B/prim, first pixel %6.2f s%s\n",
      side,
      f.peakRss / primitives,
      (f.peakRss - f.startRss) / primitives,
      f.embreeBytes / primitives,
      f.firstPixel,
      f.ok ? "" : "  (FAILED: nothing hit or no figures)");
}

} // namespace

int main(int argc, char **argv)
{
  double scale = 1.0;
  std::vector<std::string> kinds = {"triangles", "spheres", "curves"};
  const char *quality = nullptr; // prism's default; Embree: medium
  RTCBuildQuality embreeQuality = RTC_BUILD_QUALITY_MEDIUM;
  bool edit = false;
  bool packed = true;
  std::string sides = "both"; // or one of them alone, for a profiler
  for (int i = 1; i < argc; i++) {
    const std::string arg = argv[i];
    if (arg == "--quick") {
      scale = 0.05;
    } else if (arg == "--scale" && i + 1 < argc) {
      scale = std::atof(argv[++i]);
    } else if (arg == "--edit") {
      edit = true;
    } else if (arg == "--instances") {
      kinds.push_back("instances");
    } else if (arg == "--only" && i + 1 < argc) {
      kinds = {argv[++i]};
    } else if (arg == "--layout" && i + 1 < argc) {
      packed = std::string(argv[++i]) != "apart";
    } else if (arg == "--side" && i + 1 < argc
               && (std::string(argv[i + 1]) == "prism"
                   || std::string(argv[i + 1]) == "embree")) {
      sides = argv[++i];
    } else if (arg == "--quality" && i + 1 < argc) {
      quality = argv[++i];
      embreeQuality = std::string(quality) == "high" ? RTC_BUILD_QUALITY_HIGH
                      : std::string(quality) == "low"
                          ? RTC_BUILD_QUALITY_LOW
                          : RTC_BUILD_QUALITY_MEDIUM;
    } else {
      std::fprintf(stderr,
          "usage: prism-bench-big-scene [--quick | --scale F] [--instances] "
          "[--edit]\n"
          "  [--only triangles|spheres|curves|instances] [--quality "
          "low|medium|high]\n"
          "  [--layout packed|apart] [--side prism|embree]\n"
          "  peak RSS, Embree bytes and time to first pixel per primitive,\n"
          "  prism (shared arrays) against raw Embree on the same data;\n"
          "  --edit: one transform moved in a 1M-instance world\n");
      return 2;
    }
  }
  if (edit) {
    const Figures none = inChild([&] {
      runEdit(0.1 * scale); // 1M instances at scale 1
      return Figures{};
    });
    (void)none;
    return 0;
  }
  for (const std::string &kind : kinds) {
    const Figures prism = sides == "embree" ? Figures{} : inChild([&] {
      return runPrism(kind, scale, quality, packed);
    });
    const Figures embree = sides == "prism" ? Figures{} : inChild([&] {
      return runEmbree(kind, scale, embreeQuality);
    });
    const double primitives = std::max(prism.primitives, embree.primitives);
    std::printf("%s: %.0f%s\n",
        kind.c_str(),
        primitives,
        kind == "spheres" || kind == "curves" ? (
            packed ? " (prism given xyzr)" : " (prism given xyz and r apart)")
                                              : "");
    print("prism", prism, primitives);
    print("embree", embree, primitives);
    std::printf("  prism / embree: peak RSS %.2fx, first pixel %.2fx\n",
        prism.peakRss / embree.peakRss,
        prism.firstPixel / embree.firstPixel);
    std::fflush(stdout);
  }
  return 0;
}
