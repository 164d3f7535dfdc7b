// prism-bench-volumes: frame times of volume rendering. A procedural
// structuredRegular field (soft blobs in empty space, as scanned objects
// sit in their scanner's box) at 128^3 and 256^3, and a hexahedral
// unstructured mesh of about 1M cells over the same function, rendered by
// `raycast` with the majorant grid (empty-space skipping, early stop) and
// without it (the spec's Appendix C reference marcher, every step), and by
// `pathtracer` (one sample per pixel: delta tracking) with and without
// the grid. Prints the median frame time of each, the speed-up of the
// grid, and the RMSE between the two raycast images (same sampling rate:
// the images must agree). Never a test: it prints.
#include <anari/anari.h>

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
    ANARIArray3D data = anariNewArray3D(
        m_device, nullptr, nullptr, nullptr, ANARI_FLOAT32, n, n, n);
    auto *v = (float *)anariMapArray(m_device, data);
    const float s = 1.f / float(n - 1);
    for (uint32_t z = 0; z < n; z++)
      for (uint32_t y = 0; y < n; y++)
        for (uint32_t x = 0; x < n; x++)
          v[(size_t(z) * n + y) * n + x] =
              blobs(float(x) * s, float(y) * s, float(z) * s);
    anariUnmapArray(m_device, data);
    ANARISpatialField f = anariNewSpatialField(m_device, "structuredRegular");
    const float spacing[3] = {s, s, s};
    anariSetParameter(m_device, f, "data", ANARI_ARRAY3D, &data);
    anariSetParameter(m_device, f, "spacing", ANARI_FLOAT32_VEC3, spacing);
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

  void measure(const char *name, ANARIWorld w)
  {
    const Result skipping = render(w, "raycast", true);
    const Result reference = render(w, "raycast", false);
    double squared = 0.0, mean = 0.0;
    for (size_t i = 0; i < skipping.image.size(); i++) {
      if (i % 4 == 3)
        continue;
      const double d = skipping.image[i] - reference.image[i];
      squared += d * d;
      mean += reference.image[i];
    }
    const double values = double(skipping.image.size()) * 0.75;
    std::printf(
        "%-24s raycast %8.1f ms, reference marcher %8.1f ms: %5.2fx"
        "  (RMSE between them %.2e, mean value %.3f)\n",
        name,
        1e3 * skipping.medianSeconds,
        1e3 * reference.medianSeconds,
        reference.medianSeconds / skipping.medianSeconds,
        std::sqrt(squared / std::max(values, 1.0)),
        mean / std::max(values, 1.0));
    const Result traced = render(w, "pathtracer", true);
    const Result tracedWithout = render(w, "pathtracer", false);
    std::printf(
        "%-24s pathtracer 1 spp %8.1f ms, one majorant %8.1f ms: "
        "%5.2fx\n",
        name,
        1e3 * traced.medianSeconds,
        1e3 * tracedWithout.medianSeconds,
        tracedWithout.medianSeconds / traced.medianSeconds);
    std::fflush(stdout);
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
  for (int i = 1; i < argc; i++) {
    const std::string arg = argv[i];
    if (arg == "--quick") {
      options.quick = true;
      options.width = 256;
      options.height = 192;
      options.runs = 1;
    } else if (arg == "--runs" && i + 1 < argc) {
      options.runs = std::max(1, std::atoi(argv[++i]));
    } else {
      std::fprintf(stderr,
          "usage: prism-bench-volumes [--quick] [--runs N]\n"
          "  frame times of raycast (majorant grid vs the reference marcher)"
          " and pathtracer\n  on 128^3 and 256^3 structuredRegular fields and"
          " a ~1M-cell unstructured mesh\n");
      return 2;
    }
  }
  std::printf("%ux%u, median of %d frames\n",
      options.width,
      options.height,
      options.runs);
  Bench bench(options);
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
