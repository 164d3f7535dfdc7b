// prism-bench-volumes: frame times of volume rendering. A procedural
// structuredRegular field (soft blobs in empty space, as scanned objects
// sit in their scanner's box) at 128^3 and 256^3, and a hexahedral
// unstructured mesh of about 1M cells over the same function, rendered by
// `raycast` with the majorant grid (empty-space skipping, early stop) and
// without it (the spec's Appendix C reference marcher, every step), and by
// `pathtracer` (one sample per pixel: delta tracking) with and without
// the grid. Prints the median frame time of each, the speed-up of the
// grid, and the RMSE between the two raycast images (same sampling rate:
// the images must agree). With --nanovdb: a dense field (a head scan's
// size, every voxel non-zero) and a sparse cloud (the blobs at 256^3) each
// as a structuredRegular grid and as a NanoVDB grid, NanoVDB's time over
// the dense grid's and the RMSE between their images. Never a test: it
// prints.
#include <anari/anari.h>
#include <nanovdb/util/GridBuilder.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

struct Options
{
  uint32_t width{1024}, height{768};
  int runs{3};
  bool quick{false};
};

// Soft blobs in [0, 1]^3, zero beyond them: about 85% of the box is empty.
float blobs(float x, float y, float z)
{
  const float centers[4][4] = {{0.35f, 0.4f, 0.45f, 0.22f},
      {0.65f, 0.55f, 0.5f, 0.18f},
      {0.5f, 0.7f, 0.35f, 0.12f},
      {0.45f, 0.3f, 0.7f, 0.1f}};
  float value = 0.f;
  for (const auto &c : centers) {
    const float dx = x - c[0], dy = y - c[1], dz = z - c[2];
    const float d = std::sqrt(dx * dx + dy * dy + dz * dz) / c[3];
    value = std::max(value, 1.f - d);
  }
  // Fine structure inside, so sampling matters.
  return value > 0.f ? value
                           * (0.75f
                               + 0.25f * std::sin(40.f * x) * std::sin(37.f * y)
                                     * std::sin(43.f * z))
                     : 0.f;
}

// Everywhere non-zero, as a scan's noise floor fills its box: an MRI-like
// head, a lumpy ellipsoid in a faint haze.
float head(float x, float y, float z)
{
  const float dx = (x - 0.5f) / 0.42f, dy = (y - 0.37f) / 0.32f,
              dz = (z - 0.094f) / 0.09f;
  const float r = std::sqrt(dx * dx + dy * dy + dz * dz);
  const float tissue =
      r < 1.f ? 0.6f + 0.3f * std::sin(23.f * x) * std::sin(29.f * y) : 0.f;
  return 0.05f + 0.02f * std::sin(71.f * x + 53.f * y) + tissue;
}

using Function = float (*)(float, float, float);

struct Dimensions
{
  uint32_t x, y, z;
  // Samples one spacing apart, the longest axis spanning [0, 1].
  float spacing() const
  {
    return 1.f / float(std::max({x, y, z}) - 1);
  }
};

class Bench
{
 public:
  explicit Bench(const Options &options) : m_options(options)
  {
    m_library = anariLoadLibrary("prism", nullptr, nullptr);
    if (!m_library) {
      std::fprintf(stderr, "cannot load the prism library\n");
      std::exit(1);
    }
    m_device = anariNewDevice(m_library, "default");
  }
  ~Bench()
  {
    anariRelease(m_device, m_device);
    anariUnloadLibrary(m_library);
  }

  ANARISpatialField structured(uint32_t n)
  {
    return structured({n, n, n}, blobs);
  }
  // nx x ny x nz samples of `value` over [0, 1] along the longest axis.
  ANARISpatialField structured(const Dimensions &size, Function value)
  {
    ANARIArray3D data = anariNewArray3D(m_device,
        nullptr,
        nullptr,
        nullptr,
        ANARI_FLOAT32,
        size.x,
        size.y,
        size.z);
    auto *v = (float *)anariMapArray(m_device, data);
    const float s = size.spacing();
    for (uint32_t z = 0; z < size.z; z++)
      for (uint32_t y = 0; y < size.y; y++)
        for (uint32_t x = 0; x < size.x; x++)
          v[(size_t(z) * size.y + y) * size.x + x] =
              value(float(x) * s, float(y) * s, float(z) * s);
    anariUnmapArray(m_device, data);
    ANARISpatialField f = anariNewSpatialField(m_device, "structuredRegular");
    const float spacing[3] = {s, s, s};
    anariSetParameter(m_device, f, "data", ANARI_ARRAY3D, &data);
    anariSetParameter(m_device, f, "spacing", ANARI_FLOAT32_VEC3, spacing);
    anariRelease(m_device, data);
    anariCommitParameters(m_device, f);
    return f;
  }
  // The same samples as a NanoVDB float grid (voxel ijk at ijk * spacing,
  // as the dense grid's sample ijk): every voxel active when `dense`,
  // else only the non-zero ones (background 0).
  ANARISpatialField nanoVdb(const Dimensions &size, Function value, bool dense)
  {
    nanovdb::GridBuilder<float> builder(0.f, nanovdb::GridClass::FogVolume);
    auto voxels = builder.getAccessor();
    const float s = size.spacing();
    for (uint32_t z = 0; z < size.z; z++)
      for (uint32_t y = 0; y < size.y; y++)
        for (uint32_t x = 0; x < size.x; x++) {
          const float v = value(float(x) * s, float(y) * s, float(z) * s);
          if (dense || v != 0.f)
            voxels.setValue(nanovdb::Coord(int(x), int(y), int(z)), v);
        }
    const auto handle = builder.getHandle<>(double(s), nanovdb::Vec3d(0.0));
    ANARIArray1D data = anariNewArray1D(
        m_device, nullptr, nullptr, nullptr, ANARI_UINT8, handle.size());
    std::memcpy(anariMapArray(m_device, data), handle.data(), handle.size());
    anariUnmapArray(m_device, data);
    ANARISpatialField f = anariNewSpatialField(m_device, "nanovdb");
    anariSetParameter(m_device, f, "data", ANARI_ARRAY1D, &data);
    anariRelease(m_device, data);
    anariCommitParameters(m_device, f);
    return f;
  }
  // n^3 hexahedra over [0, 1]^3 with the same function at the vertices.
  ANARISpatialField unstructured(uint32_t n)
  {
    const uint32_t m = n + 1;
    std::vector<float> positions, values;
    positions.reserve(size_t(m) * m * m * 3);
    const float s = 1.f / float(n);
    for (uint32_t z = 0; z < m; z++)
      for (uint32_t y = 0; y < m; y++)
        for (uint32_t x = 0; x < m; x++) {
          positions.insert(
              positions.end(), {float(x) * s, float(y) * s, float(z) * s});
          values.push_back(blobs(float(x) * s, float(y) * s, float(z) * s));
        }
    std::vector<uint32_t> index, offsets;
    std::vector<uint8_t> types;
    auto vertex = [&](uint32_t x, uint32_t y, uint32_t z) {
      return (z * m + y) * m + x;
    };
    for (uint32_t z = 0; z < n; z++)
      for (uint32_t y = 0; y < n; y++)
        for (uint32_t x = 0; x < n; x++) {
          offsets.push_back(uint32_t(index.size()));
          types.push_back(12); // VTK_HEXAHEDRON
          index.insert(index.end(),
              {vertex(x, y, z),
                  vertex(x + 1, y, z),
                  vertex(x + 1, y + 1, z),
                  vertex(x, y + 1, z),
                  vertex(x, y, z + 1),
                  vertex(x + 1, y, z + 1),
                  vertex(x + 1, y + 1, z + 1),
                  vertex(x, y + 1, z + 1)});
        }
    ANARISpatialField f = anariNewSpatialField(m_device, "unstructured");
    auto set = [&](const char *name,
                   const void *data,
                   ANARIDataType type,
                   size_t count) {
      ANARIArray1D a =
          anariNewArray1D(m_device, nullptr, nullptr, nullptr, type, count);
      std::memcpy(anariMapArray(m_device, a),
          data,
          count
              * (type == ANARI_FLOAT32_VEC3 ? 12
                  : type == ANARI_UINT8     ? 1
                                            : 4));
      anariUnmapArray(m_device, a);
      anariSetParameter(m_device, f, name, ANARI_ARRAY1D, &a);
      anariRelease(m_device, a);
    };
    set("vertex.position",
        positions.data(),
        ANARI_FLOAT32_VEC3,
        positions.size() / 3);
    set("vertex.data", values.data(), ANARI_FLOAT32, values.size());
    set("index", index.data(), ANARI_UINT32, index.size());
    set("cell.index", offsets.data(), ANARI_UINT32, offsets.size());
    set("cell.type", types.data(), ANARI_UINT8, types.size());
    anariCommitParameters(m_device, f);
    return f;
  }

  // A world of one transferFunction1D volume of `field` (released).
  ANARIWorld world(ANARISpatialField field)
  {
    ANARIVolume v = anariNewVolume(m_device, "transferFunction1D");
    anariSetParameter(m_device, v, "value", ANARI_SPATIAL_FIELD, &field);
    anariRelease(m_device, field);
    const float colors[] = {
        0.23f, 0.3f, 0.75f, 0.87f, 0.87f, 0.87f, 0.71f, 0.02f, 0.15f};
    const float opacities[] = {0.f, 0.3f, 0.9f};
    ANARIArray1D c = anariNewArray1D(
        m_device, colors, nullptr, nullptr, ANARI_FLOAT32_VEC3, 3);
    ANARIArray1D o = anariNewArray1D(
        m_device, opacities, nullptr, nullptr, ANARI_FLOAT32, 3);
    anariSetParameter(m_device, v, "color", ANARI_ARRAY1D, &c);
    anariSetParameter(m_device, v, "opacity", ANARI_ARRAY1D, &o);
    const float unitDistance = 0.05f;
    anariSetParameter(
        m_device, v, "unitDistance", ANARI_FLOAT32, &unitDistance);
    anariCommitParameters(m_device, v);
    anariRelease(m_device, c);
    anariRelease(m_device, o);
    ANARIWorld w = anariNewWorld(m_device);
    ANARIArray1D volumes =
        anariNewArray1D(m_device, &v, nullptr, nullptr, ANARI_VOLUME, 1);
    anariSetParameter(m_device, w, "volume", ANARI_ARRAY1D, &volumes);
    anariRelease(m_device, volumes);
    anariRelease(m_device, v);
    anariCommitParameters(m_device, w);
    return w;
  }

  struct Result
  {
    double medianSeconds{0.0};
    std::vector<float> image;
  };
  Result render(ANARIWorld w, const char *subtype, bool grid)
  {
    ANARICamera camera = anariNewCamera(m_device, "perspective");
    const float eye[3] = {1.9f, 1.4f, 2.1f};
    const float direction[3] = {-1.4f, -0.9f, -1.6f};
    const float aspect = float(m_options.width) / float(m_options.height);
    const float fovy = 0.6f;
    anariSetParameter(m_device, camera, "position", ANARI_FLOAT32_VEC3, eye);
    anariSetParameter(
        m_device, camera, "direction", ANARI_FLOAT32_VEC3, direction);
    anariSetParameter(m_device, camera, "aspect", ANARI_FLOAT32, &aspect);
    anariSetParameter(m_device, camera, "fovy", ANARI_FLOAT32, &fovy);
    anariCommitParameters(m_device, camera);
    ANARIRenderer renderer = anariNewRenderer(m_device, subtype);
    const bool on = grid;
    anariSetParameter(
        m_device, renderer, "volumeMajorantGrid", ANARI_BOOL, &on);
    const float black[4] = {0, 0, 0, 1};
    anariSetParameter(
        m_device, renderer, "background", ANARI_FLOAT32_VEC4, black);
    anariCommitParameters(m_device, renderer);
    ANARIFrame frame = anariNewFrame(m_device);
    const uint32_t size[2] = {m_options.width, m_options.height};
    const ANARIDataType color = ANARI_FLOAT32_VEC4;
    anariSetParameter(m_device, frame, "world", ANARI_WORLD, &w);
    anariSetParameter(m_device, frame, "camera", ANARI_CAMERA, &camera);
    anariSetParameter(m_device, frame, "renderer", ANARI_RENDERER, &renderer);
    anariSetParameter(m_device, frame, "size", ANARI_UINT32_VEC2, size);
    anariSetParameter(
        m_device, frame, "channel.color", ANARI_DATA_TYPE, &color);
    anariCommitParameters(m_device, frame);
    // One frame to warm up (first-frame builds), then the timed ones.
    anariRenderFrame(m_device, frame);
    anariFrameReady(m_device, frame, ANARI_WAIT);
    std::vector<double> times;
    for (int run = 0; run < m_options.runs; run++) {
      const auto start = Clock::now();
      anariRenderFrame(m_device, frame);
      anariFrameReady(m_device, frame, ANARI_WAIT);
      times.push_back(
          std::chrono::duration<double>(Clock::now() - start).count());
    }
    std::sort(times.begin(), times.end());
    Result result;
    result.medianSeconds = times[times.size() / 2];
    uint32_t width = 0, height = 0;
    ANARIDataType type;
    auto *p = (const float *)anariMapFrame(
        m_device, frame, "channel.color", &width, &height, &type);
    if (p)
      result.image.assign(p, p + 4 * size_t(width) * height);
    anariUnmapFrame(m_device, frame, "channel.color");
    for (ANARIObject o :
        {(ANARIObject)frame, (ANARIObject)renderer, (ANARIObject)camera})
      anariRelease(m_device, o);
    return result;
  }

  struct Measured
  {
    Result raycast, pathtracer;
  };
  Measured measure(const char *name, ANARIWorld w)
  {
    Measured measured;
    measured.raycast = render(w, "raycast", true);
    const Result reference = render(w, "raycast", false);
    std::printf(
        "%-24s raycast %8.1f ms, reference marcher %8.1f ms: %5.2fx"
        "  (RMSE between them %.2e, mean value %.3f)\n",
        name,
        1e3 * measured.raycast.medianSeconds,
        1e3 * reference.medianSeconds,
        reference.medianSeconds / measured.raycast.medianSeconds,
        rmse(measured.raycast.image, reference.image),
        meanColor(reference.image));
    measured.pathtracer = render(w, "pathtracer", true);
    const Result tracedWithout = render(w, "pathtracer", false);
    std::printf(
        "%-24s pathtracer 1 spp %8.1f ms, one majorant %8.1f ms: "
        "%5.2fx\n",
        name,
        1e3 * measured.pathtracer.medianSeconds,
        1e3 * tracedWithout.medianSeconds,
        tracedWithout.medianSeconds / measured.pathtracer.medianSeconds);
    std::fflush(stdout);
    return measured;
  }

  // The same field as a dense structuredRegular grid and as a NanoVDB
  // grid (every voxel active when `dense`): NanoVDB's time over the
  // dense grid's, and how far apart their raycast images are.
  void compareWithNanoVdb(
      const char *name, const Dimensions &size, Function value, bool dense)
  {
    char label[64];
    std::snprintf(label, sizeof(label), "%s dense", name);
    ANARIWorld w = world(structured(size, value));
    const Measured grid = measure(label, w);
    anariRelease(m_device, w);
    std::snprintf(label, sizeof(label), "%s nanovdb", name);
    w = world(nanoVdb(size, value, dense));
    const Measured vdb = measure(label, w);
    anariRelease(m_device, w);
    std::printf(
        "%-24s nanovdb / dense: raycast %.2fx, pathtracer %.2fx"
        "  (raycast RMSE between them %.2e; pathtracer mean %.4f vs %.4f)\n",
        name,
        vdb.raycast.medianSeconds / grid.raycast.medianSeconds,
        vdb.pathtracer.medianSeconds / grid.pathtracer.medianSeconds,
        rmse(vdb.raycast.image, grid.raycast.image),
        meanColor(vdb.pathtracer.image),
        meanColor(grid.pathtracer.image));
    std::fflush(stdout);
  }

  static double rmse(const std::vector<float> &a, const std::vector<float> &b)
  {
    double squared = 0.0, values = 0.0;
    for (size_t i = 0; i < std::min(a.size(), b.size()); i++) {
      if (i % 4 == 3)
        continue;
      const double d = a[i] - b[i];
      squared += d * d;
      values += 1.0;
    }
    return std::sqrt(squared / std::max(values, 1.0));
  }
  static double meanColor(const std::vector<float> &image)
  {
    double sum = 0.0, values = 0.0;
    for (size_t i = 0; i < image.size(); i++) {
      if (i % 4 != 3) {
        sum += image[i];
        values += 1.0;
      }
    }
    return sum / std::max(values, 1.0);
  }

  ANARIDevice device() const
  {
    return m_device;
  }

 private:
  Options m_options;
  ANARILibrary m_library{nullptr};
  ANARIDevice m_device{nullptr};
};

} // namespace

int main(int argc, char **argv)
{
  Options options;
  bool nanovdbOnly = false;
  std::vector<std::string> one;
  for (int i = 1; i < argc; i++) {
    const std::string arg = argv[i];
    if (arg == "--quick") {
      options.quick = true;
      options.width = 256;
      options.height = 192;
      options.runs = 1;
    } else if (arg == "--one" && i + 3 < argc) {
      one = {argv[i + 1], argv[i + 2], argv[i + 3]};
      i += 3;
    } else if (arg == "--size" && i + 2 < argc) {
      options.width = uint32_t(std::max(1, std::atoi(argv[++i])));
      options.height = uint32_t(std::max(1, std::atoi(argv[++i])));
    } else if (arg == "--nanovdb") {
      nanovdbOnly = true;
    } else if (arg == "--runs" && i + 1 < argc) {
      options.runs = std::max(1, std::atoi(argv[++i]));
    } else {
      std::fprintf(stderr,
          "usage: prism-bench-volumes [--quick] [--runs N] [--size W H] "
          "[--nanovdb]\n"
          "  [--one FIELD DATA RENDERER]\n"
          "  frame times of raycast (majorant grid vs the reference marcher)"
          " and pathtracer\n  on 128^3 and 256^3 structuredRegular fields and"
          " a ~1M-cell unstructured mesh;\n  --nanovdb: only dense data "
          "(128x96x24)"
          " and a sparse cloud (256^3) as dense\n  and NanoVDB grids;"
          " --one dense|nanovdb head|cloud raycast|pathtracer: that\n  alone"
          " (for paired runs); --size W H: the frame's size\n");
      return 2;
    }
  }
  std::printf("%ux%u, median of %d frames\n",
      options.width,
      options.height,
      options.runs);
  Bench bench(options);
  if (!one.empty()) {
    // One field, one renderer: for paired runs of whole processes.
    const bool cloud = one[1] == "cloud";
    const uint32_t n = options.quick ? 128 : 256;
    const Dimensions size =
        cloud ? Dimensions{n, n, n} : Dimensions{128, 96, 24};
    const Function value = cloud ? blobs : head;
    ANARIWorld w =
        bench.world(one[0] == "nanovdb" ? bench.nanoVdb(size, value, !cloud)
                                        : bench.structured(size, value));
    const auto result = bench.render(w, one[2].c_str(), true);
    std::printf("%s %s %s: %.1f ms\n",
        one[0].c_str(),
        one[1].c_str(),
        one[2].c_str(),
        1e3 * result.medianSeconds);
    anariRelease(bench.device(), w);
    return 0;
  }
  if (nanovdbOnly) {
    bench.compareWithNanoVdb("head 128x96x24", {128, 96, 24}, head, true);
    const uint32_t n = options.quick ? 128 : 256;
    bench.compareWithNanoVdb("cloud", {n, n, n}, blobs, false);
    return 0;
  }
  for (uint32_t n : {128u, 256u}) {
    const auto start = Clock::now();
    ANARIWorld w = bench.world(bench.structured(n));
    const double build =
        std::chrono::duration<double>(Clock::now() - start).count();
    const std::string name = "structuredRegular " + std::to_string(n) + "^3";
    std::printf("%-24s built in %.2f s\n", name.c_str(), build);
    bench.measure(name.c_str(), w);
    anariRelease(bench.device(), w);
    if (options.quick)
      break;
  }
  const uint32_t cells = options.quick ? 32 : 100;
  const auto start = Clock::now();
  ANARIWorld w = bench.world(bench.unstructured(cells));
  const double build =
      std::chrono::duration<double>(Clock::now() - start).count();
  const std::string name =
      "unstructured " + std::to_string(cells * cells * cells) + " hex";
  std::printf("%-24s built in %.2f s\n", name.c_str(), build);
  bench.measure(name.c_str(), w);
  anariRelease(bench.device(), w);
  return 0;
}
