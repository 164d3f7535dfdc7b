// anariRenderFrame on prism_mpi: the processes meet (Rendezvous), then the
// local renderer renders this process's part and the collective parts make
// the image: depth compositing (composite mode, and any wrapped library),
// tile row gathering (replicated) or paths traced across the processes
// (pathtracer).
#include "DataParallelDevice.h"

#include "DepthCompositor.h"
#include "PoliteWait.h"
#include "TileRowGather.h"

#include "frame/PixelFormat.h"

#include <cstring>
#include <limits>
#include <optional>

namespace prism::mpi {
namespace {

const float4 kTransparent{0.f, 0.f, 0.f, 0.f};

} // namespace

RenderMode DataParallelDevice::effectiveMode(ANARIFrame handle)
{
  if (m_local->renders(m_mode))
    return m_mode;
  if (m_modeExplicit && !m_wrappedModeWarned) {
    m_wrappedModeWarned = true;
    report(handle,
        ANARI_FRAME,
        ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_OPERATION,
        std::string("anariRenderFrame: mode '") + toString(m_mode)
            + "' needs the built-in prism core; frames of wrapped "
            + m_local->description() + " are composited instead");
  }
  return RenderMode::Composite;
}

void DataParallelDevice::renderFrame(ANARIFrame handle)
try {
  LocalRenderer &renderer = local();
  const bool collective = m_session.usable();
  if (!collective && renderer.rendersApplicationPixels()) {
    renderer.device().renderFrame(handle);
    return;
  }
  const RenderMode mode =
      renderer.renders(m_mode) ? m_mode : RenderMode::Composite;
  FrameDescriptor descriptor;
  const bool live = renderer.describe(handle, mode, descriptor);
  FrameState unknownFrame; // a stale handle still answers the agreement
  unknownFrame.index = ~0ull;
  FrameState *state = &unknownFrame;
  {
    std::lock_guard lock(m_stateMutex);
    auto it = m_frames.find(handle);
    if (live && it != m_frames.end())
      state = &it->second;
    state->assembled.clear();
    state->bytesSent = 0;
    state->activePixels.reset();
  }
  descriptor.frameIndex = state->index;
  descriptor.renderIndex = state->renders;
  descriptor.mode = uint32_t(mode);
  const MPI_Comm communicator = state->communicator.committed;
  bool allValid = descriptor.valid != 0;
  if (collective) {
    const RendezvousResult meeting =
        m_rendezvous.meet(descriptor, communicator, m_timeoutSeconds);
    if (!meeting.render) {
      report(handle,
          ANARI_FRAME,
          ANARI_SEVERITY_ERROR,
          ANARI_STATUS_INVALID_OPERATION,
          "anariRenderFrame: nothing is rendered: " + meeting.problem);
      return;
    }
    state->renders++;
    allValid = meeting.allValid;
  }
  if (state == &unknownFrame || !allValid) {
    renderer.renderAlone(handle); // reports what the frame lacks
    return;
  }
  state->width = descriptor.width;
  state->height = descriptor.height;
  if (renderer.denoises(handle) && !state->denoiseWarned) {
    state->denoiseWarned = true;
    report(handle,
        ANARI_FRAME,
        ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_OPERATION,
        "anariRenderFrame: the renderer's 'denoise' is not applied to the"
        " image rank 0 assembles from several processes");
  }
  const RenderMode rendered = effectiveMode(handle); // said once
  if (!collective)
    renderComposited(handle, *state, MPI_COMM_NULL);
  else if (rendered == RenderMode::Replicated)
    renderReplicated(handle, *state, communicator);
  else if (rendered == RenderMode::PathTracer && tracesPathsAcross(handle))
    renderPathTraced(handle, *state, communicator);
  else
    renderComposited(handle, *state, communicator);
} catch (const std::exception &e) {
  report(handle,
      ANARI_FRAME,
      ANARI_SEVERITY_ERROR,
      ANARI_STATUS_UNKNOWN_ERROR,
      std::string("anariRenderFrame: ") + e.what());
} catch (...) {
  report(handle,
      ANARI_FRAME,
      ANARI_SEVERITY_ERROR,
      ANARI_STATUS_UNKNOWN_ERROR,
      "anariRenderFrame: failed for an unknown reason");
}

// Composite mode /////////////////////////////////////////////////////////////

void DataParallelDevice::renderComposited(
    ANARIFrame handle, FrameState &state, MPI_Comm communicator)
{
  LocalRenderer &renderer = *m_local;
  uint64_t lightBytes = 0;
  const LinearImage own =
      renderer.renderForCompositing(handle, communicator, lightBytes);
  const std::vector<float4> &color = *own.color;
  const std::vector<float> &depth = *own.depth;
  CompositedImage image;
  std::optional<DepthCompositor> compositor;
  if (communicator != MPI_COMM_NULL) {
    politeBarrier(communicator);
    compositor.emplace(communicator, state.width, state.height);
    image = compositor->composite(color, depth);
  } else {
    // No MPI: this process's pixels are the image.
    image.color = color;
    image.depth = depth;
    if (image.color.empty()) {
      const size_t pixels = size_t(state.width) * state.height;
      image.color.assign(pixels, kTransparent);
      image.depth.assign(pixels, std::numeric_limits<float>::infinity());
    }
  }
  if (!image.color.empty()) {
    addBackground(state.width,
        image.color,
        renderer.backgroundOf(handle, state.width, state.height));
  }
  auto assembled = assembleComposite(
      handle, state, image, own, compositor ? &*compositor : nullptr);
  std::lock_guard lock(m_stateMutex);
  state.assembled = std::move(assembled);
  state.bytesSent = (compositor ? compositor->bytesSent() : 0) + lightBytes;
}

std::map<std::string, DataParallelDevice::MappedChannel>
DataParallelDevice::assembleComposite(ANARIFrame handle,
    const FrameState &state,
    const CompositedImage &image,
    const LinearImage &own,
    DepthCompositor *compositor)
{
  LocalRenderer &renderer = *m_local;
  anari::DeviceImpl &device = renderer.device();
  const bool rankZero = !image.color.empty();
  // Elsewhere, a renderer's own color and depth are its frame's channels;
  // a wrapped device's are linear, and are converted here.
  const bool ownChannels = !rankZero && !renderer.rendersApplicationPixels();
  const size_t pixels = size_t(state.width) * state.height;
  std::map<std::string, MappedChannel> assembled;
  for (int c = 0; c < kChannelCount; c++) {
    const ANARIDataType type = renderer.channelType(handle, c);
    const size_t unit = pixelSize(type);
    if (type == ANARI_UNKNOWN || unit == 0)
      continue;
    const char *name = kChannelNames[c];
    MappedChannel channel{type, {}};
    if (c == 0 && (rankZero || ownChannels)) {
      const std::vector<float4> &source = rankZero ? image.color : *own.color;
      if (source.empty())
        continue;
      channel.pixels.resize(source.size() * unit);
      writeColorPixels(
          type, source.data(), source.size(), channel.pixels.data());
    } else if (c == 1 && (rankZero || ownChannels)) {
      const std::vector<float> &source = rankZero ? image.depth : *own.depth;
      if (source.empty())
        continue;
      channel.pixels.resize(source.size() * sizeof(float));
      std::memcpy(channel.pixels.data(), source.data(), channel.pixels.size());
    } else if (c < 2) {
      continue;
    } else {
      // Channels that do not blend show the nearest fragment's process.
      uint32_t w = 0, h = 0;
      ANARIDataType mappedType = ANARI_UNKNOWN;
      const void *mapped =
          device.frameBufferMap(handle, name, &w, &h, &mappedType);
      const bool usable =
          mapped && mappedType == type && w == state.width && h == state.height;
      const auto *mine = usable ? (const unsigned char *)mapped : nullptr;
      if (compositor)
        channel.pixels = compositor->takeNearest(mine, unit);
      else if (mine)
        channel.pixels.assign(mine, mine + pixels * unit);
      else
        channel.pixels.assign(pixels * unit, 0);
      if (mapped)
        device.frameBufferUnmap(handle, name);
      if (!rankZero)
        continue; // mapped from the local frame itself
    }
    assembled[name] = std::move(channel);
  }
  return assembled;
}

// Replicated mode ////////////////////////////////////////////////////////////

void DataParallelDevice::renderReplicated(
    ANARIFrame handle, FrameState &state, MPI_Comm communicator)
{
  LocalRenderer &renderer = *m_local;
  anari::DeviceImpl &device = renderer.device();
  int rank = 0, ranks = 1;
  MPI_Comm_rank(communicator, &rank);
  MPI_Comm_size(communicator, &ranks);
  uint64_t bytesSent = 0;
  renderer.renderTileRows(handle, uint32_t(rank), uint32_t(ranks));
  // Each process knows its own rows' blocks only: the frame's count is
  // the sum (every process reduces, even one whose frame could not say).
  uint64_t active = 0;
  device.getProperty(handle,
      "activePixels",
      ANARI_UINT64,
      &active,
      sizeof(active),
      ANARI_WAIT);
  politeBarrier(communicator); // the sum below then waits for no one
  MPI_Allreduce(MPI_IN_PLACE, &active, 1, MPI_UINT64_T, MPI_SUM, communicator);
  std::map<std::string, MappedChannel> assembled;
  for (int c = 0; c < kChannelCount; c++) {
    const ANARIDataType type = renderer.channelType(handle, c);
    if (type == ANARI_UNKNOWN)
      continue;
    const char *name = kChannelNames[c];
    const size_t bytes = size_t(state.width) * state.height * pixelSize(type);
    uint32_t width = 0, height = 0;
    ANARIDataType mappedType = ANARI_UNKNOWN;
    const void *pixels =
        device.frameBufferMap(handle, name, &width, &height, &mappedType);
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
        renderer.tileSize(),
        bytesSent);
    if (rank == 0)
      assembled[name] = MappedChannel{type, std::move(image)};
  }
  std::lock_guard lock(m_stateMutex);
  state.assembled = std::move(assembled);
  state.bytesSent = bytesSent;
  state.activePixels = active;
}

// Pathtracer mode ////////////////////////////////////////////////////////////

bool DataParallelDevice::tracesPathsAcross(ANARIFrame handle)
{
  // Only a renderer that traces wavefronts shades through its transport;
  // others see their own process's world and are composited. Every
  // process runs the same renderer subtype (the meeting checked), so all
  // decide alike.
  if (!m_local->tracesWavefronts(handle))
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
    report(handle,
        ANARI_FRAME,
        ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_OPERATION,
        "anariRenderFrame: 'pathtracer' mode needs MPI initialised with"
        " MPI_THREAD_SERIALIZED or more; the frame is composited instead");
  }
  return false;
}

void DataParallelDevice::renderPathTraced(
    ANARIFrame handle, FrameState &state, MPI_Comm communicator)
{
  // Every process renders every pixel in lockstep, so rank 0's own
  // buffers are the image.
  uint64_t bytesSent = 0;
  m_local->renderPathsAcross(handle, communicator, bytesSent);
  std::lock_guard lock(m_stateMutex);
  state.bytesSent = bytesSent;
}

} // namespace prism::mpi
