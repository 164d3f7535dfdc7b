#include "CoreRenderer.h"

#include "DistributedTransport.h"
#include "EmitterExchange.h"

#include "Device.h"
#include "camera/Camera.h"
#include "frame/Frame.h"
#include "geometry/Geometry.h"
#include "renderer/Renderer.h"
#include "world/Group.h"
#include "world/Surface.h"
#include "world/World.h"

#include <algorithm>
#include <cstring>

namespace prism::mpi {
namespace {

// Replicated mode: what must be the same in every process's world.
void fingerprintWorld(const World &world, FrameDescriptor &d)
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
    const Group &group = *world.placement(i).group();
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

} // namespace

CoreRenderer::CoreRenderer(ANARILibrary library) : m_device(new Device(library))
{}

CoreRenderer::~CoreRenderer()
{
  // The device's last public reference: frames in flight finish first.
  m_device->release((ANARIObject)m_device->this_device());
}

anari::DeviceImpl &CoreRenderer::device()
{
  return *m_device;
}

std::string CoreRenderer::description() const
{
  return "the built-in prism core";
}

bool CoreRenderer::renders(RenderMode) const
{
  return true;
}

bool CoreRenderer::rendersApplicationPixels() const
{
  return true;
}

ANARIDataType CoreRenderer::typeOf(ANARIObject handle)
{
  const Object *object = m_device->lookup(handle);
  return object ? object->type() : ANARI_UNKNOWN;
}

void CoreRenderer::setThreads(int threads)
{
  m_device->taskPool().setThreads(threads);
}

Frame *CoreRenderer::frameOf(ANARIFrame handle) const
{
  Object *object = m_device->lookup(handle);
  return object && object->type() == ANARI_FRAME ? static_cast<Frame *>(object)
                                                 : nullptr;
}

bool CoreRenderer::describe(
    ANARIFrame handle, RenderMode mode, FrameDescriptor &d)
{
  Frame *frame = frameOf(handle);
  if (!frame) {
    m_device->flushCommits();
    return false;
  }
  // The committed size, renderer, channels and world are what the
  // processes compare.
  m_device->flushCommitsAndRefresh(*frame);
  d.width = frame->width();
  d.height = frame->height();
  d.valid = frame->isValid() ? 1 : 0;
  for (int c = 0; c < kChannelCount; c++)
    d.channelTypes[c] = frame->channelType(kChannelNames[c]);
  if (mode == RenderMode::Replicated && frame->world())
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
  return true;
}

ANARIDataType CoreRenderer::channelType(ANARIFrame handle, int channel)
{
  const Frame *frame = frameOf(handle);
  return frame ? frame->channelType(kChannelNames[channel]) : ANARI_UNKNOWN;
}

bool CoreRenderer::denoises(ANARIFrame handle)
{
  const Frame *frame = frameOf(handle);
  return frame && frame->renderer() && frame->renderer()->denoise();
}

void CoreRenderer::renderAlone(ANARIFrame frame)
{
  m_device->renderFrame(frame);
}

uint64_t CoreRenderer::shareWorldLights(
    ANARIFrame handle, World &world, MPI_Comm communicator, bool withEmitters)
{
  const EmitterExchangeResult shared =
      shareLights(world, communicator, withEmitters);
  if (!shared.problem.empty()) {
    m_device->reportStatus(handle,
        ANARI_FRAME,
        ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_OPERATION,
        "anariRenderFrame: " + shared.problem);
  }
  return shared.bytesSent;
}

LinearImage CoreRenderer::renderForCompositing(
    ANARIFrame handle, MPI_Comm communicator, uint64_t &bytesSent)
{
  Frame &frame = *frameOf(handle);
  frame.share({.keepDepth = true, .omitBackground = true});
  if (World *world = frame.world()) {
    // Lit by its own emitters, and by every process's declared lights for
    // a renderer that reads lights (every process runs the same one, so
    // all take part alike).
    if (frame.renderer() && frame.renderer()->tracesWavefronts())
      bytesSent += shareWorldLights(handle, *world, communicator, false);
    else
      world->keepOwnEmitters();
  }
  m_device->renderFrame(handle);
  const FrameBuffers &local = frame.linearPixels();
  return {&local.color, &local.depth};
}

LocalRenderer::BackgroundAt CoreRenderer::backgroundOf(
    ANARIFrame handle, uint32_t width, uint32_t height)
{
  const Frame *frame = frameOf(handle);
  const Renderer *renderer = frame ? frame->renderer() : nullptr;
  if (!renderer)
    return [](uint32_t, uint32_t) {
      return float4{0.f, 0.f, 0.f, 1.f};
    };
  return [renderer, width, height](uint32_t x, uint32_t y) {
    return renderer->background(x, y, width, height);
  };
}

void CoreRenderer::renderTileRows(
    ANARIFrame handle, uint32_t part, uint32_t parts)
{
  Frame &frame = *frameOf(handle);
  frame.share({.tileRowPart = part, .tileRowParts = parts});
  if (World *world = frame.world())
    world->keepOwnEmitters(); // every process holds every emitter
  m_device->renderFrame(handle);
  frame.ready(ANARI_WAIT);
}

uint32_t CoreRenderer::tileSize() const
{
  return Frame::kTileSize;
}

bool CoreRenderer::tracesWavefronts(ANARIFrame handle)
{
  const Frame *frame = frameOf(handle);
  return frame && frame->renderer() && frame->renderer()->tracesWavefronts();
}

void CoreRenderer::renderPathsAcross(
    ANARIFrame handle, MPI_Comm communicator, uint64_t &bytesSent)
{
  Frame &frame = *frameOf(handle);
  // Every process renders every pixel: the paths, replicated, advance in
  // lockstep and end the same everywhere, so rank 0's own buffers are the
  // image.
  frame.share({.lockstep = true});
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
  m_device->setTransportSource([communicator, &bytesSent](const World &world) {
    return std::make_unique<DistributedTransport>(
        world, communicator, bytesSent);
  });
  // Later frames trace locally, even when this render throws.
  struct EndPathTracing
  {
    Device &device;
    ~EndPathTracing()
    {
      device.setTransportSource({});
    }
  } end{*m_device};
  m_device->renderFrame(handle);
  frame.ready(ANARI_WAIT);
}

} // namespace prism::mpi
