// prism-render: renders a scene file or a built-in demo scene with any ANARI
// library (prism by default) and writes the image. See --help. The scene
// comes from prism_scene_io; this parses options, then loads, renders and
// writes, one stage a function.
#include "CameraFraming.h"
#include "Console.h"
#include "DeviceSession.h"
#include "Environment.h"
#include "FrameLoop.h"
#include "FrameMemory.h"
#include "FrameOutput.h"
#include "Interrupt.h"
#include "NsiRender.h"
#include "Objects.h"
#include "Options.h"
#include "ProcessShare.h"
#include "Progress.h"
#include "RendererParameters.h"
#include "SceneLoader.h"

#include <anari/anari.h>

#ifdef PRISM_RENDER_HAS_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <numbers>

namespace prism::render {
namespace {

using scenes::operator-;

constexpr int kExitFailure = 1; // the scene, the device or the output failed
constexpr int kExitUsage = 2;   // the command line asks for the impossible
constexpr int kContinue = -1;   // a stage passed: the run goes on

int fail(const std::string &message, int code = kExitFailure)
{
  console::error(message);
  return code;
}

void listDemos()
{
  for (const scenes::DemoScene &demo : scenes::demoScenes())
    std::printf("demo:%-18s %s\n", demo.name, demo.description);
}

scene_io::LoadOptions loadOptions(const Options &options)
{
  scene_io::LoadOptions load;
  load.gltfCamera = options.cameraIndex;
  load.gltfVariant = options.variant;
  load.gltfTime = options.time;
  if (options.rawDimensions)
    load.raw.dimensions = *options.rawDimensions;
  load.raw.type = options.rawType;
  load.raw.spacing = options.rawSpacing;
  load.gridName = options.gridName;
  load.transferFunction = options.transferFunction;
  return load;
}

// Ray tracers reject rays from beyond ~1e18: a camera there is refused
// rather than handed to the device.
bool usable(const scenes::Vec3 &v)
{
  return std::all_of(v.begin(), v.end(), [](float c) {
    return std::isfinite(c) && std::fabs(c) <= 1e15f;
  });
}

std::string cameraText(const scene_io::CameraSetup &view)
{
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
  return text;
}

// One run, stage by stage; each stage returns kContinue or the exit code.
class RenderRun
{
 public:
  explicit RenderRun(const Options &options)
      : m_options(options), m_session(options.verbose, &console::message)
  {}

  int checkInputs();
  int openDevice();
  int loadScene();
  int lightScene();
  int makeRenderer();
  int makeCamera();
  int makeFrame();
  int render();
  int writeOutputs();

 private:
  scenes::Bounds worldBounds();
  void printSummary(const std::vector<OutputImage> &images);

  const Options &m_options;
  tools::DeviceSession m_session;
  scene_io::SceneSource m_source;
  std::vector<ChannelRequest> m_requests;
  scenes::Scene m_scene;
  int m_errorsBeforeLoad{0};
  double m_loadSeconds{0.0};
  ANARIRenderer m_renderer{nullptr};
  ANARIFrame m_frame{nullptr};
  uint32_t m_frames{1};
  uint32_t m_samplesPerFrame{1}; // the renderer's pixelSamples
  bool m_accumulates{false};     // frames add to one image (--spp > 1)
  FrameCompletions m_completions;
  bool m_watchCompletion{false};
  LoopResult m_loop;
  uint64_t m_raysBefore{0};
  bool m_countsRays{false};
};

// What to load and where to write, checked before any device is touched.
int RenderRun::checkInputs()
{
  const scene_io::SourceResult source =
      scene_io::identifySceneSource(m_options.scene);
  if (!source.ok())
    return fail(source.error, source.badName ? kExitUsage : kExitFailure);
  m_source = source.source;
  if (m_source.format == scene_io::SceneFormat::Nsi)
    // An NSI stream names its own camera, resolution and output files:
    // libnsi renders it, and this is the run's end.
    return renderNsiScene(m_options);
  if (m_source.format == scene_io::SceneFormat::Raw) {
    scene_io::RawVolumeFormat format = loadOptions(m_options).raw;
    const std::string error = resolveRawFormat(m_source.path, format);
    if (!error.empty())
      return fail(error, kExitUsage);
  }
  const std::string colorPath =
      m_options.output.empty() ? m_source.name + ".png" : m_options.output;
  m_requests = channelRequests(m_options, colorPath);
  for (const ChannelRequest &r : m_requests) {
    const std::filesystem::path parent =
        std::filesystem::path(r.path).parent_path();
    std::error_code ec;
    if (!parent.empty() && !std::filesystem::is_directory(parent, ec))
      return fail("cannot write '" + r.path + "': folder '" + parent.string()
                  + "' does not exist");
  }
  return kContinue;
}

int RenderRun::openDevice()
{
  if (!m_options.traceFile.empty()) {
    // libanari then loads the debug layer around the library, recording.
    setenv("ANARI_DEBUG_LAYER", "1", 1);
    setenv("ANARI_DEBUG_TRACE", m_options.traceFile.c_str(), 1);
  }
  bool usage = false;
  const std::string error = m_session.open(
      {m_options.library, m_options.deviceSubtype, m_options.threads}, usage);
  if (!error.empty())
    return fail(error, usage ? kExitUsage : kExitFailure);
  ANARIDevice device = m_session.device();
  const char **renderers = anariGetObjectSubtypes(device, ANARI_RENDERER);
  if (m_options.renderer != "default" && renderers && *renderers
      && !tools::contains(renderers, m_options.renderer))
    return fail("the device has no renderer '" + m_options.renderer
                    + "' (renderers: " + tools::joinList(renderers) + ")",
        kExitUsage);
  for (const ChannelRequest &r : m_requests) {
    const char *needed = channelExtension(r);
    if (needed && !m_session.has(needed))
      return fail(std::string("this device does not implement ") + (needed + 6)
                  + ", so " + r.channel + " cannot be written to '" + r.path
                  + "'");
  }
  return kContinue;
}

// The scene. Device errors from here on (a file the loader passed but the
// device refused, such as a NanoVDB tree it found corrupt) fail the run:
// the image would be missing what the file holds.
int RenderRun::loadScene()
{
  ANARIDevice device = m_session.device();
  if (m_options.mpiPartition) {
    const std::optional<scenes::Partition> share =
        m_session.has("ANARI_KHR_DATA_PARALLEL_MPI") ? processShare(device)
                                                     : std::nullopt;
    if (share) {
      scenes::setPartition(*share);
      if (!m_options.quiet)
        console::message("process " + std::to_string(share->part) + " of "
                         + std::to_string(share->parts)
                         + " builds its share of the scene");
    } else
      console::warning(
          "--mpi-partition needs a data-parallel device (prism_mpi); the "
          "whole scene is built");
  }
  m_errorsBeforeLoad = m_session.errors();
  const auto start = std::chrono::steady_clock::now();
  scene_io::LoadResult loaded =
      scene_io::loadScene(device, m_source, loadOptions(m_options));
  m_scene = loaded.scene;
  scenes::releaseListedSurfaces(device, m_scene); // the viewer's, not needed
  m_session.keep(m_scene.world);
  if (interrupted())
    return fail("interrupted (Ctrl-C); no image written", kExitInterrupted);
  for (const std::string &note : m_scene.notes)
    console::warning(note);
  if (!loaded.ok())
    return fail(loaded.error);
  const bool gltf = m_source.format == scene_io::SceneFormat::Gltf;
  if (m_options.cameraIndex >= 0 && !gltf)
    console::warning("--camera only applies to glTF files; ignored");
  if (!m_options.variant.empty() && !gltf)
    console::warning("--variant only applies to glTF files; ignored");
  if (m_options.time && !gltf)
    console::warning("--time only applies to glTF files; ignored");
  if (m_options.transferFunction.given && !scene_io::hasVolumeStyle(m_source))
    console::warning(
        "--tf-* options only apply to volumes (.raw, .nvdb, demo:volume); "
        "ignored");
  if (!m_options.gridName.empty()
      && m_source.format != scene_io::SceneFormat::NanoVdb)
    console::warning("--grid only applies to NanoVDB files; ignored");
  const int lit = lightScene();
  for (ANARILight light : m_scene.lights) // the environment's too
    m_session.keep(light);
  m_loadSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  return lit;
}

// Whether the device's renderer of that subtype says (its "ignoresLights"
// property, docs/renderers.md) that it shades without lights; a device
// that does not say is taken to use them.
bool ignoresLights(ANARIDevice device, const std::string &renderer)
{
  ANARIRenderer probe = anariNewRenderer(device, renderer.c_str());
  if (!probe)
    return false;
  uint8_t ignores = 0; // ANARI_BOOL
  const int found = anariGetProperty(device,
      probe,
      "ignoresLights",
      ANARI_BOOL,
      &ignores,
      sizeof(ignores),
      ANARI_WAIT);
  anariRelease(device, probe);
  return found && ignores;
}

// Files are lit the way glTF viewers light them (scene_io::lightingFor
// states the rule), and the run says so; renderers that ignore lights get
// no default environment, and no claim that one lights the scene.
int RenderRun::lightScene()
{
  ANARIDevice device = m_session.device();
  const scene_io::EnvironmentChoice choice{m_options.environment,
      m_options.environmentIntensity,
      m_options.environmentRotateDegrees,
      m_options.environmentGiven};
  const scene_io::Lighting lighting = scene_io::lightingFor(m_scene, choice);
  const bool lightFree = ignoresLights(device, m_options.renderer);
  if (!lighting.add || (lightFree && !choice.given))
    return kContinue;
  if (!scenes::hasSubtype(device, ANARI_LIGHT, "hdri")) {
    console::warning(
        "the device has no hdri light (KHR_LIGHT_HDRI) to light the scene "
        "with an environment; it renders with its own lights only");
    return kContinue;
  }
  const scenes::Vec3 up = m_options.up.value_or(
      m_scene.camera.valid ? m_scene.camera.up : scenes::Vec3{0.f, 1.f, 0.f});
  const scene_io::Environment environment =
      scene_io::makeEnvironment(device, lighting.environment, up);
  if (!environment.error.empty())
    return fail(environment.error);
  scene_io::addWorldLight(device, m_scene, environment.light);
  if (m_options.quiet)
    return kContinue;
  if (lightFree)
    console::warning("the " + m_options.renderer
                     + " renderer ignores lights; --env changes nothing");
  else if (choice.given)
    console::message("lit by " + environment.description);
  else if (m_scene.lights.size() > 1)
    console::message("the scene's lights, with " + environment.description
                     + " as a dim fill (--env none: its lights only)");
  else
    console::message("the scene has no lights; lit by "
                     + environment.description + " (--env none: unlit)");
  return kContinue;
}

int RenderRun::makeRenderer()
{
  ANARIDevice device = m_session.device();
  m_renderer =
      m_session.keep(anariNewRenderer(device, m_options.renderer.c_str()));
  const bool explicitBackground = m_options.background.has_value();
  if (explicitBackground || m_scene.hasBackground) {
    const std::array<float, 4> background =
        m_options.background.value_or(m_scene.background);
    if (rendererDeclares(device, m_options.renderer, "background")
        != Declared::No)
      anariSetParameter(device,
          m_renderer,
          "background",
          ANARI_FLOAT32_VEC4,
          background.data());
    else if (explicitBackground)
      console::warning(
          "the renderer has no 'background'; --background ignored");
  }
  if (m_options.denoise) {
    if (m_session.has("ANARI_KHR_RENDERER_DENOISE")) {
      const bool on = true;
      anariSetParameter(device, m_renderer, "denoise", ANARI_BOOL, &on);
    } else {
      console::warning(
          "the device does not implement KHR_RENDERER_DENOISE; --denoise "
          "ignored");
    }
  }
  const ParameterOutcome parameters = setRendererParameters(
      device, m_renderer, m_options.renderer, m_options.rendererParameters);
  for (const std::string &w : parameters.warnings)
    console::warning(w);
  if (!parameters.error.empty())
    return fail(parameters.error, kExitUsage);
  anariCommitParameters(device, m_renderer);
  return kContinue;
}

// The world's bounds as the device sees them, else as the builder computed
// them.
scenes::Bounds RenderRun::worldBounds()
{
  scenes::Bounds bounds;
  float box[6] = {std::numeric_limits<float>::infinity(), 0, 0, 0, 0, 0};
  if (anariGetProperty(m_session.device(),
          m_scene.world,
          "bounds",
          ANARI_FLOAT32_BOX3,
          box,
          sizeof(box),
          ANARI_WAIT)
      && std::all_of(box, box + 6, [](float v) { return std::isfinite(v); })) {
    bounds.extend(scenes::Vec3{box[0], box[1], box[2]});
    bounds.extend(scenes::Vec3{box[3], box[4], box[5]});
  }
  return bounds.empty() ? m_scene.bounds : bounds;
}

int RenderRun::makeCamera()
{
  ANARIDevice device = m_session.device();
  const scenes::Bounds bounds = worldBounds();
  // The bounds query waited for every commit, so the device has judged the
  // scene by now.
  if (m_session.errors() > m_errorsBeforeLoad)
    return fail("the device refused the scene '" + m_options.scene
                + "' (see above); no image written");
  const float aspect = float(m_options.width) / float(m_options.height);
  const scene_io::CameraOverrides overrides{
      m_options.eye, m_options.at, m_options.up, m_options.fovyDegrees};
  const scene_io::CameraSetup view = scene_io::frameCamera(
      m_scene.camera, bounds, aspect, overrides, m_scene.outline);
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
  ANARICamera camera = m_session.keep(anariNewCamera(
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
  if (m_options.verbose)
    console::message(cameraText(view));
  scenes::setObject(device, m_frame, "camera", ANARI_CAMERA, camera);
  return kContinue;
}

int RenderRun::makeFrame()
{
  ANARIDevice device = m_session.device();
  m_frame = m_session.keep(anariNewFrame(device));
  const uint32_t size[2] = {m_options.width, m_options.height};
  anariSetParameter(device, m_frame, "size", ANARI_UINT32_VEC2, size);
  scenes::setObject(device, m_frame, "world", ANARI_WORLD, m_scene.world);
  scenes::setObject(device, m_frame, "renderer", ANARI_RENDERER, m_renderer);
  for (const ChannelRequest &r : m_requests)
    anariSetParameter(
        device, m_frame, r.channel.c_str(), ANARI_DATA_TYPE, &r.type);
  if (m_options.samplesPerPixel > 1) {
    if (m_session.has("ANARI_KHR_FRAME_ACCUMULATION")) {
      const bool on = true;
      anariSetParameter(device, m_frame, "accumulation", ANARI_BOOL, &on);
      m_accumulates = true;
      // Bench runs time one-sample frames.
      if (m_options.benchFrames == 0) {
        m_samplesPerFrame = takeSamplesPerCall(device,
            m_renderer,
            m_options.renderer,
            m_options.samplesPerPixel,
            uint64_t(m_options.width) * m_options.height);
        anariCommitParameters(device, m_renderer);
      }
      m_frames = m_options.samplesPerPixel / m_samplesPerFrame;
    } else {
      console::warning(
          "the device does not implement frame accumulation "
          "(KHR_FRAME_ACCUMULATION); rendering 1 sample per pixel instead "
          "of "
          + std::to_string(m_options.samplesPerPixel));
    }
  }
  if (m_options.benchFrames > 0)
    m_frames = m_options.benchFrames;
  m_watchCompletion = m_options.benchFrames == 0
                      && m_session.has("ANARI_KHR_FRAME_COMPLETION_CALLBACK");
  if (m_watchCompletion)
    callBackWhenDone(device, m_frame, m_completions);
  const int made = makeCamera();
  anariCommitParameters(device, m_frame);
  return made;
}

int RenderRun::render()
{
  ANARIDevice device = m_session.device();
  FrameLoop loop;
  loop.device = device;
  loop.frame = m_frame;
  loop.frames = m_frames;
  loop.samplesPerFrame = m_samplesPerFrame;
  loop.completions = m_watchCompletion ? &m_completions : nullptr;
  loop.showProgress = !m_options.quiet && console::stderrIsTerminal();
  loop.unit = m_options.benchFrames > 0 ? "frames" : "samples";
  // Rays the renderer traced (its "raysTraced" property, where it has one).
  m_countsRays = anariGetProperty(device,
      m_renderer,
      "raysTraced",
      ANARI_UINT64,
      &m_raysBefore,
      sizeof(m_raysBefore),
      ANARI_NO_WAIT);
  const int errorsBefore = m_session.errors();
  m_loop = renderFrames(loop);
  if (m_loop.interrupted && m_loop.frameSeconds.empty())
    return fail("interrupted (Ctrl-C); no image written", kExitInterrupted);
  if (m_session.errors() > errorsBefore)
    return fail(
        "the device reported errors while rendering (see above); no image "
        "written");
  if (m_loop.interrupted)
    console::warning(
        "interrupted (Ctrl-C) after "
        + std::to_string(m_loop.frameSeconds.size() * m_samplesPerFrame)
        + " of " + std::to_string(m_frames * m_samplesPerFrame) + " "
        + loop.unit + "; writing what was rendered");
  return kContinue;
}

int RenderRun::writeOutputs()
{
  ANARIDevice device = m_session.device();
  // A data-parallel device (KHR_DATA_PARALLEL_MPI) defines the image on
  // rank 0 of the frame's communicator only: the other processes of an
  // `mpirun` write nothing (prism_mpi tells a frame's rank as mpiRank).
  int32_t mpiRank = 0;
  if (m_session.has("ANARI_KHR_DATA_PARALLEL_MPI")
      && anariGetProperty(device,
          m_frame,
          "mpiRank",
          ANARI_INT32,
          &mpiRank,
          sizeof(mpiRank),
          ANARI_NO_WAIT)
      && mpiRank > 0)
    return 0;
  std::vector<OutputImage> images;
  std::vector<std::string> warnings;
  const std::string readError = readChannels(device,
      m_frame,
      m_requests,
      m_options.width,
      m_options.height,
      images,
      warnings);
  for (const std::string &w : warnings)
    console::warning(w);
  if (!readError.empty())
    return fail(readError);
  const std::string writeError = writeImages(images);
  if (!writeError.empty())
    return fail(writeError);
  printSummary(images);
  return m_loop.interrupted ? kExitInterrupted : 0;
}

void RenderRun::printSummary(const std::vector<OutputImage> &images)
{
  const char *scene = m_options.scene.c_str();
  if (m_options.benchFrames > 0) {
    std::printf("%s: %u frames of %ux%u, renderer %s: %s\n",
        scene,
        unsigned(m_loop.frameSeconds.size()),
        m_options.width,
        m_options.height,
        m_options.renderer.c_str(),
        benchSummary(m_loop.frameSeconds).c_str());
    uint64_t raysAfter = 0;
    if (m_countsRays && m_loop.seconds > 0.0
        && anariGetProperty(m_session.device(),
            m_renderer,
            "raysTraced",
            ANARI_UINT64,
            &raysAfter,
            sizeof(raysAfter),
            ANARI_NO_WAIT)) {
      const double rays = double(raysAfter - m_raysBefore);
      std::printf("%s: %.0f rays traced, %.2f Mrays/s\n",
          scene,
          rays,
          rays / m_loop.seconds * 1e-6);
    }
  }
  if (m_options.quiet)
    return;
  for (const OutputImage &image : images)
    std::printf("wrote %s (%ux%u)\n",
        image.path.c_str(),
        image.image.width,
        image.image.height);
  const size_t frames = m_loop.frameSeconds.size();
  // What the written image holds: bench frames take one sample each, and
  // add up only when --spp turned accumulation on.
  const size_t samples = m_options.benchFrames == 0 ? frames * m_samplesPerFrame
                         : m_accumulates            ? frames
                                                    : 1;
  std::printf("scene %s in %s, %u frame%s in %s (%u spp)\n",
      scene,
      formatDuration(m_loadSeconds).c_str(),
      unsigned(frames),
      frames == 1 ? "" : "s",
      formatDuration(m_loop.seconds).c_str(),
      unsigned(samples));
}

int run(int argc, char **argv)
{
  // Ctrl-C from here on stops the run (RenderRun::render says what is
  // written).
  watchInterrupts();
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
#ifdef PRISM_RENDER_HAS_TBB
  // TBB-based devices (prism among them) share this process's TBB: the
  // limit applies to every arena they create.
  std::unique_ptr<tbb::global_control> threadLimit;
  if (options.threads > 0)
    threadLimit = std::make_unique<tbb::global_control>(
        tbb::global_control::max_allowed_parallelism, options.threads);
#endif
  RenderRun job(options);
  int status = kContinue;
  for (int (RenderRun::*stage)() : {&RenderRun::checkInputs,
           &RenderRun::openDevice,
           &RenderRun::loadScene,
           &RenderRun::makeRenderer,
           &RenderRun::makeFrame,
           &RenderRun::render,
           &RenderRun::writeOutputs}) {
    if (status != kContinue)
      return status;
    status = (job.*stage)();
  }
  return status;
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
