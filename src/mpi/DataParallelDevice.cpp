#include "DataParallelDevice.h"

#include "DepthCompositor.h"
#include "DistributedTransport.h"
#include "EmitterExchange.h"
#include "PoliteWait.h"
#include "TileRowGather.h"

#include "camera/Camera.h"
#include "frame/Frame.h"
#include "frame/PixelFormat.h"
#include "geometry/Geometry.h"
#include "renderer/PathTracer.h"
#include "renderer/Renderer.h"
#include "world/Group.h"
#include "world/Surface.h"
#include "world/World.h"

#include "MachineLimits.h"

#include "anari/frontend/type_utility.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace prism::mpi {

DataParallelDevice::DataParallelDevice(ANARILibrary library) : Device(library)
{
  if (!m_session.usable()) {
    reportStatus(this_device(),
        ANARI_DEVICE,
        ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_OPERATION,
        m_session.problem());
  }
  // An unmodified single-process program chooses its mode from outside.
  if (const char *mode = std::getenv("PRISM_MPI_MODE"))
    setMode(ANARI_STRING, mode);
  // ... and the library that renders its objects.
  const char *wrappedName = std::getenv("PRISM_MPI_WRAPPED_LIBRARY");
  if (wrappedName && *wrappedName)
    setWrapParameter("wrappedLibrary", ANARI_STRING, wrappedName);
  const char *subtype = std::getenv("PRISM_MPI_WRAPPED_DEVICE");
  if (subtype && *subtype)
    setWrapParameter("wrappedDevice", ANARI_STRING, subtype);
  if (const char *timeout = std::getenv("PRISM_MPI_TIMEOUT")) {
    const float seconds = std::strtof(timeout, nullptr);
    setTimeout(ANARI_FLOAT32, &seconds);
  }
}

DataParallelDevice::~DataParallelDevice()
{
  // Frames in flight finish before MPI may be finalized under them.
  taskPool().wait();
  // The wrapped device goes before its library (a member, closed after).
  if (m_wrappedDevice)
    m_wrappedDevice->release((ANARIObject)m_wrappedDevice);
  m_wrappedDevice = nullptr;
}

void DataParallelDevice::reportBadDeviceParameter(const std::string &message)
{
  reportStatus(this_device(),
      ANARI_DEVICE,
      ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      message);
}

void DataParallelDevice::setMode(ANARIDataType type, const void *mem)
{
  const auto mode = type == ANARI_STRING && mem
                        ? parseRenderMode((const char *)mem)
                        : std::nullopt;
  if (!mode) {
    std::string message =
        "device: parameter 'mode' must be the STRING 'pathtracer',"
        " 'composite' or 'replicated' (got ";
    if (type == ANARI_STRING && mem)
      message.append("'").append((const char *)mem).append("'");
    else
      message.append(anari::toString(type));
    message.append("); it stays '").append(toString(m_mode)).append("'");
    reportBadDeviceParameter(message);
    return;
  }
  m_mode = *mode;
  m_modeExplicit = true;
}

void DataParallelDevice::setTimeout(ANARIDataType type, const void *mem)
{
  double seconds = 0.0;
  if (type == ANARI_FLOAT32 && mem)
    seconds = *(const float *)mem;
  else if (type == ANARI_FLOAT64 && mem)
    seconds = *(const double *)mem;
  else
    seconds = std::numeric_limits<double>::quiet_NaN();
  if (!(seconds >= 0.0) || !std::isfinite(seconds)) {
    std::string message =
        "device: parameter 'mpiTimeout' must be a FLOAT32"
        " or FLOAT64 number of seconds, 0 or more (got ";
    message.append(std::isnan(seconds) ? std::string(anari::toString(type))
                                       : std::to_string(seconds));
    message.append("); it stays ");
    message.append(std::to_string(m_timeoutSeconds));
    reportBadDeviceParameter(message);
    return;
  }
  m_timeoutSeconds = seconds;
}

void DataParallelDevice::setThreads(ANARIDataType type, const void *mem)
{
  const bool isCount = (type == ANARI_INT32 || type == ANARI_UINT32) && mem;
  int64_t threads = -1;
  if (isCount && type == ANARI_INT32)
    threads = *(const int32_t *)mem;
  else if (isCount)
    threads = *(const uint32_t *)mem;
  const unsigned limit = limits::maxPoolThreads();
  if (threads < 0 || threads > int64_t(limit)) {
    std::string message =
        "device: parameter 'numThreads' must be an INT32 or UINT32 count, 0"
        " (every hardware thread) up to "
        + std::to_string(limit) + ", this machine's limit (got ";
    message.append(
        isCount ? std::to_string(threads) : std::string(anari::toString(type)));
    message.append("); it is ignored");
    reportBadDeviceParameter(message);
    return;
  }
  taskPool().setThreads(int(threads));
}

ANARIFrame DataParallelDevice::newFrame()
{
  if (anari::DeviceImpl *device = wrapped()) {
    ANARIFrame frame = created(device->newFrame(), ANARI_FRAME);
    if (frame) {
      // The wrapped frame always renders what compositing needs.
      const ANARIDataType color = ANARI_FLOAT32_VEC4;
      const ANARIDataType depth = ANARI_FLOAT32;
      device->setParameter(frame, "channel.color", ANARI_DATA_TYPE, &color);
      device->setParameter(frame, "channel.depth", ANARI_DATA_TYPE, &depth);
      std::lock_guard lock(m_stateMutex);
      FrameState &state = m_frames[frame] = FrameState{};
      state.index = m_framesCreated++;
    }
    return frame;
  }
  ANARIFrame frame = Device::newFrame();
  if (frame) {
    std::lock_guard lock(m_stateMutex);
    m_frames[frame].index = m_framesCreated++;
  }
  return frame;
}

ANARIWorld DataParallelDevice::newWorld()
{
  if (anari::DeviceImpl *device = wrapped()) {
    ANARIWorld world = created(device->newWorld(), ANARI_WORLD);
    if (world) {
      std::lock_guard lock(m_stateMutex);
      m_worlds[world] = {};
    }
    return world;
  }
  ANARIWorld world = Device::newWorld();
  if (world) {
    std::lock_guard lock(m_stateMutex);
    m_worlds[world] = {};
  }
  return world;
}

DataParallelDevice::CommunicatorParameter *DataParallelDevice::communicatorOf(
    ANARIObject object)
{
  auto frame = m_frames.find(object);
  if (frame != m_frames.end())
    return &frame->second.communicator;
  auto world = m_worlds.find(object);
  return world != m_worlds.end() ? &world->second : nullptr;
}

void DataParallelDevice::setParameter(
    ANARIObject object, const char *name, ANARIDataType type, const void *mem)
try {
  const std::string parameter = name ? name : "";
  if (object == (ANARIObject)this_device() && parameter == "mode") {
    setMode(type, mem);
    return;
  }
  if (object == (ANARIObject)this_device() && parameter == "mpiTimeout") {
    setTimeout(type, mem);
    return;
  }
  if (object == (ANARIObject)this_device() && parameter == "numThreads") {
    setThreads(type, mem);
    return;
  }
  if (object == (ANARIObject)this_device()
      && (parameter == "wrappedLibrary" || parameter == "wrappedDevice")) {
    setWrapParameter(parameter, type, mem);
    return;
  }
  if (object == (ANARIObject)this_device()) {
    Device::setParameter(object, name, type, mem);
    passDeviceParameter(parameter, type, mem);
    return;
  }
  anari::DeviceImpl *device = wrapped();
  if (parameter == "mpiCommunicator" && (device || lookup(object))) {
    std::lock_guard lock(m_stateMutex);
    if (CommunicatorParameter *communicator = communicatorOf(object)) {
      if (type != ANARI_VOID_POINTER || !mem) {
        reportStatus(object,
            m_frames.count(object) ? ANARI_FRAME : ANARI_WORLD,
            ANARI_SEVERITY_ERROR,
            ANARI_STATUS_INVALID_ARGUMENT,
            std::string("anariSetParameter: parameter 'mpiCommunicator' must"
                        " be a non-NULL VOID_POINTER to an MPI_Comm (got ")
                + (mem ? anari::toString(type) : "NULL") + "); it is ignored");
        return;
      }
      communicator->staged = *(const MPI_Comm *)mem;
      return;
    }
  }
  if (device) {
    const ANARIObject value =
        anari::isObject(type) && mem ? *(const ANARIObject *)mem : nullptr;
    if (!liveWrapped(object, "anariSetParameter")
        || (value && !liveWrapped(value, "anariSetParameter (its value)")))
      return;
    if (!setWrappedParameter(object, parameter, type, mem))
      device->setParameter(object, name, type, mem);
    return;
  }
  Device::setParameter(object, name, type, mem);
} catch (...) {
  reportStatus(object,
      ANARI_OBJECT,
      ANARI_SEVERITY_ERROR,
      ANARI_STATUS_UNKNOWN_ERROR,
      "anariSetParameter: failed (out of memory?)");
}

void DataParallelDevice::unsetParameter(ANARIObject object, const char *name)
{
  const std::string parameter = name ? name : "";
  if (object == (ANARIObject)this_device()) {
    if (parameter == "wrappedLibrary")
      setWrapParameter(parameter, ANARI_STRING, "");
    else if (parameter == "wrappedDevice")
      setWrapParameter(parameter, ANARI_STRING, "default");
    else {
      Device::unsetParameter(object, name);
      if (!wrapOpen() && m_wrappedDevice)
        m_wrappedDevice->unsetParameter((ANARIObject)m_wrappedDevice, name);
    }
    return;
  }
  if (parameter == "mpiCommunicator") {
    std::lock_guard lock(m_stateMutex);
    if (CommunicatorParameter *communicator = communicatorOf(object)) {
      communicator->staged = MPI_COMM_WORLD;
      return;
    }
  }
  if (anari::DeviceImpl *device = wrapped()) {
    if (liveWrapped(object, "anariUnsetParameter")
        && !unsetWrappedParameter(object, parameter))
      device->unsetParameter(object, name);
    return;
  }
  Device::unsetParameter(object, name);
}

void DataParallelDevice::unsetAllParameters(ANARIObject object)
{
  {
    std::lock_guard lock(m_stateMutex);
    if (CommunicatorParameter *communicator = communicatorOf(object))
      communicator->staged = MPI_COMM_WORLD;
  }
  if (object != (ANARIObject)this_device() && wrapped()) {
    unsetAllWrappedParameters(object);
    return;
  }
  Device::unsetAllParameters(object);
}

void DataParallelDevice::commitParameters(ANARIObject object)
{
  {
    std::lock_guard lock(m_stateMutex);
    if (CommunicatorParameter *communicator = communicatorOf(object))
      communicator->committed = communicator->staged;
  }
  if (object == (ANARIObject)this_device()) {
    Device::commitParameters(object);
    if (!wrapOpen() && m_wrappedDevice)
      m_wrappedDevice->commitParameters((ANARIObject)m_wrappedDevice);
    return;
  }
  if (wrapped()) {
    commitWrapped(object);
    return;
  }
  Device::commitParameters(object);
}

void DataParallelDevice::release(ANARIObject object)
{
  if (object == (ANARIObject)this_device()) {
    Device::release(object); // may delete this device: nothing after it
    return;
  }
  if (wrapped()) {
    releaseWrapped(object);
    return;
  }
  Device::release(object);
  // The application's last reference is gone: so is what this device kept
  // for the frame or world (an assembled image can be large).
  if (!lookup(object)) {
    std::lock_guard lock(m_stateMutex);
    m_frames.erase(object);
    m_worlds.erase(object);
  }
}

bool DataParallelDevice::collectiveWorldBounds(
    ANARIObject world, bool foundLocally, float bounds[6])
{
  MPI_Comm communicator = MPI_COMM_WORLD;
  {
    std::lock_guard lock(m_stateMutex);
    auto it = m_worlds.find(world);
    if (it != m_worlds.end())
      communicator = it->second.committed;
  }
  // The union of every process's bounds: lower corners by minimum, upper
  // corners by maximum (negated, so one reduction does both).
  const float infinity = std::numeric_limits<float>::infinity();
  float local[6];
  for (int i = 0; i < 3; i++) {
    local[i] = foundLocally ? bounds[i] : infinity;
    local[3 + i] = foundLocally ? -bounds[3 + i] : infinity;
  }
  float global[6];
  MPI_Allreduce(local, global, 6, MPI_FLOAT, MPI_MIN, communicator);
  if (!(global[0] <= -global[3]))
    return false; // no process has anything in its world
  for (int i = 0; i < 3; i++) {
    bounds[i] = global[i];
    bounds[3 + i] = -global[3 + i];
  }
  return true;
}

int DataParallelDevice::getProperty(ANARIObject object,
    const char *name,
    ANARIDataType type,
    void *mem,
    uint64_t size,
    ANARIWaitMask mask)
{
  if (int answered = getFrameProperty(object, name, type, mem, size))
    return answered;
  anari::DeviceImpl *device =
      object == (ANARIObject)this_device() ? nullptr : wrapped();
  const int found =
      device ? (liveWrapped(object, "anariGetProperty")
                    ? device->getProperty(object, name, type, mem, size, mask)
                    : 0)
             : Device::getProperty(object, name, type, mem, size, mask);
  const bool worldBounds = m_session.usable() && (mask & ANARI_WAIT) && name
                           && std::string(name) == "bounds"
                           && type == ANARI_FLOAT32_BOX3 && mem
                           && size >= 6 * sizeof(float);
  if (!worldBounds)
    return found;
  // A stale handle still takes part, so the other processes never wait on
  // this one.
  if (device) {
    std::lock_guard lock(m_stateMutex);
    auto it = m_wrappedObjects.find(object);
    if (it != m_wrappedObjects.end() && it->second.type != ANARI_WORLD)
      return found;
  } else if (Object *target = lookup(object);
             target && target->type() != ANARI_WORLD) {
    return found;
  }
  try {
    return collectiveWorldBounds(object, found != 0, (float *)mem) ? 1 : 0;
  } catch (...) {
    return found;
  }
}

int DataParallelDevice::getFrameProperty(ANARIObject object,
    const char *name,
    ANARIDataType type,
    void *mem,
    uint64_t size)
{
  const std::string property = name ? name : "";
  std::lock_guard lock(m_stateMutex);
  auto it = m_frames.find(object);
  if (it == m_frames.end() || !(m_wrappedDevice || lookup(object)) || !mem)
    return 0;
  if (property == "mpiBytesSent" && type == ANARI_UINT64
      && size >= sizeof(uint64_t)) {
    std::memcpy(mem, &it->second.bytesSent, sizeof(uint64_t));
    return 1;
  }
  if ((property == "mpiRank" || property == "mpiSize") && type == ANARI_INT32
      && size >= sizeof(int32_t) && m_session.usable()) {
    int value = 0;
    if (property == "mpiRank")
      MPI_Comm_rank(it->second.communicator.committed, &value);
    else
      MPI_Comm_size(it->second.communicator.committed, &value);
    const int32_t answer = value;
    std::memcpy(mem, &answer, sizeof(answer));
    return 1;
  }
  return 0;
}

const void *DataParallelDevice::frameBufferMap(ANARIFrame frame,
    const char *channel,
    uint32_t *width,
    uint32_t *height,
    ANARIDataType *pixelType)
{
  {
    std::lock_guard lock(m_stateMutex);
    auto it = m_frames.find(frame);
    if (it != m_frames.end() && channel) {
      auto assembled = it->second.assembled.find(channel);
      if (assembled != it->second.assembled.end()) {
        *width = it->second.width;
        *height = it->second.height;
        *pixelType = assembled->second.type;
        return assembled->second.pixels.data();
      }
    }
  }
  if (anari::DeviceImpl *device = wrapped()) {
    if (!liveWrapped(frame, "anariMapFrame")) {
      *width = *height = 0;
      *pixelType = ANARI_UNKNOWN;
      return nullptr;
    }
    return device->frameBufferMap(frame, channel, width, height, pixelType);
  }
  return Device::frameBufferMap(frame, channel, width, height, pixelType);
}

void DataParallelDevice::fingerprintWorld(
    const World &world, FrameDescriptor &d)
{
  const box3 bounds = world.bounds();
  const float corners[6] = {bounds.lower.x,
      bounds.lower.y,
      bounds.lower.z,
      bounds.upper.x,
      bounds.upper.y,
      bounds.upper.z};
  std::memcpy(d.worldBounds, corners, sizeof(corners));
  for (uint32_t i = 0; i < world.placementCount(); i++) {
    const Group &group = *world.placement(i).group;
    for (uint32_t s = 0; s < group.surfaceCount(); s++) {
      const Surface *surface = group.surface(s);
      if (surface && surface->geometry())
        d.worldPrimitives += surface->geometry()->primitiveCount();
    }
  }
  d.worldLights =
      uint32_t(world.ownDeclaredLights().size() + world.ownEmitterCount());
  d.worldVolumes = uint32_t(world.volumes().size());
  d.worldContent = world.contentHash();
}

FrameDescriptor DataParallelDevice::describe(
    Frame *frame, const FrameState &state) const
{
  FrameDescriptor d;
  d.frameIndex = state.index;
  d.renderIndex = state.renders;
  d.mode = uint32_t(m_mode);
  if (!frame)
    return d;
  d.width = frame->width();
  d.height = frame->height();
  d.valid = frame->isValid() ? 1 : 0;
  for (int c = 0; c < kChannelCount; c++)
    d.channelTypes[c] = frame->channelType(kChannelNames[c]);
  if (m_mode == RenderMode::Replicated && frame->world())
    fingerprintWorld(*frame->world(), d);
  if (const Renderer *renderer = frame->renderer()) {
    const std::string &subtype = renderer->subtype();
    std::memcpy(d.renderer,
        subtype.data(),
        std::min(subtype.size(), sizeof(d.renderer) - 1));
    d.rendererContent = renderer->contentHash();
  }
  if (const Camera *camera = frame->camera())
    d.cameraContent = camera->contentHash();
  return d;
}

void DataParallelDevice::renderFrame(ANARIFrame handle)
try {
  if (wrapped()) {
    renderWrapped(handle);
    return;
  }
  if (!m_session.usable()) {
    Device::renderFrame(handle);
    return;
  }
  Object *object = lookup(handle);
  Frame *frame = object && object->type() == ANARI_FRAME
                     ? static_cast<Frame *>(object)
                     : nullptr;
  // The committed size, renderer, channels and world are what the
  // processes compare.
  if (frame)
    flushCommitsAndRefresh(*frame);
  else
    flushCommits();
  FrameState unknownFrame; // a stale handle still answers the agreement
  unknownFrame.index = ~0ull;
  FrameState *state = &unknownFrame;
  {
    std::lock_guard lock(m_stateMutex);
    auto it = m_frames.find(handle);
    if (frame && it != m_frames.end())
      state = &it->second;
    state->assembled.clear();
    state->bytesSent = 0;
  }
  const MPI_Comm communicator = state->communicator.committed;
  const RendezvousResult meeting = m_rendezvous.meet(
      describe(frame, *state), communicator, m_timeoutSeconds);
  if (!meeting.render) {
    reportStatus(handle,
        ANARI_FRAME,
        ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_OPERATION,
        "anariRenderFrame: nothing is rendered: " + meeting.problem);
    return;
  }
  state->renders++;
  if (!frame || !meeting.allValid) {
    Device::renderFrame(handle); // reports what the frame lacks
    return;
  }
  state->width = frame->width();
  state->height = frame->height();
  if (frame->renderer()->denoise() && !state->denoiseWarned) {
    state->denoiseWarned = true;
    reportStatus(handle,
        ANARI_FRAME,
        ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_OPERATION,
        "anariRenderFrame: the renderer's 'denoise' is not applied to the"
        " image rank 0 assembles from several processes");
  }
  if (m_mode == RenderMode::Replicated)
    renderReplicated(handle, *frame, *state, communicator);
  else if (m_mode == RenderMode::PathTracer
           && tracesPathsAcross(handle, *frame))
    renderPathTraced(handle, *frame, *state, communicator);
  else
    renderComposited(handle, *frame, *state, communicator);
} catch (const std::exception &e) {
  reportStatus(handle,
      ANARI_FRAME,
      ANARI_SEVERITY_ERROR,
      ANARI_STATUS_UNKNOWN_ERROR,
      std::string("anariRenderFrame: ") + e.what());
} catch (...) {
  reportStatus(handle,
      ANARI_FRAME,
      ANARI_SEVERITY_ERROR,
      ANARI_STATUS_UNKNOWN_ERROR,
      "anariRenderFrame: failed for an unknown reason");
}

uint64_t DataParallelDevice::shareWorldLights(
    ANARIFrame handle, World &world, MPI_Comm communicator, bool withEmitters)
{
  const EmitterExchangeResult shared =
      shareLights(world, communicator, withEmitters);
  if (!shared.problem.empty()) {
    reportStatus(handle,
        ANARI_FRAME,
        ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_OPERATION,
        "anariRenderFrame: " + shared.problem);
  }
  return shared.bytesSent;
}

void DataParallelDevice::renderComposited(
    ANARIFrame handle, Frame &frame, FrameState &state, MPI_Comm communicator)
{
  frame.share({.keepDepth = true, .omitBackground = true});
  uint64_t lightBytes = 0;
  if (World *world = frame.world()) {
    // Lit by its own emitters, and by every process's declared lights for
    // the path tracer (the only renderer that reads lights; every process
    // runs the same one, so all take part alike).
    if (dynamic_cast<const PathTracer *>(frame.renderer()))
      lightBytes = shareWorldLights(handle, *world, communicator, false);
    else
      world->keepOwnEmitters();
  }
  Device::renderFrame(handle);
  const FrameBuffers &local = frame.linearPixels();
  politeBarrier(communicator);
  DepthCompositor compositor(communicator, state.width, state.height);
  CompositedImage image = compositor.composite(local.color, local.depth);
  const bool rankZero = !image.color.empty();
  if (rankZero && frame.renderer()) {
    const Renderer &renderer = *frame.renderer();
    addBackground(state.width, image.color, [&](uint32_t x, uint32_t y) {
      return renderer.background(x, y, state.width, state.height);
    });
  }
  std::map<std::string, MappedChannel> assembled;
  for (const char *name : kChannelNames) {
    const ANARIDataType type = frame.channelType(name);
    if (type == ANARI_UNKNOWN)
      continue;
    MappedChannel channel{type, {}};
    const std::string channelName = name;
    if (channelName == "channel.color") {
      if (!rankZero)
        continue;
      channel.pixels.resize(image.color.size() * pixelSize(type));
      writeColorPixels(
          type, image.color.data(), image.color.size(), channel.pixels.data());
    } else if (channelName == "channel.depth") {
      if (!rankZero)
        continue;
      channel.pixels.resize(image.depth.size() * sizeof(float));
      std::memcpy(
          channel.pixels.data(), image.depth.data(), channel.pixels.size());
    } else {
      // Channels that do not blend show the nearest fragment's process.
      uint32_t width = 0, height = 0;
      ANARIDataType mappedType = ANARI_UNKNOWN;
      const void *pixels =
          Device::frameBufferMap(handle, name, &width, &height, &mappedType);
      const bool usable = pixels && mappedType == type && width == state.width
                          && height == state.height;
      channel.pixels = compositor.takeNearest(
          usable ? (const unsigned char *)pixels : nullptr, pixelSize(type));
      if (!rankZero)
        continue;
    }
    assembled[name] = std::move(channel);
  }
  std::lock_guard lock(m_stateMutex);
  state.assembled = std::move(assembled);
  state.bytesSent = compositor.bytesSent() + lightBytes;
}

void DataParallelDevice::renderReplicated(
    ANARIFrame handle, Frame &frame, FrameState &state, MPI_Comm communicator)
{
  int rank = 0, ranks = 1;
  MPI_Comm_rank(communicator, &rank);
  MPI_Comm_size(communicator, &ranks);
  uint64_t bytesSent = 0;
  frame.share({.tileRowPart = uint32_t(rank), .tileRowParts = uint32_t(ranks)});
  if (World *world = frame.world())
    world->keepOwnEmitters(); // every process holds every emitter
  Device::renderFrame(handle);
  frame.ready(ANARI_WAIT);
  politeBarrier(communicator);
  std::map<std::string, MappedChannel> assembled;
  for (const char *name : kChannelNames) {
    const ANARIDataType type = frame.channelType(name);
    if (type == ANARI_UNKNOWN)
      continue;
    const size_t bytes = size_t(state.width) * state.height * pixelSize(type);
    uint32_t width = 0, height = 0;
    ANARIDataType mappedType = ANARI_UNKNOWN;
    const void *pixels =
        Device::frameBufferMap(handle, name, &width, &height, &mappedType);
    // A process that could not render still sends rows, of zeros, so the
    // others are not left waiting.
    std::vector<unsigned char> zeros;
    if (!pixels || mappedType != type || width != state.width
        || height != state.height) {
      zeros.assign(bytes, 0);
      pixels = zeros.data();
    }
    std::vector<unsigned char> image = gatherTileRows(communicator,
        (const unsigned char *)pixels,
        state.width,
        state.height,
        pixelSize(type),
        Frame::kTileSize,
        bytesSent);
    if (rank == 0)
      assembled[name] = MappedChannel{type, std::move(image)};
  }
  std::lock_guard lock(m_stateMutex);
  state.assembled = std::move(assembled);
  state.bytesSent = bytesSent;
}

std::unique_ptr<RayTransport> DataParallelDevice::transportFor(
    const World &world)
{
  std::lock_guard lock(m_stateMutex);
  if (m_pathTracing) {
    return std::make_unique<DistributedTransport>(
        world, m_pathTracing->communicator, *m_pathTracing->bytesSent);
  }
  return Device::transportFor(world);
}

bool DataParallelDevice::tracesPathsAcross(
    ANARIFrame handle, const Frame &frame)
{
  // Only the path tracer shades through its transport; other renderers
  // see their own process's world and are composited. Every process runs
  // the same renderer subtype (the meeting checked), so all decide alike.
  if (!dynamic_cast<const PathTracer *>(frame.renderer()))
    return false;
  // The frame renders on the device's render thread while the calling
  // thread waits: MPI must allow calls from any one thread at a time. The
  // level is the same on every process of an mpirun, so all decide alike.
  int level = MPI_THREAD_SINGLE;
  MPI_Query_thread(&level);
  if (level >= MPI_THREAD_SERIALIZED)
    return true;
  if (!m_threadLevelWarned) {
    m_threadLevelWarned = true;
    reportStatus(handle,
        ANARI_FRAME,
        ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_OPERATION,
        "anariRenderFrame: 'pathtracer' mode needs MPI initialised with"
        " MPI_THREAD_SERIALIZED or more; the frame is composited instead");
  }
  return false;
}

void DataParallelDevice::renderPathTraced(
    ANARIFrame handle, Frame &frame, FrameState &state, MPI_Comm communicator)
{
  // Every process renders every pixel: the paths, replicated, advance in
  // lockstep and end the same everywhere, so rank 0's own buffers are the
  // image.
  frame.share({.lockstep = true});
  uint64_t bytesSent = 0;
  // Any process may shade any path, so each samples every process's
  // emissive surfaces and declared lights (sent again only when a world
  // placed them anew).
  if (World *world = frame.world())
    bytesSent += shareWorldLights(handle, *world, communicator, true);
  // A world changed on some processes restarts their accumulation only:
  // every process must start from the same sample, or their paths would
  // differ and the lockstep break. One reduction of (first, ~last).
  uint32_t samples[2] = {frame.nextSampleIndex(), ~frame.nextSampleIndex()};
  MPI_Allreduce(MPI_IN_PLACE, samples, 2, MPI_UINT32_T, MPI_MIN, communicator);
  if (samples[0] != ~samples[1])
    frame.restartAccumulation();
  {
    std::lock_guard lock(m_stateMutex);
    m_pathTracing = PathTracing{communicator, &bytesSent};
  }
  // Later frames trace locally, even when this render throws.
  struct EndPathTracing
  {
    DataParallelDevice &device;
    ~EndPathTracing()
    {
      std::lock_guard lock(device.m_stateMutex);
      device.m_pathTracing.reset();
    }
  } end{*this};
  Device::renderFrame(handle);
  frame.ready(ANARI_WAIT);
  std::lock_guard lock(m_stateMutex);
  state.bytesSent = bytesSent;
}

} // namespace prism::mpi
