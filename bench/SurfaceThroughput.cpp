// Raycast throughput against raw Embree on the same camera rays.
//
// For each scene (a ~1M-triangle mesh, 1M spheres) this renders 1920x1080
// frames with prism's `raycast` renderer through the public API, then
// traces the identical primary rays with Embree directly (same BVH quality
// and scene flags, 8-wide packets, all cores, no shading, no frame
// writing), and reports
// median times, their ratio (prism's share of raw Embree throughput), BVH
// build time and BVH bytes per primitive. Run: build/bin/prism-bench-surfaces
#include <anari/anari.h>
#include <embree3/rtcore.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <thread>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;
constexpr uint32_t kWidth = 1920, kHeight = 1080;
constexpr int kRuns = 7;

struct Scene
{
  const char *name;
  const char *subtype; // "triangle" or "sphere"
  std::vector<float> positions;
  std::vector<uint32_t> indices; // triangles only
  size_t vertices{0};            // positions holds one padding vertex more
  float radius{0.f};             // spheres only
  size_t primitives{0};
};

// A torus tessellated into a grid of quads split in two triangles.
Scene makeMesh(int segments)
{
  Scene s{"torus mesh", "triangle", {}, {}, 0, 0.f, 0};
  const int n = segments, m = segments;
  for (int i = 0; i < n; i++) {
    for (int j = 0; j < m; j++) {
      const float u = 2.f * float(M_PI) * float(i) / float(n);
      const float v = 2.f * float(M_PI) * float(j) / float(m);
      const float r = 1.f + 0.4f * std::cos(v);
      s.positions.insert(s.positions.end(),
          {r * std::cos(u), 0.4f * std::sin(v), r * std::sin(u)});
    }
  }
  for (int i = 0; i < n; i++) {
    for (int j = 0; j < m; j++) {
      const uint32_t a = i * m + j, b = ((i + 1) % n) * m + j;
      const uint32_t c = ((i + 1) % n) * m + (j + 1) % m,
                     d = i * m + (j + 1) % m;
      s.indices.insert(s.indices.end(), {a, b, c, a, c, d});
    }
  }
  s.primitives = s.indices.size() / 3;
  s.vertices = size_t(n) * m;
  s.positions.insert(s.positions.end(), {0.f, 0.f, 0.f}); // Embree padding
  return s;
}

Scene makeSpheres(size_t count)
{
  Scene s{"random spheres", "sphere", {}, {}, 0, 0.006f, count};
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> coordinate(-1.2f, 1.2f);
  for (size_t i = 0; i < count; i++)
    s.positions.insert(s.positions.end(),
        {coordinate(rng), coordinate(rng) * 0.5f, coordinate(rng)});
  s.vertices = count;
  return s;
}

// The camera both sides use: perspective, 40 degrees, looking at the origin.
struct Camera
{
  float eye[3] = {0.f, 1.2f, 3.2f};
  float direction[3];
  float up[3] = {0, 1, 0};
  float fovy = 40.f * float(M_PI) / 180.f;
  float right[3], trueUp[3];

  Camera()
  {
    const float l =
        std::sqrt(eye[0] * eye[0] + eye[1] * eye[1] + eye[2] * eye[2]);
    for (int i = 0; i < 3; i++)
      direction[i] = -eye[i] / l;
    right[0] = direction[1] * up[2] - direction[2] * up[1];
    right[1] = direction[2] * up[0] - direction[0] * up[2];
    right[2] = direction[0] * up[1] - direction[1] * up[0];
    const float rl = std::sqrt(
        right[0] * right[0] + right[1] * right[1] + right[2] * right[2]);
    for (float &c : right)
      c /= rl;
    trueUp[0] = right[1] * direction[2] - right[2] * direction[1];
    trueUp[1] = right[2] * direction[0] - right[0] * direction[2];
    trueUp[2] = right[0] * direction[1] - right[1] * direction[0];
  }
  void ray(uint32_t x, uint32_t y, float out[3]) const
  {
    const float h = std::tan(0.5f * fovy),
                w = h * float(kWidth) / float(kHeight);
    const float sx = (2.f * (float(x) + 0.5f) / float(kWidth) - 1.f) * w;
    const float sy = (2.f * (float(y) + 0.5f) / float(kHeight) - 1.f) * h;
    float l = 0.f;
    for (int i = 0; i < 3; i++) {
      out[i] = direction[i] + sx * right[i] + sy * trueUp[i];
      l += out[i] * out[i];
    }
    l = std::sqrt(l);
    for (int i = 0; i < 3; i++)
      out[i] /= l;
  }
};

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

std::atomic<long long> g_embreeBytes{0};

bool trackMemory(void *, ssize_t bytes, bool)
{
  g_embreeBytes += bytes;
  return true;
}

struct RawResult
{
  double buildSeconds, frameSeconds;
  long long bytes;
  size_t hits;
};

RawResult rawEmbree(const Scene &s, const Camera &camera)
{
  RTCDevice device = rtcNewDevice(nullptr);
  rtcSetDeviceMemoryMonitorFunction(device, trackMemory, nullptr);
  RTCScene scene = rtcNewScene(device);
  // The same build quality and flags as prism's scenes (rt/Scene.cpp).
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  std::vector<float> spheres;
  RTCGeometry g;
  if (std::strcmp(s.subtype, "triangle") == 0) {
    g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(g,
        RTC_BUFFER_TYPE_VERTEX,
        0,
        RTC_FORMAT_FLOAT3,
        s.positions.data(),
        0,
        12,
        s.vertices);
    rtcSetSharedGeometryBuffer(g,
        RTC_BUFFER_TYPE_INDEX,
        0,
        RTC_FORMAT_UINT3,
        s.indices.data(),
        0,
        12,
        s.primitives);
  } else {
    for (size_t i = 0; i < s.primitives; i++)
      spheres.insert(spheres.end(),
          {s.positions[3 * i],
              s.positions[3 * i + 1],
              s.positions[3 * i + 2],
              s.radius});
    g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    rtcSetSharedGeometryBuffer(g,
        RTC_BUFFER_TYPE_VERTEX,
        0,
        RTC_FORMAT_FLOAT4,
        spheres.data(),
        0,
        16,
        s.primitives);
  }
  rtcCommitGeometry(g);
  rtcAttachGeometry(scene, g);
  rtcReleaseGeometry(g);
  g_embreeBytes = 0;
  const auto buildStart = Clock::now();
  rtcCommitScene(scene);
  RawResult result{};
  result.buildSeconds =
      std::chrono::duration<double>(Clock::now() - buildStart).count();
  result.bytes = g_embreeBytes;

  std::vector<double> times;
  for (int run = 0; run < kRuns; run++) {
    std::atomic<size_t> hits{0};
    const auto start = Clock::now();
    // Rows of 8-pixel packets, as prism's renderer traces them.
    tbb::parallel_for(uint32_t(0), kHeight, [&](uint32_t y) {
      size_t rowHits = 0;
      for (uint32_t x = 0; x < kWidth; x += 8) {
        alignas(32) RTCRayHit8 rh;
        alignas(32) int valid[8];
        for (int i = 0; i < 8; i++) {
          float d[3];
          camera.ray(x + i, y, d);
          rh.ray.org_x[i] = camera.eye[0];
          rh.ray.org_y[i] = camera.eye[1];
          rh.ray.org_z[i] = camera.eye[2];
          rh.ray.dir_x[i] = d[0];
          rh.ray.dir_y[i] = d[1];
          rh.ray.dir_z[i] = d[2];
          rh.ray.tnear[i] = 0.f;
          rh.ray.tfar[i] = INFINITY;
          rh.ray.time[i] = 0.5f;
          rh.ray.mask[i] = ~0u;
          rh.ray.flags[i] = 0;
          rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
          rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
          valid[i] = x + i < kWidth ? -1 : 0;
        }
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        rtcIntersect8(valid, scene, &context, &rh);
        for (int i = 0; i < 8; i++)
          rowHits += rh.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID;
      }
      hits += rowHits;
    });
    times.push_back(
        std::chrono::duration<double>(Clock::now() - start).count());
    result.hits = hits;
  }
  result.frameSeconds = median(times);
  rtcReleaseScene(scene);
  rtcReleaseDevice(device);
  return result;
}

struct PrismResult
{
  double firstFrameSeconds, frameSeconds;
};

PrismResult prism(const Scene &s, const Camera &camera)
{
  ANARILibrary library = anariLoadLibrary("prism", nullptr, nullptr);
  ANARIDevice d = anariNewDevice(library, "default");
  ANARIGeometry g = anariNewGeometry(d, s.subtype);
  ANARIArray1D positions = anariNewArray1D(
      d, s.positions.data(), nullptr, nullptr, ANARI_FLOAT32_VEC3, s.vertices);
  anariSetParameter(d, g, "vertex.position", ANARI_ARRAY1D, &positions);
  anariRelease(d, positions);
  if (!s.indices.empty()) {
    ANARIArray1D index = anariNewArray1D(
        d, s.indices.data(), nullptr, nullptr, ANARI_UINT32_VEC3, s.primitives);
    anariSetParameter(d, g, "primitive.index", ANARI_ARRAY1D, &index);
    anariRelease(d, index);
  } else {
    anariSetParameter(d, g, "radius", ANARI_FLOAT32, &s.radius);
  }
  anariCommitParameters(d, g);
  ANARIMaterial m = anariNewMaterial(d, "matte");
  anariCommitParameters(d, m);
  ANARISurface surface = anariNewSurface(d);
  anariSetParameter(d, surface, "geometry", ANARI_GEOMETRY, &g);
  anariSetParameter(d, surface, "material", ANARI_MATERIAL, &m);
  anariCommitParameters(d, surface);
  ANARIWorld world = anariNewWorld(d);
  ANARIArray1D surfaces =
      anariNewArray1D(d, &surface, nullptr, nullptr, ANARI_SURFACE, 1);
  anariSetParameter(d, world, "surface", ANARI_ARRAY1D, &surfaces);
  anariCommitParameters(d, world);
  ANARICamera c = anariNewCamera(d, "perspective");
  const float aspect = float(kWidth) / float(kHeight);
  anariSetParameter(d, c, "position", ANARI_FLOAT32_VEC3, camera.eye);
  anariSetParameter(d, c, "direction", ANARI_FLOAT32_VEC3, camera.direction);
  anariSetParameter(d, c, "up", ANARI_FLOAT32_VEC3, camera.up);
  anariSetParameter(d, c, "fovy", ANARI_FLOAT32, &camera.fovy);
  anariSetParameter(d, c, "aspect", ANARI_FLOAT32, &aspect);
  anariCommitParameters(d, c);
  ANARIRenderer r = anariNewRenderer(d, "raycast");
  anariCommitParameters(d, r);
  ANARIFrame f = anariNewFrame(d);
  const uint32_t size[2] = {kWidth, kHeight};
  const ANARIDataType color = ANARI_UFIXED8_RGBA_SRGB, depth = ANARI_FLOAT32;
  anariSetParameter(d, f, "size", ANARI_UINT32_VEC2, size);
  anariSetParameter(d, f, "channel.color", ANARI_DATA_TYPE, &color);
  anariSetParameter(d, f, "channel.depth", ANARI_DATA_TYPE, &depth);
  anariSetParameter(d, f, "world", ANARI_WORLD, &world);
  anariSetParameter(d, f, "camera", ANARI_CAMERA, &c);
  anariSetParameter(d, f, "renderer", ANARI_RENDERER, &r);
  anariCommitParameters(d, f);

  PrismResult result{};
  const auto start = Clock::now();
  anariRenderFrame(d, f); // includes applying commits and the BVH build
  anariFrameReady(d, f, ANARI_WAIT);
  result.firstFrameSeconds =
      std::chrono::duration<double>(Clock::now() - start).count();
  std::vector<double> times;
  for (int run = 0; run < kRuns; run++) {
    const auto t0 = Clock::now();
    anariRenderFrame(d, f);
    anariFrameReady(d, f, ANARI_WAIT);
    times.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
  }
  result.frameSeconds = median(times);
  for (ANARIObject o : {(ANARIObject)f,
           (ANARIObject)r,
           (ANARIObject)c,
           (ANARIObject)world,
           (ANARIObject)surfaces,
           (ANARIObject)surface,
           (ANARIObject)m,
           (ANARIObject)g})
    anariRelease(d, o);
  anariRelease(d, d);
  anariUnloadLibrary(library);
  return result;
}

} // namespace

int main(int argc, char **argv)
{
  bool quick = false, prismOnly = false, embreeOnly = false;
  const char *only = nullptr; // --only <scene subtype>: one scene (profiling)
  for (int i = 1; i < argc; i++) {
    quick |= std::strcmp(argv[i], "--quick") == 0; // small scenes (smoke run)
    prismOnly |= std::strcmp(argv[i], "--prism-only") == 0; // for profiling
    embreeOnly |= std::strcmp(argv[i], "--embree-only") == 0;
    if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc)
      only = argv[++i];
  }
  const Camera camera;
  std::printf(
      "prism-bench-surfaces: %ux%u, median of %d frames, %u hardware threads\n",
      kWidth,
      kHeight,
      kRuns,
      std::thread::hardware_concurrency());
  std::printf("%-16s %10s %11s %11s %8s %10s %11s %9s\n",
      "scene",
      "primitives",
      "prism (ms)",
      "embree (ms)",
      "ratio",
      "Mrays/s",
      "build (ms)",
      "B/prim");
  Scene scenes[] = {
      makeMesh(quick ? 100 : 708), makeSpheres(quick ? 10000 : 1000000)};
  for (const Scene &s : scenes) {
    if (only && std::strcmp(only, s.subtype) != 0)
      continue;
    const RawResult raw =
        prismOnly ? RawResult{1, 1, 0, 0} : rawEmbree(s, camera);
    const PrismResult ours = embreeOnly ? PrismResult{1, 1} : prism(s, camera);
    const double rays = double(kWidth) * kHeight;
    std::printf("%-16s %10zu %11.1f %11.1f %7.0f%% %10.1f %11.1f %9.1f\n",
        s.name,
        s.primitives,
        ours.frameSeconds * 1e3,
        raw.frameSeconds * 1e3,
        100.0 * raw.frameSeconds / ours.frameSeconds,
        rays / ours.frameSeconds * 1e-6,
        raw.buildSeconds * 1e3,
        double(raw.bytes) / double(s.primitives));
    std::printf(
        "%-16s first prism frame (commit + BVH build + render): %.1f ms; "
        "embree hit %.1f%% of rays\n",
        "",
        ours.firstFrameSeconds * 1e3,
        100.0 * double(raw.hits) / rays);
  }
  return 0;
}
