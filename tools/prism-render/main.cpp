// prism-render: renders a scene file or a built-in demo scene with any ANARI
// library (prism by default) and writes the image. See --help.
#include "CameraFraming.h"
#include "Console.h"
#include "DefaultEnvironment.h"
#include "DemoScenes.h"
#include "FrameMemory.h"
#include "FrameOutput.h"
#include "GltfLoader.h"
#include "NanoVdbLoader.h"
#include "NsiScene.h"
#include "ObjLoader.h"
#include "Objects.h"
#include "Options.h"
#include "ProcessShare.h"
#include "Progress.h"
#include "RawVolumeLoader.h"
#include "RendererParameters.h"
#include "VolumeStyle.h"

#include <anari/anari.h>

#include <unistd.h>

#ifdef PRISM_RENDER_HAS_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <memory>
#include <mutex>
#include <numbers>
#include <set>
#include <thread>

namespace prism::render {
namespace {

// std::array vectors: their operators live in prism::scenes, out of ADL's
// reach.
using scenes::operator+;
using scenes::operator-;
using scenes::operator*;

constexpr int kExitFailure = 1; // the scene, the device or the output failed
constexpr int kExitUsage = 2;   // the command line asks for the impossible
constexpr int kExitInterrupted = 128 + SIGINT; // Ctrl-C, as shells report it

// Set by the SIGINT handler; the render loop stops at the next check.
volatile std::sig_atomic_t g_interrupted = 0;
std::atomic<long long> g_firstInterruptMs{0};

extern "C" void onInterrupt(int)
{
  // Only async-signal-safe calls here.
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  const long long ms = now.tv_sec * 1000ll + now.tv_nsec / 1000000;
  if (!g_interrupted) {
    g_firstInterruptMs = ms;
    g_interrupted = 1;
  } else if (ms - g_firstInterruptMs >= 1000) {
    // Ctrl-C again, a second later: end the process at once. (Sooner, it
    // is the same Ctrl-C delivered twice, as wrappers that signal both the
    // process and its group do.)
    _exit(kExitInterrupted);
  }
}

// Counts the frames the device reports done (KHR_FRAME_COMPLETION_CALLBACK).
// NOTE: onFrame runs on a device thread.
class FrameCompletions
{
 public:
  static void onFrame(const void *user, ANARIDevice, ANARIFrame)
  {
    auto *self = (FrameCompletions *)user;
    {
      std::lock_guard lock(self->m_mutex);
      self->m_done++;
    }
    self->m_changed.notify_all();
  }
  // Whether `count` frames are done, waiting at most `timeout` for it.
  bool waitFor(uint64_t count, std::chrono::milliseconds timeout)
  {
    std::unique_lock lock(m_mutex);
    return m_changed.wait_for(lock, timeout, [&] { return m_done >= count; });
  }

 private:
  std::mutex m_mutex;
  std::condition_variable m_changed;
  uint64_t m_done{0};
};

struct StatusState
{
  bool verbose{false};
  std::atomic<int> errors{0};
};

const char *severityName(ANARIStatusSeverity severity)
{
  switch (severity) {
  case ANARI_SEVERITY_FATAL_ERROR:
    return "fatal error";
  case ANARI_SEVERITY_ERROR:
    return "error";
  case ANARI_SEVERITY_WARNING:
    return "warning";
  case ANARI_SEVERITY_PERFORMANCE_WARNING:
    return "performance warning";
  case ANARI_SEVERITY_INFO:
    return "info";
  default:
    return "debug";
  }
}

// Device messages with their severity; warnings and worse always, the rest
// with --verbose. NOTE: called from device threads.
void statusCallback(const void *userPtr,
    ANARIDevice,
    ANARIObject,
    ANARIDataType,
    ANARIStatusSeverity severity,
    ANARIStatusCode,
    const char *message)
{
  auto *state = (StatusState *)userPtr;
  if (severity <= ANARI_SEVERITY_ERROR)
    state->errors++;
  if (severity <= ANARI_SEVERITY_WARNING || state->verbose)
    console::message(std::string("device ") + severityName(severity) + ": "
                     + (message ? message : ""));
}

enum class SourceKind { Demo, Gltf, Obj, Raw, NanoVdb };

std::string lowerExtension(const std::string &path)
{
  std::string e = std::filesystem::path(path).extension().string();
  for (char &c : e)
    c = char(std::tolower((unsigned char)c));
  return e;
}

std::string joinList(const char **list)
{
  std::string joined;
  for (; list && *list; ++list)
    joined += std::string(joined.empty() ? "" : ", ") + *list;
  return joined.empty() ? "none" : joined;
}

bool contains(const char **list, const std::string &name)
{
  for (; list && *list; ++list)
    if (name == *list)
      return true;
  return false;
}

// The device's extensions: the library's list for the subtype plus the
// device's `extension` property, whichever the device fills in.
std::set<std::string> deviceExtensions(
    ANARILibrary library, ANARIDevice device, const std::string &subtype)
{
  std::set<std::string> extensions;
  for (const char **e = anariGetDeviceExtensions(library, subtype.c_str());
       e && *e;
       ++e)
    extensions.insert(*e);
  const char **property = nullptr;
  if (anariGetProperty(device,
          device,
          "extension",
          ANARI_STRING_LIST,
          &property,
          sizeof(property),
          ANARI_WAIT))
    for (; property && *property; ++property)
      extensions.insert(*property);
  return extensions;
}

void listDemos()
{
  for (const scenes::DemoScene &demo : scenes::demoScenes())
    std::printf("demo:%-18s %s\n", demo.name, demo.description);
}

// Everything the run creates, released in reverse order however it ends.
struct Session
{
  StatusState status;
  ANARILibrary library{nullptr};
  ANARIDevice device{nullptr};
  std::vector<ANARIObject> objects;

  ~Session()
  {
    if (device) {
      for (auto it = objects.rbegin(); it != objects.rend(); ++it)
        if (*it)
          anariRelease(device, *it);
      anariRelease(device, device);
    }
    if (library)
      anariUnloadLibrary(library);
  }
  template <typename T>
  T keep(T object)
  {
    objects.push_back(object);
    return object;
  }
};

int fail(const std::string &message, int code = kExitFailure)
{
  console::error(message);
  return code;
}

int run(int argc, char **argv)
{
  // Ctrl-C from here on: the run stops, says so and writes nothing.
  std::signal(SIGINT, onInterrupt);
  const ParseResult parsed = parseOptions(argc, argv);
  if (!parsed.ok()) {
    console::error(parsed.error);
    console::message("try 'prism-render --help'");
    return kExitUsage;
  }
  const Options &options = parsed.options;
  if (options.help) {
    std::fputs(helpText().c_str(), stdout);
    return 0;
  }
  if (options.listDemos) {
    listDemos();
    return 0;
  }
  if (const std::string why = whyFrameDoesNotFit(options); !why.empty())
    return fail(why);

  // What to load, checked before any device is touched.
  SourceKind kind = SourceKind::Demo;
  const scenes::DemoScene *demo = nullptr;
  std::string sceneName;
  RawVolumeFormat rawFormat;
  if (options.scene.starts_with("demo:")) {
    sceneName = options.scene.substr(5);
    demo = scenes::findDemoScene(sceneName);
    if (!demo) {
      std::string names;
      for (const scenes::DemoScene &d : scenes::demoScenes())
        names += std::string(names.empty() ? "" : ", ") + d.name;
      return fail(
          "unknown demo scene '" + sceneName + "' (demos: " + names + ")",
          kExitUsage);
    }
  } else if (isNsiScene(options.scene)) {
    // An NSI stream names its own camera, resolution and output files.
    return renderNsiScene(options);
  } else {
    const std::string extension = lowerExtension(options.scene);
    if (extension == ".gltf" || extension == ".glb")
      kind = SourceKind::Gltf;
    else if (extension == ".obj")
      kind = SourceKind::Obj;
    else if (extension == ".raw")
      kind = SourceKind::Raw;
    else if (extension == ".nvdb")
      kind = SourceKind::NanoVdb;
    else
      return fail("'" + options.scene
              + "': unknown scene file type (expected .gltf, .glb, .obj, "
                ".raw, .nvdb, an NSI stream or demo:<name>)",
          kExitUsage);
    std::error_code ec;
    if (std::filesystem::is_directory(options.scene, ec))
      return fail(
          "cannot read scene '" + options.scene + "': it is a directory");
    std::FILE *file = std::fopen(options.scene.c_str(), "rb");
    if (!file)
      return fail(
          "cannot open scene '" + options.scene + "': " + std::strerror(errno));
    std::fclose(file);
    sceneName = std::filesystem::path(options.scene).stem().string();
    if (kind == SourceKind::Raw) {
      const std::string error =
          resolveRawFormat(options.scene, options, rawFormat);
      if (!error.empty())
        return fail(error, kExitUsage);
    }
  }
  const std::string colorPath =
      options.output.empty() ? sceneName + ".png" : options.output;
  const std::vector<ChannelRequest> requests =
      channelRequests(options, colorPath);
  for (const ChannelRequest &r : requests) {
    const std::filesystem::path parent =
        std::filesystem::path(r.path).parent_path();
    std::error_code ec;
    if (!parent.empty() && !std::filesystem::is_directory(parent, ec))
      return fail("cannot write '" + r.path + "': folder '" + parent.string()
                  + "' does not exist");
  }

#ifdef PRISM_RENDER_HAS_TBB
  // TBB-based devices (prism among them) share this process's TBB: the
  // limit applies to every arena they create.
  std::unique_ptr<tbb::global_control> threadLimit;
  if (options.threads > 0)
    threadLimit = std::make_unique<tbb::global_control>(
        tbb::global_control::max_allowed_parallelism, options.threads);
#endif

  auto interrupted = []() {
    return g_interrupted != 0;
  };
  const std::string interruptedMessage =
      "interrupted (Ctrl-C); no image written";

  Session session;
  session.status.verbose = options.verbose;
  if (!options.traceFile.empty()) {
    // libanari then loads the debug layer around the library, recording.
    setenv("ANARI_DEBUG_LAYER", "1", 1);
    setenv("ANARI_DEBUG_TRACE", options.traceFile.c_str(), 1);
  }
  session.library = anariLoadLibrary(
      options.library.c_str(), statusCallback, &session.status);
  if (!session.library)
    return fail("cannot load ANARI library '" + options.library
                    + "' (libanari_library_" + options.library + ".so)",
        kExitUsage);
  const char **deviceSubtypes = anariGetDeviceSubtypes(session.library);
  if (deviceSubtypes && *deviceSubtypes && options.deviceSubtype != "default"
      && !contains(deviceSubtypes, options.deviceSubtype))
    return fail("library '" + options.library + "' has no device '"
                    + options.deviceSubtype
                    + "' (devices: " + joinList(deviceSubtypes) + ")",
        kExitUsage);
  session.device =
      anariNewDevice(session.library, options.deviceSubtype.c_str());
  if (!session.device)
    return fail("library '" + options.library + "' could not create device '"
                + options.deviceSubtype + "'");
  ANARIDevice device = session.device;
  const std::set<std::string> extensions =
      deviceExtensions(session.library, device, options.deviceSubtype);
  auto has = [&](const char *e) {
    return extensions.count(e) > 0;
  };

  if (options.threads > 0) {
    const auto *parameters = (const ANARIParameter *)anariGetObjectInfo(device,
        ANARI_DEVICE,
        options.deviceSubtype.c_str(),
        "parameter",
        ANARI_PARAMETER_LIST);
    for (; parameters && parameters->name; ++parameters)
      if (std::strcmp(parameters->name, "numThreads") == 0) {
        const int32_t threads = int32_t(options.threads);
        anariSetParameter(device, device, "numThreads", ANARI_INT32, &threads);
        anariCommitParameters(device, device);
        break;
      }
  }

  const char **renderers = anariGetObjectSubtypes(device, ANARI_RENDERER);
  if (options.renderer != "default" && renderers && *renderers
      && !contains(renderers, options.renderer))
    return fail("the device has no renderer '" + options.renderer
                    + "' (renderers: " + joinList(renderers) + ")",
        kExitUsage);
  for (const ChannelRequest &r : requests) {
    const char *needed = channelExtension(r);
    if (needed && !has(needed))
      return fail(std::string("this device does not implement ") + (needed + 6)
                  + ", so " + r.channel + " cannot be written to '" + r.path
                  + "'");
  }

  // The scene. Device errors from here on (a file the loader passed but
  // the device refused, such as a NanoVDB tree it found corrupt) fail the
  // run: the image would be missing what the file holds.
  if (options.mpiPartition) {
    const std::optional<scenes::Partition> share =
        has("ANARI_KHR_DATA_PARALLEL_MPI") ? processShare(device)
                                           : std::nullopt;
    if (share) {
      scenes::setPartition(*share);
      if (!options.quiet)
        console::message("process " + std::to_string(share->part) + " of "
                         + std::to_string(share->parts)
                         + " builds its share of the scene");
    } else
      console::warning(
          "--mpi-partition needs a data-parallel device (prism_mpi); the "
          "whole scene is built");
  }
  const int errorsBeforeLoad = session.status.errors.load();
  LoadResult loaded;
  const auto loadStart = std::chrono::steady_clock::now();
  switch (kind) {
  case SourceKind::Demo:
    if (options.transferFunction.given && demo->buildWithVolumeStyle) {
      scenes::TransferFunction style = demo->volumeStyle();
      applyTransferFunctionOptions(options.transferFunction, style);
      loaded.scene = demo->buildWithVolumeStyle(device, style);
    } else {
      loaded.scene = demo->build(device);
    }
    break;
  case SourceKind::Gltf: {
    GltfOptions gltf;
    gltf.cameraIndex = options.cameraIndex;
    loaded = loadGltf(device, options.scene, gltf);
    break;
  }
  case SourceKind::Obj:
    loaded = loadObj(device, options.scene);
    break;
  case SourceKind::Raw:
    loaded = loadRawVolume(
        device, options.scene, rawFormat, options.transferFunction);
    break;
  case SourceKind::NanoVdb:
    loaded = loadNanoVdb(
        device, options.scene, options.gridName, options.transferFunction);
    break;
  }
  scenes::Scene &scene = loaded.scene;
  session.keep(scene.world);
  if (interrupted())
    return fail(interruptedMessage, kExitInterrupted);
  for (const std::string &note : scene.notes)
    console::warning(note);
  if (!loaded.ok())
    return fail(loaded.error);
  if (options.cameraIndex >= 0 && kind != SourceKind::Gltf)
    console::warning("--camera only applies to glTF files; ignored");
  const bool hasVolume = kind == SourceKind::Raw || kind == SourceKind::NanoVdb
                         || (demo && demo->buildWithVolumeStyle);
  if (options.transferFunction.given && !hasVolume)
    console::warning(
        "--tf-* options only apply to volumes (.raw, .nvdb, demo:volume); "
        "ignored");
  if (!options.gridName.empty() && kind != SourceKind::NanoVdb)
    console::warning("--grid only applies to NanoVDB files; ignored");

  // Scene files without lights would render black with the path tracer:
  // light them the way glTF viewers do, and say so.
  const bool explicitEnvironment = options.environment != "studio";
  const bool hdri = scenes::hasSubtype(device, ANARI_LIGHT, "hdri");
  if (!scene.emitsLight && options.environment != "none" && !hdri) {
    console::warning(
        "the scene has no lights and the device has no hdri light "
        "(KHR_LIGHT_HDRI) to light it with; it renders unlit");
  } else if (!scene.emitsLight && options.environment != "none") {
    const EnvironmentChoice choice{options.environment,
        options.environmentIntensity,
        options.environmentRotateDegrees};
    const scenes::Vec3 up = options.up.value_or(
        scene.camera.valid ? scene.camera.up : scenes::Vec3{0.f, 1.f, 0.f});
    const Environment environment = makeEnvironment(device, choice, up);
    if (!environment.error.empty())
      return fail(environment.error);
    session.keep(environment.light);
    lightWorldWith(device, scene.world, environment.light);
    if (!options.quiet)
      console::message("the scene has no lights; lit by "
                       + environment.description + " (--env none: unlit)");
  } else if (explicitEnvironment && scene.emitsLight) {
    console::warning(
        "the scene has lights of its own; --env applies only to scenes "
        "without any");
  }
  const double loadSeconds = std::chrono::duration<double>(
      std::chrono::steady_clock::now() - loadStart)
                                 .count();

  // The renderer.
  ANARIRenderer renderer =
      session.keep(anariNewRenderer(device, options.renderer.c_str()));
  const bool explicitBackground = options.background.has_value();
  if (explicitBackground || scene.hasBackground) {
    const std::array<float, 4> background =
        options.background.value_or(scene.background);
    if (rendererDeclares(device, options.renderer, "background")
        != Declared::No)
      anariSetParameter(device,
          renderer,
          "background",
          ANARI_FLOAT32_VEC4,
          background.data());
    else if (explicitBackground)
      console::warning(
          "the renderer has no 'background'; --background "
          "ignored");
  }
  if (options.denoise) {
    if (has("ANARI_KHR_RENDERER_DENOISE")) {
      const int32_t on = 1;
      anariSetParameter(device, renderer, "denoise", ANARI_BOOL, &on);
    } else {
      console::warning(
          "the device does not implement KHR_RENDERER_DENOISE; "
          "--denoise ignored");
    }
  }
  const ParameterOutcome parameters = setRendererParameters(
      device, renderer, options.renderer, options.rendererParameters);
  for (const std::string &w : parameters.warnings)
    console::warning(w);
  if (!parameters.error.empty())
    return fail(parameters.error, kExitUsage);
  anariCommitParameters(device, renderer);

  // The camera: the world's bounds as the device sees them, else as the
  // builder computed them.
  scenes::Bounds bounds;
  float box[6] = {std::numeric_limits<float>::infinity(), 0, 0, 0, 0, 0};
  if (anariGetProperty(device,
          scene.world,
          "bounds",
          ANARI_FLOAT32_BOX3,
          box,
          sizeof(box),
          ANARI_WAIT)
      && std::all_of(box, box + 6, [](float v) { return std::isfinite(v); })) {
    bounds.extend(scenes::Vec3{box[0], box[1], box[2]});
    bounds.extend(scenes::Vec3{box[3], box[4], box[5]});
  }
  if (bounds.empty())
    bounds = scene.bounds;
  // The bounds query waited for every commit, so the device has judged the
  // scene by now.
  if (session.status.errors.load() > errorsBeforeLoad)
    return fail("the device refused the scene '" + options.scene
                + "' (see above); no image written");
  const float aspect = float(options.width) / float(options.height);
  const CameraSetup view = frameCamera(scene.camera, bounds, aspect, options);
  // Ray tracers reject rays from beyond ~1e18; refuse such a camera here
  // rather than hand the device rays it cannot trace.
  auto usable = [](const scenes::Vec3 &v) {
    return std::all_of(v.begin(), v.end(), [](float c) {
      return std::isfinite(c) && std::fabs(c) <= 1e15f;
    });
  };
  if (!usable(view.eye) || !usable(view.at) || !usable(view.up)
      || !(scenes::length(view.at - view.eye) > 0.f)) {
    char where[128];
    std::snprintf(where,
        sizeof(where),
        "%g,%g,%g",
        view.eye[0],
        view.eye[1],
        view.eye[2]);
    return fail(std::string("the camera is out of range (eye ") + where
                + "); give --eye and --at");
  }
  ANARICamera camera = session.keep(anariNewCamera(
      device, view.orthographic ? "orthographic" : "perspective"));
  scenes::setVec3(device, camera, "position", view.eye);
  scenes::setVec3(
      device, camera, "direction", scenes::normalize(view.at - view.eye));
  scenes::setVec3(device, camera, "up", view.up);
  scenes::setFloat(device, camera, "aspect", aspect);
  if (view.orthographic)
    scenes::setFloat(device, camera, "height", view.height);
  else
    scenes::setFloat(device,
        camera,
        "fovy",
        view.fovyDegrees * std::numbers::pi_v<float> / 180.f);
  anariCommitParameters(device, camera);
  if (options.verbose) {
    char text[256];
    std::snprintf(text,
        sizeof(text),
        "camera %s eye %g,%g,%g at %g,%g,%g up %g,%g,%g fovy %g",
        view.framed ? "(framed to the bounds)" : "(from the scene)",
        view.eye[0],
        view.eye[1],
        view.eye[2],
        view.at[0],
        view.at[1],
        view.at[2],
        view.up[0],
        view.up[1],
        view.up[2],
        view.fovyDegrees);
    console::message(text);
  }

  // The frame.
  ANARIFrame frame = session.keep(anariNewFrame(device));
  const uint32_t size[2] = {options.width, options.height};
  anariSetParameter(device, frame, "size", ANARI_UINT32_VEC2, size);
  scenes::setObject(device, frame, "world", ANARI_WORLD, scene.world);
  scenes::setObject(device, frame, "renderer", ANARI_RENDERER, renderer);
  scenes::setObject(device, frame, "camera", ANARI_CAMERA, camera);
  for (const ChannelRequest &r : requests)
    anariSetParameter(
        device, frame, r.channel.c_str(), ANARI_DATA_TYPE, &r.type);
  uint32_t frames = 1;
  if (options.samplesPerPixel > 1) {
    if (has("ANARI_KHR_FRAME_ACCUMULATION")) {
      const int32_t on = 1;
      anariSetParameter(device, frame, "accumulation", ANARI_BOOL, &on);
      frames = options.samplesPerPixel;
    } else {
      console::warning(
          "the device does not implement frame accumulation "
          "(KHR_FRAME_ACCUMULATION); rendering 1 sample per "
          "pixel instead of "
          + std::to_string(options.samplesPerPixel));
    }
  }
  // Devices that call back when a frame is done let the loop wait for that
  // and still notice Ctrl-C; bench runs wait plainly, to time frames alone
  // (Ctrl-C stops them between frames).
  FrameCompletions completions;
  const bool watchCompletion =
      options.benchFrames == 0 && has("ANARI_KHR_FRAME_COMPLETION_CALLBACK");
  if (watchCompletion) {
    const ANARIFrameCompletionCallback callback = &FrameCompletions::onFrame;
    anariSetParameter(device,
        frame,
        "frameCompletionCallback",
        ANARI_FRAME_COMPLETION_CALLBACK,
        &callback);
    // VOID_POINTER values are passed as the pointer itself (spec).
    anariSetParameter(device,
        frame,
        "frameCompletionCallbackUserData",
        ANARI_VOID_POINTER,
        &completions);
  }
  anariCommitParameters(device, frame);

  const bool showProgress = !options.quiet && console::stderrIsTerminal();
  const int errorsBeforeRender = session.status.errors.load();
  double renderSeconds = 0.0;
  std::vector<double> frameSeconds;
  if (options.benchFrames > 0)
    frames = options.benchFrames;
  // Rays the renderer traced (its "raysTraced" property, where it has one).
  auto raysTraced = [&](uint64_t &rays) {
    return anariGetProperty(device,
               renderer,
               "raysTraced",
               ANARI_UINT64,
               &rays,
               sizeof(rays),
               ANARI_NO_WAIT)
           != 0;
  };
  uint64_t raysBefore = 0;
  const bool countsRays = raysTraced(raysBefore);
  {
    Progress progress(
        showProgress, frames, options.benchFrames > 0 ? "frames" : "samples");
    const auto start = std::chrono::steady_clock::now();
    for (uint32_t i = 0; i < frames && !interrupted(); i++) {
      const auto frameStart = std::chrono::steady_clock::now();
      anariRenderFrame(device, frame);
      if (watchCompletion) {
        // Woken by the device when the frame is done, and every 20 ms to
        // see whether Ctrl-C came or the progress bar should move.
        while (!completions.waitFor(i + 1, std::chrono::milliseconds(20))) {
          if (interrupted()) {
            anariDiscardFrame(device, frame);
            break;
          }
          if (!showProgress)
            continue;
          float partial = 0.f;
          anariGetProperty(device,
              frame,
              "renderProgress",
              ANARI_FLOAT32,
              &partial,
              sizeof(partial),
              ANARI_NO_WAIT);
          progress.update(i + std::clamp(double(partial), 0.0, 1.0));
        }
        anariFrameReady(device, frame, ANARI_WAIT);
        if (showProgress && !interrupted())
          progress.update(i + 1);
      } else if (showProgress) {
        while (!anariFrameReady(device, frame, ANARI_NO_WAIT)) {
          float partial = 0.f;
          anariGetProperty(device,
              frame,
              "renderProgress",
              ANARI_FLOAT32,
              &partial,
              sizeof(partial),
              ANARI_NO_WAIT);
          progress.update(i + std::clamp(double(partial), 0.0, 1.0));
          std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        progress.update(i + 1);
      } else {
        anariFrameReady(device, frame, ANARI_WAIT);
      }
      frameSeconds.push_back(std::chrono::duration<double>(
          std::chrono::steady_clock::now() - frameStart)
                                 .count());
    }
    renderSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
            .count();
    progress.finish();
  }
  if (interrupted())
    return fail(interruptedMessage, kExitInterrupted);
  if (session.status.errors.load() > errorsBeforeRender)
    return fail(
        "the device reported errors while rendering (see above); "
        "no image written");

  // A data-parallel device (KHR_DATA_PARALLEL_MPI) defines the image on
  // rank 0 of the frame's communicator only: the other processes of an
  // `mpirun` write nothing (prism_mpi tells a frame's rank as mpiRank).
  int32_t mpiRank = 0;
  if (has("ANARI_KHR_DATA_PARALLEL_MPI")
      && anariGetProperty(device,
          frame,
          "mpiRank",
          ANARI_INT32,
          &mpiRank,
          sizeof(mpiRank),
          ANARI_NO_WAIT)
      && mpiRank > 0)
    return 0;

  std::vector<OutputImage> images;
  std::vector<std::string> warnings;
  const std::string readError = readChannels(
      device, frame, requests, options.width, options.height, images, warnings);
  for (const std::string &w : warnings)
    console::warning(w);
  if (!readError.empty())
    return fail(readError);
  const std::string writeError = writeImages(images);
  if (!writeError.empty())
    return fail(writeError);

  if (options.benchFrames > 0) {
    std::vector<double> sorted = frameSeconds;
    std::sort(sorted.begin(), sorted.end());
    const double median =
        sorted.size() % 2
            ? sorted[sorted.size() / 2]
            : 0.5 * (sorted[sorted.size() / 2 - 1] + sorted[sorted.size() / 2]);
    std::printf(
        "%s: %u frames of %ux%u, renderer %s: min %.2f ms, median "
        "%.2f ms, max %.2f ms\n",
        options.scene.c_str(),
        unsigned(sorted.size()),
        options.width,
        options.height,
        options.renderer.c_str(),
        sorted.front() * 1e3,
        median * 1e3,
        sorted.back() * 1e3);
    uint64_t raysAfter = 0;
    if (countsRays && raysTraced(raysAfter) && renderSeconds > 0.0) {
      const double rays = double(raysAfter - raysBefore);
      std::printf("%s: %.0f rays traced, %.2f Mrays/s\n",
          options.scene.c_str(),
          rays,
          rays / renderSeconds * 1e-6);
    }
  }
  if (!options.quiet) {
    for (const OutputImage &image : images)
      std::printf("wrote %s (%ux%u)\n",
          image.path.c_str(),
          image.image.width,
          image.image.height);
    std::printf("scene %s in %s, %u frame%s in %s (%u spp)\n",
        options.scene.c_str(),
        formatDuration(loadSeconds).c_str(),
        unsigned(frameSeconds.size()),
        frameSeconds.size() == 1 ? "" : "s",
        formatDuration(renderSeconds).c_str(),
        options.benchFrames > 0 ? 1u : frames);
  }
  return 0;
}

} // namespace
} // namespace prism::render

int main(int argc, char **argv)
{
  try {
    return prism::render::run(argc, argv);
  } catch (const std::bad_alloc &) {
    prism::render::console::error("out of memory");
  } catch (const std::exception &e) {
    prism::render::console::error(e.what());
  }
  return 1;
}
