// prism-bench-convergence: how fast the path tracer reaches a clean image.
// Each scene (ConvergenceScenes.h) is accumulated frame by frame; at every
// power of two samples per pixel its RMSE against a high-sample reference
// of its own (computed once, cached in the build tree) is printed with the
// wall and CPU time spent so far, then the log-log slope of error over
// samples and the time to reach fixed RMSE levels, as medians over runs.
// CPU seconds beside wall seconds show what idle threads cost. With
// --error-threshold T the renderer samples adaptively (errorThreshold) and
// the mean samples per pixel actually taken are printed too: reaching a
// level with fewer of them than a uniform run is what adaptivity buys.
// --samples-per-call N takes N samples per anariRenderFrame (the renderer's
// pixelSamples, as prism-render --spp does), so no thread waits at a
// sample's end; the frame's numSamples says how many it holds, so a device
// without pixelSamples is measured too (one sample a call).
// Never a test: it prints.
// The reference is rendered with another renderer `seed`: independent
// sequences. A reference continuing the measured samples' own sequence
// shares their first N samples and so scores their error too low.
#include "ConvergenceScenes.h"

#include <anari/anari.h>
#include <sys/resource.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

struct Options
{
  uint32_t width{512}, height{512};
  uint32_t maxSamples{256};
  uint32_t referenceSamples{4096};
  int runs{3};
  int maxPathLength{8};
  float errorThreshold{0.f}; // of the measured runs; 0: uniform
  int32_t samplesPerCall{1}; // the renderer's pixelSamples
  std::string cache; // folder for the reference; default beside the binary
  std::vector<std::string> scenes; // default: all of them
};

const float kLevels[] = {0.05f, 0.02f, 0.015f, 0.01f};
// The renderer seed of the measured images (the default) and the
// reference's.
constexpr int32_t kMeasuredSeed = 0, kReferenceSeed = 1;

class Renderer
{
 public:
  Renderer(const Options &options, const std::string &sceneName)
      : m_options(options)
  {
    m_library = anariLoadLibrary("prism", nullptr, nullptr);
    if (!m_library) {
      std::fprintf(stderr, "cannot load the prism library\n");
      std::exit(1);
    }
    m_device = anariNewDevice(m_library, "default");
    std::string error;
    m_scene = prism::bench::buildConvergenceScene(m_device, sceneName, error);
    if (!m_scene.world) {
      std::fprintf(stderr, "%s: %s\n", sceneName.c_str(), error.c_str());
      std::exit(1);
    }
    m_camera = anariNewCamera(m_device, "perspective");
    const auto &c = m_scene.camera;
    const float direction[3] = {
        c.at[0] - c.eye[0], c.at[1] - c.eye[1], c.at[2] - c.eye[2]};
    const float fovy = c.fovyDegrees * 3.14159265f / 180.f;
    const float aspect = float(options.width) / float(options.height);
    anariSetParameter(
        m_device, m_camera, "position", ANARI_FLOAT32_VEC3, c.eye.data());
    anariSetParameter(
        m_device, m_camera, "direction", ANARI_FLOAT32_VEC3, direction);
    anariSetParameter(
        m_device, m_camera, "up", ANARI_FLOAT32_VEC3, c.up.data());
    anariSetParameter(m_device, m_camera, "fovy", ANARI_FLOAT32, &fovy);
    anariSetParameter(m_device, m_camera, "aspect", ANARI_FLOAT32, &aspect);
    anariCommitParameters(m_device, m_camera);
    m_renderer = anariNewRenderer(m_device, "pathtracer");
    anariSetParameter(m_device,
        m_renderer,
        "maxPathLength",
        ANARI_INT32,
        &options.maxPathLength);
    if (options.samplesPerCall > 1)
      anariSetParameter(m_device,
          m_renderer,
          "pixelSamples",
          ANARI_INT32,
          &options.samplesPerCall);
    anariCommitParameters(m_device, m_renderer);
  }
  // Later frames draw their samples from the sequences of this seed,
  // stopping tiles at `errorThreshold` (0: every pixel every sample).
  void useSeed(int32_t seed, float errorThreshold) const
  {
    anariSetParameter(m_device, m_renderer, "seed", ANARI_INT32, &seed);
    anariSetParameter(
        m_device, m_renderer, "errorThreshold", ANARI_FLOAT32, &errorThreshold);
    anariCommitParameters(m_device, m_renderer);
  }
  // The pixels the frame's next sample will take (adaptive sampling).
  uint64_t activePixels(ANARIFrame frame) const
  {
    uint64_t pixels = 0;
    anariGetProperty(m_device,
        frame,
        "activePixels",
        ANARI_UINT64,
        &pixels,
        sizeof(pixels),
        ANARI_WAIT);
    return pixels;
  }
  // The samples per pixel the frame holds; `otherwise` if the device does
  // not say.
  uint32_t numSamples(ANARIFrame frame, uint32_t otherwise) const
  {
    uint32_t samples = 0;
    if (!anariGetProperty(m_device,
            frame,
            "numSamples",
            ANARI_UINT32,
            &samples,
            sizeof(samples),
            ANARI_WAIT))
      return otherwise;
    return samples;
  }
  ~Renderer()
  {
    for (ANARIObject o : {(ANARIObject)m_camera, (ANARIObject)m_renderer})
      anariRelease(m_device, o);
    prism::scenes::releaseScene(m_device, m_scene);
    anariRelease(m_device, m_device);
    anariUnloadLibrary(m_library);
  }

  // A fresh accumulating frame (its first sample restarts the average).
  ANARIFrame newFrame() const
  {
    ANARIFrame frame = anariNewFrame(m_device);
    const uint32_t size[2] = {m_options.width, m_options.height};
    const ANARIDataType color = ANARI_FLOAT32_VEC4;
    const uint8_t on = 1;
    anariSetParameter(m_device, frame, "size", ANARI_UINT32_VEC2, size);
    anariSetParameter(
        m_device, frame, "channel.color", ANARI_DATA_TYPE, &color);
    anariSetParameter(m_device, frame, "accumulation", ANARI_BOOL, &on);
    anariSetParameter(m_device, frame, "world", ANARI_WORLD, &m_scene.world);
    anariSetParameter(m_device, frame, "camera", ANARI_CAMERA, &m_camera);
    anariSetParameter(m_device, frame, "renderer", ANARI_RENDERER, &m_renderer);
    anariCommitParameters(m_device, frame);
    return frame;
  }
  // Renders one more call's samples; returns its wall time in seconds and
  // adds the CPU seconds of all threads to `cpuSeconds`.
  double addSamples(ANARIFrame frame, double &cpuSeconds) const
  {
    const double cpuStart = processCpuSeconds();
    const auto start = Clock::now();
    anariRenderFrame(m_device, frame);
    anariFrameReady(m_device, frame, ANARI_WAIT);
    const double wall =
        std::chrono::duration<double>(Clock::now() - start).count();
    cpuSeconds += processCpuSeconds() - cpuStart;
    return wall;
  }
  static double processCpuSeconds()
  {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const auto seconds = [](const timeval &t) {
      return double(t.tv_sec) + 1e-6 * double(t.tv_usec);
    };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
  }
  std::vector<float> color(ANARIFrame frame) const
  {
    uint32_t w = 0, h = 0;
    ANARIDataType type = ANARI_UNKNOWN;
    auto *pixels = (const float *)anariMapFrame(
        m_device, frame, "channel.color", &w, &h, &type);
    std::vector<float> out;
    if (pixels && type == ANARI_FLOAT32_VEC4)
      out.assign(pixels, pixels + size_t(w) * h * 4);
    anariUnmapFrame(m_device, frame, "channel.color");
    return out;
  }
  void release(ANARIFrame frame) const
  {
    anariRelease(m_device, frame);
  }

 private:
  const Options &m_options;
  ANARILibrary m_library{nullptr};
  ANARIDevice m_device{nullptr};
  prism::scenes::Scene m_scene;
  ANARICamera m_camera{nullptr};
  ANARIRenderer m_renderer{nullptr};
};

double rmse(const std::vector<float> &a, const std::vector<float> &b)
{
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); i += 4)
    for (int c = 0; c < 3; c++) {
      const double d = double(a[i + c]) - double(b[i + c]);
      sum += d * d;
    }
  return std::sqrt(sum / (3.0 * double(a.size() / 4)));
}

std::vector<float> reference(const Renderer &renderer,
    const Options &options,
    const std::string &sceneName,
    const char *argv0)
{
  std::filesystem::path folder = options.cache;
  if (folder.empty())
    folder = std::filesystem::absolute(argv0).parent_path() / "bench-cache";
  const std::filesystem::path path =
      folder
      / (sceneName + "-" + std::to_string(options.width) + "x"
          + std::to_string(options.height) + "-depth"
          + std::to_string(options.maxPathLength) + "-"
          + std::to_string(options.referenceSamples) + "spp-seed"
          + std::to_string(kReferenceSeed) + ".f32");
  const size_t floats = size_t(options.width) * options.height * 4;
  std::vector<float> image(floats);
  std::ifstream in(path, std::ios::binary);
  if (in.read((char *)image.data(), std::streamsize(floats * sizeof(float)))) {
    std::printf("reference: %s (cached)\n", path.c_str());
    return image;
  }
  std::printf("reference: rendering %u spp once into %s ...\n",
      options.referenceSamples,
      path.c_str());
  std::fflush(stdout);
  renderer.useSeed(kReferenceSeed, 0.f);
  ANARIFrame frame = renderer.newFrame();
  double cpuSeconds = 0.0;
  for (uint32_t s = 0; s < options.referenceSamples;) {
    renderer.addSamples(frame, cpuSeconds);
    s = renderer.numSamples(frame, s + 1);
  }
  image = renderer.color(frame);
  renderer.release(frame);
  std::filesystem::create_directories(folder);
  std::ofstream(path, std::ios::binary)
      .write((const char *)image.data(),
          std::streamsize(image.size() * sizeof(float)));
  return image;
}

struct Point
{
  uint32_t samples;
  double error, seconds, cpuSeconds;
  double meanSamples; // per pixel, taken: fewer than `samples` if adaptive
};

// Least-squares slope of log(error) over log(samples), from 4 spp on
// (the first samples are dominated by the pixel-centre sample).
double slope(const std::vector<Point> &points)
{
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (const Point &p : points) {
    if (p.samples < 4)
      continue;
    const double x = std::log(double(p.samples)), y = std::log(p.error);
    sx += x, sy += y, sxx += x * x, sxy += x * y, n++;
  }
  return n > 1 ? (n * sxy - sx * sy) / (n * sxx - sx * sx) : 0.0;
}

// Seconds (of `clock`: wall or CPU) until the error first falls to
// `level`, interpolated log-log between the measured points; negative if
// never.
double timeTo(
    const std::vector<Point> &points, double level, double Point::*clock)
{
  for (size_t i = 0; i < points.size(); i++) {
    if (points[i].error > level)
      continue;
    if (i == 0)
      return points[0].*clock;
    const Point &a = points[i - 1], &b = points[i];
    const double f = std::log(a.error / level) / std::log(a.error / b.error);
    return std::exp(std::log(a.*clock) + f * std::log(b.*clock / a.*clock));
  }
  return -1.0;
}

double median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  return values.empty() ? 0.0 : values[values.size() / 2];
}

Options parseOptions(int argc, char **argv)
{
  Options options;
  for (int i = 1; i < argc; i++) {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--quick") {
      options.width = options.height = 128;
      options.maxSamples = 256;
      options.referenceSamples = 1024;
      options.runs = 1;
    } else if (arg == "--runs" && hasValue) {
      options.runs = std::max(1, std::atoi(argv[++i]));
    } else if (arg == "--max-spp" && hasValue) {
      options.maxSamples = uint32_t(std::max(1, std::atoi(argv[++i])));
    } else if (arg == "--reference-spp" && hasValue) {
      options.referenceSamples = uint32_t(std::max(16, std::atoi(argv[++i])));
    } else if (arg == "--max-path-length" && hasValue) {
      options.maxPathLength = std::max(1, std::atoi(argv[++i]));
    } else if (arg == "--error-threshold" && hasValue) {
      options.errorThreshold = std::max(0.f, float(std::atof(argv[++i])));
    } else if (arg == "--samples-per-call" && hasValue) {
      options.samplesPerCall = std::clamp(std::atoi(argv[++i]), 1, 65536);
    } else if (arg == "--scene" && hasValue) {
      options.scenes.push_back(argv[++i]);
    } else if (arg == "--cache" && hasValue) {
      options.cache = argv[++i];
    } else if (arg == "--size" && hasValue
               && std::sscanf(
                      argv[i + 1], "%ux%u", &options.width, &options.height)
                      == 2) {
      i++;
    } else {
      std::fprintf(stderr,
          "usage: prism-bench-convergence [--quick] [--runs N] [--size WxH] "
          "[--max-spp N] [--reference-spp N] [--max-path-length N] "
          "[--error-threshold T] [--samples-per-call N] [--scene NAME]... "
          "[--cache FOLDER]\n");
      std::exit(2);
    }
  }
  return options;
}

// Measures one scene: its runs, then the medians.
void measure(
    const Options &options, const std::string &sceneName, const char *argv0)
{
  std::printf(
      "\n== %s %ux%u, maxPathLength %d, errorThreshold %g, %d samples a "
      "call\n",
      sceneName.c_str(),
      options.width,
      options.height,
      options.maxPathLength,
      double(options.errorThreshold),
      options.samplesPerCall);
  const Renderer renderer(options, sceneName);
  const std::vector<float> ref = reference(renderer, options, sceneName, argv0);
  renderer.useSeed(kMeasuredSeed, options.errorThreshold);
  const double pixels = double(options.width) * options.height;

  std::vector<double> slopes;
  std::vector<std::vector<double>> times(std::size(kLevels)),
      cpuTimes(std::size(kLevels)), samplesTo(std::size(kLevels));
  for (int run = 0; run < options.runs; run++) {
    std::vector<Point> points;
    ANARIFrame frame = renderer.newFrame();
    double seconds = 0.0, cpuSeconds = 0.0, taken = 0.0;
    uint64_t active = uint64_t(pixels);
    for (uint32_t s = 0; s < options.maxSamples;) {
      seconds += renderer.addSamples(frame, cpuSeconds);
      const uint32_t before = s;
      s = std::max(renderer.numSamples(frame, s + 1), s + 1);
      // Pixels active before a call of several samples may stop within
      // it: then this overcounts what was taken.
      taken += double(active) * double(s - before);
      if (options.errorThreshold > 0.f)
        active = renderer.activePixels(frame);
      // A point where the count reached or passed a power of two.
      if (std::bit_floor(s) > before)
        points.push_back({s,
            rmse(renderer.color(frame), ref),
            seconds,
            cpuSeconds,
            taken / pixels});
    }
    renderer.release(frame);
    std::printf(
        "run %d\n  spp      RMSE    seconds  CPU seconds  mean spp "
        "taken\n",
        run + 1);
    for (const Point &p : points)
      std::printf("%5u  %8.5f  %9.3f  %11.3f  %14.1f\n",
          p.samples,
          p.error,
          p.seconds,
          p.cpuSeconds,
          p.meanSamples);
    slopes.push_back(slope(points));
    for (size_t l = 0; l < std::size(kLevels); l++) {
      times[l].push_back(timeTo(points, kLevels[l], &Point::seconds));
      cpuTimes[l].push_back(timeTo(points, kLevels[l], &Point::cpuSeconds));
      samplesTo[l].push_back(timeTo(points, kLevels[l], &Point::meanSamples));
    }
  }
  std::printf("%s, median of %d runs: slope %.3f (error ~ N^%.3f)\n",
      sceneName.c_str(),
      options.runs,
      median(slopes),
      median(slopes));
  for (size_t l = 0; l < std::size(kLevels); l++) {
    const double t = median(times[l]), cpu = median(cpuTimes[l]),
                 spp = median(samplesTo[l]);
    if (t < 0)
      std::printf("  RMSE %.3f: not reached within %u spp\n",
          kLevels[l],
          options.maxSamples);
    else
      std::printf(
          "  RMSE %.3f reached in %.2f s wall, %.2f s CPU, %.1f spp taken\n",
          kLevels[l],
          t,
          cpu,
          spp);
  }
}

} // namespace

int main(int argc, char **argv)
{
  Options options = parseOptions(argc, argv);
  if (options.scenes.empty())
    options.scenes = prism::bench::convergenceSceneNames();
  std::printf("prism-bench-convergence: %u hardware threads\n",
      std::thread::hardware_concurrency());
  for (const std::string &scene : options.scenes)
    measure(options, scene, argv[0]);
  return 0;
}
