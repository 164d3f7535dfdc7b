#include "RenderSession.h"

#include "AnariWorldBuilder.h"
#include "ImageIO.h"
#include "OutputChannels.h"
#include "OutputFiles.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <map>

#include <cmath>

namespace prism::nsi {

namespace {

void onAnariStatus(const void *userData,
    ANARIDevice,
    ANARIObject,
    ANARIDataType,
    ANARIStatusSeverity severity,
    ANARIStatusCode,
    const char *message)
{
  // Only problems reach the NSI handler; ANARI's chatter stays out.
  if (severity > ANARI_SEVERITY_WARNING || !message)
    return;
  const auto *report = static_cast<const ReportFunction *>(userData);
  (*report)(severity == ANARI_SEVERITY_WARNING ? NSIErrWarning : NSIErrError,
      std::string("ANARI: ") + message);
}

std::array<float, 3> cameraPoint(
    const Matrix &m, std::array<double, 3> p, bool vector)
{
  auto q = vector ? transformVector(m, p) : transformPoint(m, p);
  return {float(q[0]), float(q[1]), float(q[2])};
}

// Whether the library's default device lists `extension` (ANARI_KHR_...).
bool hasExtension(ANARILibrary library, const char *extension)
{
  const char **list = anariGetDeviceExtensions(library, "default");
  for (; list && *list; ++list) {
    if (std::strcmp(*list, extension) == 0)
      return true;
  }
  return false;
}

void setMatrixKeys(ANARIDevice device,
    ANARIObject object,
    const char *name,
    const Placement &matrices)
{
  std::vector<float> values;
  for (const Matrix &m : matrices)
    values.insert(values.end(), m.begin(), m.end());
  ANARIArray1D array = anariNewArray1D(
      device, nullptr, nullptr, nullptr, ANARI_FLOAT32_MAT4, matrices.size());
  if (void *mapped = anariMapArray(device, array))
    std::memcpy(mapped, values.data(), values.size() * sizeof(float));
  anariUnmapArray(device, array);
  anariSetParameter(device, object, name, ANARI_ARRAY1D, &array);
  anariRelease(device, array);
}

// "dir/beauty.exr" -> "dir/beauty.partial.exr".
std::string partialName(const std::string &file)
{
  const size_t slash = file.find_last_of('/');
  const size_t dot = file.find_last_of('.');
  const bool hasExtension =
      dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return hasExtension ? file.substr(0, dot) + ".partial" + file.substr(dot)
                      : file + ".partial";
}

// The session whose render thread this is (none elsewhere): its callbacks
// may call wait() or stop(), which must not join the thread itself.
thread_local const RenderSession *t_rendering = nullptr;

} // namespace

RenderSession::RenderSession(ReportFunction report, Stopped stopped)
    : m_report(std::move(report)), m_stopped(std::move(stopped))
{}

RenderSession::~RenderSession()
{
  close();
}

void RenderSession::release()
{
  m_builder.reset(); // its objects first, while the device lives
  if (m_device) {
    if (m_renderer)
      anariRelease(m_device, m_renderer);
    anariRelease(m_device, m_device);
  }
  if (m_library)
    anariUnloadLibrary(m_library);
  m_world = {};
  m_renderer = nullptr;
  m_device = nullptr;
  m_library = nullptr;
}

bool RenderSession::start(
    const std::string &library, const ResolvedScene &scene, bool progressive)
{
  close();
  m_progressive = progressive;
  m_library = anariLoadLibrary(library.c_str(), onAnariStatus, &m_report);
  if (!m_library) {
    m_report(NSIErrError, "cannot load the ANARI library '" + library + "'");
    return false;
  }
  m_device = anariNewDevice(m_library, "default");
  if (!m_device) {
    m_report(
        NSIErrError, "ANARI library '" + library + "' has no default device");
    release();
    return false;
  }
  m_cameraMotion =
      hasExtension(m_library, "ANARI_KHR_CAMERA_MOTION_TRANSFORMATION");
  m_builder = std::make_unique<AnariWorldBuilder>(m_device,
      m_report,
      hasExtension(
          m_library, "ANARI_KHR_GEOMETRY_TRIANGLE_MOTION_DEFORMATION"));
  m_renderer = anariNewRenderer(m_device, "default");
  apply(scene);
  launch();
  return true;
}

void RenderSession::synchronize(const ResolvedScene &scene, Stopped stopped)
{
  stop();
  m_stopped = std::move(stopped);
  m_silent = false;
  apply(scene);
  launch();
}

void RenderSession::apply(const ResolvedScene &scene)
{
  const AnariWorld world = m_builder->update(scene);
  // The renderer holds the environment: set and committed when it changed.
  const bool first = !m_world.world;
  if (first || world.background != m_world.background
      || world.ambientColor != m_world.ambientColor
      || world.ambientRadiance != m_world.ambientRadiance
      || scene.options != m_options) {
    if (scene.options.maxPathLength > 0)
      anariSetParameter(m_device,
          m_renderer,
          "maxPathLength",
          ANARI_INT32,
          &scene.options.maxPathLength);
    else
      anariUnsetParameter(m_device, m_renderer, "maxPathLength");
    anariSetParameter(m_device,
        m_renderer,
        "background",
        ANARI_FLOAT32_VEC4,
        world.background.data());
    anariSetParameter(m_device,
        m_renderer,
        "ambientColor",
        ANARI_FLOAT32_VEC3,
        world.ambientColor.data());
    anariSetParameter(m_device,
        m_renderer,
        "ambientRadiance",
        ANARI_FLOAT32,
        &world.ambientRadiance);
    anariCommitParameters(m_device, m_renderer);
  }
  m_world = world;
  m_options = scene.options;
  m_cameras = scene.cameras;
  placeOutputFiles(m_cameras, m_report, m_warnedOutputs);
  m_hasMotion = scene.hasMotion;
  for (CameraItem &camera : m_cameras) {
    if (camera.motion.size() > 1 && !m_cameraMotion) {
      m_report(NSIErrWarning,
          "camera '" + camera.handle
              + "' moves, but the ANARI device has no camera motion; its "
                "pose at shutter open is used");
      camera.motion.clear();
    }
  }
  if (m_cameras.empty())
    m_report(NSIErrWarning,
        "no camera with a screen hangs under .root; nothing is rendered");
}

void RenderSession::launch()
{
  // NOTE: wait() may read m_thread, and a stop() holds this lock from its
  // request to its join, so a render launched meanwhile is not the one it
  // joins with its request undone.
  std::lock_guard join(m_joinMutex);
  {
    // A new render starts unsuspended, whatever the last one was.
    std::lock_guard lock(m_suspendMutex);
    m_stopRequested = false;
    m_suspended = false;
    m_running = true;
    ++m_generation;
  }
  m_thread = std::thread([this] {
    t_rendering = this;
    renderAll();
  });
}

void RenderSession::join(uint64_t generation)
{
  std::lock_guard lock(m_joinMutex);
  if (m_generation == generation && m_thread.joinable())
    m_thread.join();
}

RenderSession::Waited RenderSession::wait()
{
  if (t_rendering == this)
    return Waited::kOnRenderThread;
  uint64_t ended = 0;
  {
    // A suspended render ends only after a resume, which no one may send
    // while this caller waits: return rather than hang.
    std::unique_lock lock(m_suspendMutex);
    m_suspendedOrEnded.wait(lock, [this] { return m_suspended || !m_running; });
    if (m_running)
      return Waited::kSuspended;
    ended = m_generation;
  }
  // The render seen ending, not one another thread started since.
  join(ended);
  return Waited::kEnded;
}

void RenderSession::stop()
{
  if (t_rendering == this) {
    m_stopRequested = true; // the thread ends when its callback returns
    return;
  }
  // From the request to the join, so no launch() in between undoes the
  // request and leaves this joining a render that waits for a resume.
  std::lock_guard joining(m_joinMutex);
  {
    // Under the lock, so a thread about to wait for resume sees it.
    std::lock_guard lock(m_suspendMutex);
    m_stopRequested = true;
  }
  m_resumed.notify_all();
  if (m_thread.joinable())
    m_thread.join();
}

void RenderSession::suspend()
{
  {
    std::lock_guard lock(m_suspendMutex);
    m_suspended = true;
  }
  m_suspendedOrEnded.notify_all();
}

void RenderSession::resume()
{
  {
    std::lock_guard lock(m_suspendMutex);
    m_suspended = false;
  }
  m_resumed.notify_all();
}

bool RenderSession::waitUntilResumed()
{
  std::unique_lock lock(m_suspendMutex);
  if (m_suspended && !m_stopRequested && m_parked) {
    // Told outside the lock, so the callback may resume or stop.
    lock.unlock();
    m_parked(m_frames);
    lock.lock();
  }
  m_resumed.wait(lock, [this] { return !m_suspended || m_stopRequested; });
  return !m_stopRequested;
}

void RenderSession::close()
{
  stop();
  std::lock_guard lock(m_joinMutex);
  release();
}

void RenderSession::writeOutputs(const CameraItem &item,
    const Framing &framing,
    ANARIFrame frame,
    const std::vector<const FrameChannel *> &channels,
    bool warn)
{
  std::map<const FrameChannel *, image::Image> pictures;
  for (const FrameChannel *channel : channels)
    pictures[channel] = readFrameChannel(m_device, frame, *channel);
  for (const OutputItem &output : item.outputs) {
    if (output.driverName.empty() || isDisplayDriver(output.driverName))
      continue;
    if (output.fileName.empty()) {
      if (warn)
        m_report(NSIErrWarning,
            "output driver for layer '" + output.layerHandle
                + "' has no imagefilename");
      continue;
    }
    const FrameChannel *channel = channelForVariable(output.variableName);
    image::Image written =
        channel ? pictures.at(channel)
                : image::Image(framing.frameWidth, framing.frameHeight);
    if (!output.withAlpha) {
      for (auto &p : written.pixels)
        p.a = 1.f;
    }
    image::WriteOptions options;
    options.exrPixelType = output.halfFloat ? image::ExrPixelType::Half
                                            : image::ExrPixelType::Float;
    // A progressive file is replaced whole, so a reader never sees half of
    // it: written beside it (same extension, same format), then renamed.
    const std::string target =
        m_progressive ? partialName(output.fileName) : output.fileName;
    std::string error = image::write(target, written, options).error;
    if (error.empty() && target != output.fileName
        && std::rename(target.c_str(), output.fileName.c_str()) != 0) {
      error = std::strerror(errno);
      std::remove(target.c_str());
    }
    if (!error.empty())
      m_report(NSIErrError, "cannot write '" + output.fileName + "': " + error);
  }
}

void RenderSession::renderAll()
{
  bool completed = true;
  for (const CameraItem &item : m_cameras) {
    const Framing framing =
        frameCamera(item.orthographic, item.fov, item.screen);
    ANARICamera camera = anariNewCamera(
        m_device, item.orthographic ? "orthographic" : "perspective");
    // A moving camera is its own frame (looking down -Z, +Y up) placed by
    // motion.transform at times uniform over the shutter, [0, 1].
    const bool moves = item.motion.size() > 1;
    const Matrix &placed = moves ? kIdentity : item.worldFromCamera;
    const auto position = cameraPoint(placed, {0, 0, 0}, false);
    const auto direction = cameraPoint(placed, {0, 0, -1}, true);
    const auto up = cameraPoint(placed, {0, 1, 0}, true);
    if (moves) {
      setMatrixKeys(m_device, camera, "motion.transform", item.motion);
      const float time[2] = {0.f, 1.f};
      anariSetParameter(m_device, camera, "time", ANARI_FLOAT32_BOX1, time);
    }
    anariSetParameter(
        m_device, camera, "position", ANARI_FLOAT32_VEC3, position.data());
    anariSetParameter(
        m_device, camera, "direction", ANARI_FLOAT32_VEC3, direction.data());
    anariSetParameter(m_device, camera, "up", ANARI_FLOAT32_VEC3, up.data());
    anariSetParameter(
        m_device, camera, "aspect", ANARI_FLOAT32, &framing.aspect);
    if (item.orthographic)
      anariSetParameter(
          m_device, camera, "height", ANARI_FLOAT32, &framing.height);
    else
      anariSetParameter(m_device, camera, "fovy", ANARI_FLOAT32, &framing.fovy);
    const float near = float(item.near), far = float(item.far);
    anariSetParameter(m_device, camera, "near", ANARI_FLOAT32, &near);
    if (std::isfinite(far))
      anariSetParameter(m_device, camera, "far", ANARI_FLOAT32, &far);
    if (item.apertureRadius > 0) {
      const float aperture = float(item.apertureRadius);
      const float focus = float(item.focusDistance);
      anariSetParameter(
          m_device, camera, "apertureRadius", ANARI_FLOAT32, &aperture);
      anariSetParameter(
          m_device, camera, "focusDistance", ANARI_FLOAT32, &focus);
    }
    if (m_hasMotion) {
      const float shutter[2] = {0.f, 1.f}; // the motion samples' time range
      anariSetParameter(
          m_device, camera, "shutter", ANARI_FLOAT32_BOX1, shutter);
    }
    anariSetParameter(m_device,
        camera,
        "imageRegion",
        ANARI_FLOAT32_BOX2,
        framing.imageRegion.data());
    anariCommitParameters(m_device, camera);

    ANARIFrame frame = anariNewFrame(m_device);
    const uint32_t size[2] = {framing.frameWidth, framing.frameHeight};
    anariSetParameter(m_device, frame, "size", ANARI_UINT32_VEC2, size);
    // The channels the layers ask for (unknown variables: black, warned).
    std::vector<const FrameChannel *> channels{channelForVariable("Ci")};
    anariSetParameter(m_device,
        frame,
        channels[0]->name,
        ANARI_DATA_TYPE,
        &channels[0]->type);
    for (const OutputItem &output : item.outputs) {
      const FrameChannel *channel = channelForVariable(output.variableName);
      if (!channel) {
        m_report(NSIErrWarning,
            "output layer '" + output.layerHandle + "': variable '"
                + output.variableName + "' has no ANARI channel; black");
      } else if (std::find(channels.begin(), channels.end(), channel)
                 == channels.end()) {
        anariSetParameter(
            m_device, frame, channel->name, ANARI_DATA_TYPE, &channel->type);
        channels.push_back(channel);
      }
    }
    const bool accumulate = true;
    anariSetParameter(m_device, frame, "accumulation", ANARI_BOOL, &accumulate);
    anariSetParameter(m_device, frame, "renderer", ANARI_RENDERER, &m_renderer);
    anariSetParameter(m_device, frame, "camera", ANARI_CAMERA, &camera);
    anariSetParameter(m_device, frame, "world", ANARI_WORLD, &m_world.world);
    anariCommitParameters(m_device, frame);
    anariRelease(m_device, camera);

    int samples = 0;
    for (; samples < item.oversampling; ++samples) {
      if (m_stopRequested || !waitUntilResumed()) {
        completed = false;
        break;
      }
      anariRenderFrame(m_device, frame);
      anariFrameReady(m_device, frame, ANARI_WAIT);
      if (m_progressive) // a driver is warned about once
        writeOutputs(item, framing, frame, channels, samples == 0);
      ++m_frames;
      if (m_frameDone)
        m_frameDone(m_frames);
    }
    // Stopped before the first frame: nothing to write.
    if (samples > 0 && !m_progressive)
      writeOutputs(item, framing, frame, channels, true);
    anariRelease(m_device, frame);
    if (samples == 0)
      break;
  }
  {
    std::lock_guard lock(m_suspendMutex);
    m_running = false;
  }
  m_suspendedOrEnded.notify_all();
  if (m_stopped && !m_silent)
    m_stopped(completed ? NSIRenderCompleted : NSIRenderAborted);
}

} // namespace prism::nsi
