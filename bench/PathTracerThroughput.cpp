// Path-tracer throughput against raw Embree on the same room.
//
// The furnished room (scenes/FurnishedRoom.h) is rendered at 1920x1080 by
// prism's `pathtracer` through the public ANARI API: 16 accumulated frames
// (16 samples per pixel) a run, the renderer's "raysTraced" property (camera,
// bounce and shadow rays) read around every frame gives rays per second.
// In the same process raw Embree traces the room's triangles (one scene, the
// BVH quality and flags prism uses) with paths of the same maximum length:
// camera rays, then at every hit a cosine-distributed bounce and one shadow
// ray to a random point of the ceiling light, in streams of one 32x32 tile
// (1024 rays) per TBB task, with no shading, no Russian roulette and no
// image. The two alternate frame by frame (each of prism's accumulated
// frames is paired with one raw frame traced just before it), so both meet
// the same machine. Reported: both rays per second (medians of frames), the
// median of the pairs' ratios (the target is >= 65 %) and the time
// of a 16-spp image (the sum of its frames; median of runs).
//
// Raw Embree's paths always run to the full length, prism's end earlier
// (Russian roulette, dark surfaces): the table shows rays per pixel for
// both, since later bounces are the less coherent, slower rays.
//
// Run: build/bin/prism-bench-pathtracer [--quick] [--runs N] [--spp N]
//   [--size WxH] [--max-path-length N] [--prism-only] [--embree-only]
// Timing is never a test: this prints, it does not pass or fail.
#include "DemoScenes.h"
#include "FurnishedRoom.h"

#include <anari/anari.h>
#include <embree3/rtcore.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;
using namespace prism::scenes;

constexpr uint32_t kTileSize = 32; // 1024 rays per stream, as prism's tiles

struct Options
{
  uint32_t width{1920}, height{1080};
  int samplesPerPixel{16};
  int runs{3};           // 16-spp images timed (prism)
  int maxPathLength{8};  // the pathtracer renderer's default
  bool prismOnly{false}; // for profiling one side
  bool embreeOnly{false};
};

double seconds(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double median(std::vector<double> values)
{
  if (values.empty())
    return 0.0;
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

std::string cpuModel()
{
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) == 0) {
      const size_t colon = line.find(':');
      if (colon != std::string::npos)
        return line.substr(line.find_first_not_of(" \t", colon + 1));
    }
  }
  return "unknown CPU";
}

// A pinhole camera as ANARI's `perspective` one: direction, up, fovy and
// the image's aspect.
struct PinholeCamera
{
  Vec3 eye, forward, right, up;
  float halfHeight, halfWidth; // of the image plane at distance 1

  PinholeCamera(const SuggestedCamera &camera, uint32_t width, uint32_t height)
  {
    eye = camera.eye;
    forward = normalize(camera.at - camera.eye);
    right = normalize(cross(forward, camera.up));
    up = cross(right, forward);
    halfHeight =
        std::tan(0.5f * camera.fovyDegrees * std::numbers::pi_v<float> / 180.f);
    halfWidth = halfHeight * float(width) / float(height);
  }
  // The direction through image point (u, v) in [0, 1]^2, v up.
  Vec3 direction(float u, float v) const
  {
    return normalize(forward + right * ((2.f * u - 1.f) * halfWidth)
                     + up * ((2.f * v - 1.f) * halfHeight));
  }
};

// --- prism through ANARI -----------------------------------------------------

// One timed frame: its wall time and the rays traced in it.
struct FrameResult
{
  double seconds{0.0};
  uint64_t rays{0};
};

void statusToStderr(const void *,
    ANARIDevice,
    ANARIObject,
    ANARIDataType,
    ANARIStatusSeverity severity,
    ANARIStatusCode,
    const char *message)
{
  if (severity <= ANARI_SEVERITY_WARNING)
    std::fprintf(stderr, "prism: %s\n", message);
}

// Frames of the room from prism's `pathtracer` through the public API.
class PrismRoom
{
 public:
  PrismRoom(const Options &options, const SuggestedCamera &view)
  {
    m_library = anariLoadLibrary("prism", statusToStderr, nullptr);
    if (!m_library) {
      std::fprintf(stderr, "cannot load the prism ANARI library\n");
      std::exit(1);
    }
    ANARIDevice d = m_device = anariNewDevice(m_library, "default");
    Scene scene = buildFurnishedRoom(d);
    for (const std::string &note : scene.notes)
      std::fprintf(stderr, "note: %s\n", note.c_str());
    m_world = scene.world;
    m_lights = scene.lights;

    m_camera = anariNewCamera(d, "perspective");
    const Vec3 direction = normalize(view.at - view.eye);
    const float fovy = view.fovyDegrees * std::numbers::pi_v<float> / 180.f;
    const float aspect = float(options.width) / float(options.height);
    anariSetParameter(
        d, m_camera, "position", ANARI_FLOAT32_VEC3, view.eye.data());
    anariSetParameter(
        d, m_camera, "direction", ANARI_FLOAT32_VEC3, direction.data());
    anariSetParameter(d, m_camera, "up", ANARI_FLOAT32_VEC3, view.up.data());
    anariSetParameter(d, m_camera, "fovy", ANARI_FLOAT32, &fovy);
    anariSetParameter(d, m_camera, "aspect", ANARI_FLOAT32, &aspect);
    anariCommitParameters(d, m_camera);
    m_renderer = anariNewRenderer(d, "pathtracer");
    const int32_t maxPathLength = options.maxPathLength;
    anariSetParameter(
        d, m_renderer, "maxPathLength", ANARI_INT32, &maxPathLength);
    anariCommitParameters(d, m_renderer);
    m_frame = anariNewFrame(d);
    const uint32_t size[2] = {options.width, options.height};
    const ANARIDataType color = ANARI_UFIXED8_RGBA_SRGB;
    const bool accumulate = true;
    anariSetParameter(d, m_frame, "size", ANARI_UINT32_VEC2, size);
    anariSetParameter(d, m_frame, "channel.color", ANARI_DATA_TYPE, &color);
    anariSetParameter(d, m_frame, "accumulation", ANARI_BOOL, &accumulate);
    anariSetParameter(d, m_frame, "world", ANARI_WORLD, &m_world);
    anariSetParameter(d, m_frame, "camera", ANARI_CAMERA, &m_camera);
    anariSetParameter(d, m_frame, "renderer", ANARI_RENDERER, &m_renderer);
    anariCommitParameters(d, m_frame);
  }
  ~PrismRoom()
  {
    for (ANARIObject object : {(ANARIObject)m_frame,
             (ANARIObject)m_renderer,
             (ANARIObject)m_camera,
             (ANARIObject)m_world})
      anariRelease(m_device, object);
    for (ANARILight light : m_lights)
      anariRelease(m_device, light);
    anariRelease(m_device, m_device);
    anariUnloadLibrary(m_library);
  }
  PrismRoom(const PrismRoom &) = delete;
  PrismRoom &operator=(const PrismRoom &) = delete;

  // Committing the frame again restarts its accumulation.
  void restart()
  {
    anariCommitParameters(m_device, m_frame);
  }
  // Renders one accumulated frame: its time and the rays it traced.
  FrameResult render()
  {
    const uint64_t before = raysTraced();
    const auto start = Clock::now();
    anariRenderFrame(m_device, m_frame);
    anariFrameReady(m_device, m_frame, ANARI_WAIT);
    const double frameSeconds = seconds(start);
    return {frameSeconds, raysTraced() - before};
  }
  bool countsRays() const
  {
    return m_countsRays;
  }

 private:
  uint64_t raysTraced()
  {
    uint64_t rays = 0;
    m_countsRays = m_countsRays
                   && anariGetProperty(m_device,
                       m_renderer,
                       "raysTraced",
                       ANARI_UINT64,
                       &rays,
                       sizeof(rays),
                       ANARI_WAIT);
    return rays;
  }

  ANARILibrary m_library{nullptr};
  ANARIDevice m_device{nullptr};
  ANARIWorld m_world{nullptr};
  std::vector<ANARILight> m_lights; // the scene's, released with it
  ANARICamera m_camera{nullptr};
  ANARIRenderer m_renderer{nullptr};
  ANARIFrame m_frame{nullptr};
  bool m_countsRays{true};
};

// --- raw Embree
// ----------------------------------------------------------------

// All the room's triangles in one Embree scene, built as prism builds its
// scenes (rt/Scene.cpp): high quality, robust.
class RawScene
{
 public:
  explicit RawScene(const FurnishedRoom &room)
  {
    for (const RoomPart &part : room.parts) {
      const uint32_t first = uint32_t(m_positions.size());
      m_positions.insert(m_positions.end(),
          part.mesh.positions.begin(),
          part.mesh.positions.end());
      for (const auto &triangle : part.mesh.triangles)
        m_indices.push_back(
            {first + triangle[0], first + triangle[1], first + triangle[2]});
    }
    const size_t vertexCount = m_positions.size();
    m_positions.push_back({0.f, 0.f, 0.f}); // Embree reads 16-byte vertices

    m_device = rtcNewDevice(nullptr);
    m_scene = rtcNewScene(m_device);
    rtcSetSceneBuildQuality(m_scene, RTC_BUILD_QUALITY_HIGH);
    rtcSetSceneFlags(m_scene, RTC_SCENE_FLAG_ROBUST);
    RTCGeometry geometry = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(geometry,
        RTC_BUFFER_TYPE_VERTEX,
        0,
        RTC_FORMAT_FLOAT3,
        m_positions.data(),
        0,
        sizeof(Vec3),
        vertexCount);
    rtcSetSharedGeometryBuffer(geometry,
        RTC_BUFFER_TYPE_INDEX,
        0,
        RTC_FORMAT_UINT3,
        m_indices.data(),
        0,
        sizeof(m_indices[0]),
        m_indices.size());
    rtcSetGeometryBuildQuality(geometry, RTC_BUILD_QUALITY_HIGH);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(m_scene, geometry);
    rtcReleaseGeometry(geometry);
    const auto start = Clock::now();
    rtcCommitScene(m_scene);
    m_buildSeconds = seconds(start);
  }
  ~RawScene()
  {
    rtcReleaseScene(m_scene);
    rtcReleaseDevice(m_device);
  }
  RawScene(const RawScene &) = delete;
  RawScene &operator=(const RawScene &) = delete;

  RTCScene handle() const
  {
    return m_scene;
  }
  double buildSeconds() const
  {
    return m_buildSeconds;
  }

 private:
  std::vector<Vec3> m_positions;
  std::vector<std::array<uint32_t, 3>> m_indices;
  RTCDevice m_device{nullptr};
  RTCScene m_scene{nullptr};
  double m_buildSeconds{0.0};
};

// A direction around unit `normal`, cosine distributed.
Vec3 cosineDirection(const Vec3 &normal, float u1, float u2)
{
  const Vec3 helper =
      std::abs(normal[0]) > 0.9f ? Vec3{0.f, 1.f, 0.f} : Vec3{1.f, 0.f, 0.f};
  const Vec3 tangent = normalize(cross(helper, normal));
  const Vec3 bitangent = cross(normal, tangent);
  const float radius = std::sqrt(u1);
  const float angle = 2.f * std::numbers::pi_v<float> * u2;
  return normalize(tangent * (radius * std::cos(angle))
                   + bitangent * (radius * std::sin(angle))
                   + normal * std::sqrt(std::max(0.f, 1.f - u1)));
}

void setRay(RTCRay &ray, const Vec3 &origin, const Vec3 &direction, float tFar)
{
  ray.org_x = origin[0];
  ray.org_y = origin[1];
  ray.org_z = origin[2];
  ray.tnear = 0.f;
  ray.dir_x = direction[0];
  ray.dir_y = direction[1];
  ray.dir_z = direction[2];
  ray.time = 0.f;
  ray.tfar = tFar;
  ray.mask = ~0u;
  ray.id = 0;
  ray.flags = 0;
}

// One tile's streams, reused by each thread from tile to tile.
struct Streams
{
  std::vector<RTCRayHit> paths;
  std::vector<RTCRay> shadows;
};

// Traces one sample per pixel of the image as paths of up to
// `maxPathLength` closest-hit rays; returns how many rays it traced.
uint64_t traceRawFrame(const RawScene &scene,
    const PinholeCamera &camera,
    const CeilingLight &light,
    const Options &options,
    uint32_t frameIndex,
    tbb::enumerable_thread_specific<Streams> &threadStreams)
{
  const uint32_t tilesX = (options.width + kTileSize - 1) / kTileSize;
  const uint32_t tilesY = (options.height + kTileSize - 1) / kTileSize;
  const Vec3 lightNormal = cross(light.edge2, light.edge1); // its front
  std::atomic<uint64_t> total{0};
  tbb::parallel_for(uint32_t(0), tilesX * tilesY, [&](uint32_t tileIndex) {
    Streams &streams = threadStreams.local();
    Random random(uint64_t(frameIndex) * tilesX * tilesY + tileIndex);
    const uint32_t x0 = (tileIndex % tilesX) * kTileSize;
    const uint32_t y0 = (tileIndex / tilesX) * kTileSize;
    const uint32_t x1 = std::min(x0 + kTileSize, options.width);
    const uint32_t y1 = std::min(y0 + kTileSize, options.height);
    std::vector<RTCRayHit> &paths = streams.paths;
    std::vector<RTCRay> &shadows = streams.shadows;
    paths.resize(size_t(kTileSize) * kTileSize);
    shadows.resize(paths.size());
    size_t active = 0;
    for (uint32_t y = y0; y < y1; y++) {
      for (uint32_t x = x0; x < x1; x++) {
        const float u = (float(x) + random.uniform()) / float(options.width);
        const float v =
            1.f - (float(y) + random.uniform()) / float(options.height);
        RTCRayHit &path = paths[active++];
        setRay(path.ray, camera.eye, camera.direction(u, v), INFINITY);
        path.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        path.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
      }
    }
    uint64_t traced = 0;
    for (int bounce = 0; bounce < options.maxPathLength && active > 0;
         bounce++) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      context.flags = bounce == 0 ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT
                                  : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
      rtcIntersect1M(scene.handle(),
          &context,
          paths.data(),
          unsigned(active),
          sizeof(RTCRayHit));
      traced += active;
      if (bounce + 1 == options.maxPathLength)
        break;
      // Paths that hit continue, compacted to the front of the stream;
      // each also queues a shadow ray when light and surface face.
      size_t continuing = 0, shadowCount = 0;
      for (size_t i = 0; i < active; i++) {
        const RTCRayHit &path = paths[i];
        if (path.hit.geomID == RTC_INVALID_GEOMETRY_ID)
          continue;
        const Vec3 direction{path.ray.dir_x, path.ray.dir_y, path.ray.dir_z};
        const float t = path.ray.tfar;
        Vec3 normal = normalize({path.hit.Ng_x, path.hit.Ng_y, path.hit.Ng_z});
        if (dot(normal, direction) > 0.f)
          normal = normal * -1.f;
        const float offset = 1e-4f * std::max(1.f, t);
        const Vec3 origin = Vec3{path.ray.org_x, path.ray.org_y, path.ray.org_z}
                            + direction * t + normal * offset;

        const Vec3 onLight = light.position + light.edge1 * random.uniform()
                             + light.edge2 * random.uniform();
        const Vec3 toLight = onLight - origin;
        const float distance = length(toLight);
        const Vec3 towardsLight = toLight * (1.f / distance);
        if (dot(towardsLight, normal) > 0.f
            && dot(towardsLight, lightNormal) < 0.f) {
          setRay(shadows[shadowCount++],
              origin,
              towardsLight,
              std::max(0.f, distance * (1.f - 1e-4f) - offset));
        }

        const float u1 = random.uniform(), u2 = random.uniform();
        RTCRayHit &next = paths[continuing++];
        setRay(next.ray, origin, cosineDirection(normal, u1, u2), INFINITY);
        next.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        next.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
      }
      if (shadowCount > 0) {
        RTCIntersectContext shadowContext;
        rtcInitIntersectContext(&shadowContext);
        shadowContext.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
        rtcOccluded1M(scene.handle(),
            &shadowContext,
            shadows.data(),
            unsigned(shadowCount),
            sizeof(RTCRay));
        traced += shadowCount;
      }
      active = continuing;
    }
    total += traced;
  });
  return total;
}

// Frames of the same paths, traced by raw Embree.
class RawRoom
{
 public:
  RawRoom(const Options &options, const FurnishedRoom &room)
      : m_options(options),
        m_scene(room),
        m_camera(room.camera, options.width, options.height),
        m_light(room.ceilingLight)
  {}
  double buildSeconds() const
  {
    return m_scene.buildSeconds();
  }
  FrameResult trace()
  {
    const auto start = Clock::now();
    const uint64_t rays = traceRawFrame(
        m_scene, m_camera, m_light, m_options, m_frameIndex++, m_streams);
    return {seconds(start), rays};
  }

 private:
  const Options &m_options;
  RawScene m_scene;
  PinholeCamera m_camera;
  CeilingLight m_light;
  uint32_t m_frameIndex{0};
  tbb::enumerable_thread_specific<Streams> m_streams;
};

// --- main
// --------------------------------------------------------------------------

bool parseSize(const char *text, uint32_t &width, uint32_t &height)
{
  return std::sscanf(text, "%ux%u", &width, &height) == 2 && width > 0
         && height > 0;
}

Options parseOptions(int argc, char **argv)
{
  Options options;
  for (int i = 1; i < argc; i++) {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--quick") { // a smoke run: small image, one run
      options.width = 480;
      options.height = 270;
      options.runs = 1;
    } else if (arg == "--prism-only") {
      options.prismOnly = true;
    } else if (arg == "--embree-only") {
      options.embreeOnly = true;
    } else if (arg == "--runs" && hasValue) {
      options.runs = std::max(1, std::atoi(argv[++i]));
    } else if (arg == "--spp" && hasValue) {
      options.samplesPerPixel = std::max(1, std::atoi(argv[++i]));
    } else if (arg == "--max-path-length" && hasValue) {
      options.maxPathLength = std::max(1, std::atoi(argv[++i]));
    } else if (arg == "--size" && hasValue
               && parseSize(argv[i + 1], options.width, options.height)) {
      i++;
    } else {
      std::fprintf(stderr,
          "usage: prism-bench-pathtracer [--quick] [--runs N] [--spp N] "
          "[--size WxH] [--max-path-length N] [--prism-only] "
          "[--embree-only]\n");
      std::exit(2);
    }
  }
  return options;
}

} // namespace

int main(int argc, char **argv)
{
  const Options options = parseOptions(argc, argv);
  const FurnishedRoom room = furnishedRoomLayout();
  std::printf(
      "prism-bench-pathtracer: furnished room, %zu triangles, %ux%u, "
      "maxPathLength %d\n",
      room.triangleCount(),
      options.width,
      options.height,
      options.maxPathLength);
  std::printf("machine: %u hardware threads, %s\n",
      std::thread::hardware_concurrency(),
      cpuModel().c_str());
  std::fflush(stdout);

  // Prism's frames and raw Embree's alternate, one of each per sample, so
  // both meet the same machine: on shared machines speed drifts by tens of
  // percent within minutes, which would move a ratio of two separate runs.
  // The ratio reported is the median of the pairs' ratios.
  std::unique_ptr<RawRoom> raw;
  std::unique_ptr<PrismRoom> prism;
  if (!options.prismOnly)
    raw = std::make_unique<RawRoom>(options, room);
  if (!options.embreeOnly)
    prism = std::make_unique<PrismRoom>(options, room.camera);
  const double pixels = double(options.width) * options.height;
  std::vector<double> prismRate, prismRaysPerPixel, rawRate, ratios;
  std::vector<double> imageSeconds; // per run: the sum of its frames
  double rawRaysPerPixel = 0.0, firstFrameSeconds = 0.0;
  if (raw)
    raw->trace(); // warms caches and threads
  if (prism)
    firstFrameSeconds = prism->render().seconds; // applies commits, BVH
  for (int run = 0; run < options.runs; run++) {
    if (prism)
      prism->restart();
    double image = 0.0;
    for (int sample = 0; sample < options.samplesPerPixel; sample++) {
      if (raw) {
        const FrameResult frame = raw->trace();
        rawRate.push_back(double(frame.rays) / frame.seconds);
        rawRaysPerPixel = double(frame.rays) / pixels;
      }
      if (prism) {
        const FrameResult frame = prism->render();
        prismRate.push_back(double(frame.rays) / frame.seconds);
        prismRaysPerPixel.push_back(double(frame.rays) / pixels);
        image += frame.seconds;
      }
      if (raw && prism)
        ratios.push_back(prismRate.back() / rawRate.back());
    }
    if (prism) {
      imageSeconds.push_back(image);
      std::fprintf(stderr,
          "run %d of %d: prism %d spp in %.1f s\n",
          run + 1,
          options.runs,
          options.samplesPerPixel,
          image);
    }
  }

  std::printf(
      "\n%-34s %12s %14s %16s\n", "", "rays/pixel", "Mrays/s", "(min - max)");
  auto row = [](const char *name,
                 double raysPerPixel,
                 const std::vector<double> &raysPerSecond) {
    if (raysPerSecond.empty())
      return;
    const auto [low, high] =
        std::minmax_element(raysPerSecond.begin(), raysPerSecond.end());
    std::printf("%-34s %12.2f %14.2f %7.2f - %6.2f\n",
        name,
        raysPerPixel,
        median(raysPerSecond) * 1e-6,
        *low * 1e-6,
        *high * 1e-6);
  };
  row("prism pathtracer (per frame)", median(prismRaysPerPixel), prismRate);
  row("raw Embree, streams of 1024", rawRaysPerPixel, rawRate);
  if (prism && !prism->countsRays())
    std::printf("the renderer does not report 'raysTraced'\n");
  if (!ratios.empty()) {
    const auto [low, high] = std::minmax_element(ratios.begin(), ratios.end());
    std::printf("%-34s %41.0f %%   (target >= 65 %%)\n",
        "prism / raw Embree rays per second",
        100.0 * median(ratios));
    std::printf("  median of %zu paired frames; pairs range %.0f - %.0f %%\n",
        ratios.size(),
        100.0 * *low,
        100.0 * *high);
  }
  if (!imageSeconds.empty()) {
    std::string runs;
    for (double t : imageSeconds) {
      char text[32];
      std::snprintf(text, sizeof(text), "%s%.1f", runs.empty() ? "" : ", ", t);
      runs += text;
    }
    std::printf(
        "\n%ux%u at %d spp (accumulated frames): median %.1f s "
        "(runs: %s)\n",
        options.width,
        options.height,
        options.samplesPerPixel,
        median(imageSeconds),
        runs.c_str());
    std::printf("prism first frame (commits, BVH build, 1 spp): %.2f s\n",
        firstFrameSeconds);
  }
  if (raw)
    std::printf("raw Embree BVH build: %.3f s\n", raw->buildSeconds());
  return 0;
}
