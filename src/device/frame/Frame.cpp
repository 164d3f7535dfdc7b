#include "Frame.h"

#include "../camera/Camera.h"
#include "../object/DeviceState.h"
#include "../parallel/TaskPool.h"
#include "../renderer/Renderer.h"
#include "../renderer/wavefront/RayTransport.h"
#include "../world/World.h"
#include "PixelFormat.h"

#include "MachineLimits.h"

#include "anari/frontend/type_utility.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <climits>
#include <cstring>
#include <memory>

namespace prism {
namespace {

// Mapped types each channel accepts (spec 5.1, table 10).
const std::map<std::string, std::vector<ANARIDataType>> &channelFormats()
{
  static const std::map<std::string, std::vector<ANARIDataType>> formats = {
      {"channel.color",
          {ANARI_UFIXED8_VEC4, ANARI_UFIXED8_RGBA_SRGB, ANARI_FLOAT32_VEC4}},
      {"channel.depth", {ANARI_FLOAT32}},
      {"channel.normal", {ANARI_FIXED16_VEC3, ANARI_FLOAT32_VEC3}},
      {"channel.albedo",
          {ANARI_UFIXED8_VEC3, ANARI_UFIXED8_RGB_SRGB, ANARI_FLOAT32_VEC3}},
      {"channel.primitiveId", {ANARI_UINT32}},
      {"channel.objectId", {ANARI_UINT32}},
      {"channel.instanceId", {ANARI_UINT32}},
  };
  return formats;
}

// The samples of one tile are rendered in order by whichever thread owns
// the tile at that moment: claiming a (tile, sample) pair adds one to the
// tile's pending count, and the thread that raised it from zero renders
// samples until none is pending. No thread ever waits for another.
struct TileSamples
{
  std::atomic<uint32_t> pending{0};
  uint32_t next{0}; // touched by the owner only
};

} // namespace

Frame::Frame(DeviceState &device) : Object(device, ANARI_FRAME, "") {}

Frame::~Frame() = default;

void Frame::commitParameters()
{
  // dynamic_cast: an object of an unknown subtype is inert, not a Camera.
  m_world = dynamic_cast<World *>(readObject("world", {ANARI_WORLD}));
  m_camera = dynamic_cast<Camera *>(readObject("camera", {ANARI_CAMERA}));
  m_renderer =
      dynamic_cast<Renderer *>(readObject("renderer", {ANARI_RENDERER}));
  struct Size
  {
    uint32_t width, height;
  };
  const auto size = read<Size>("size", ANARI_UINT32_VEC2, {0, 0});
  m_width = size.width;
  m_height = size.height;
  m_completionCallback = read<ANARIFrameCompletionCallback>(
      "frameCompletionCallback", ANARI_FRAME_COMPLETION_CALLBACK, nullptr);
  m_completionUserPtr = read<const void *>(
      "frameCompletionCallbackUserData", ANARI_VOID_POINTER, nullptr);
  m_accumulation = readBool("accumulation", false);

  std::map<std::string, Channel> channels;
  for (const auto &[name, accepted] : channelFormats()) {
    const Parameter *p = readAny(name.c_str());
    if (!p)
      continue;
    if (p->type() != ANARI_DATA_TYPE) {
      wrongType(name.c_str(), p->type(), {ANARI_DATA_TYPE});
      continue;
    }
    const ANARIDataType format = p->as<int32_t>();
    if (std::find(accepted.begin(), accepted.end(), format) == accepted.end()) {
      std::string list;
      for (ANARIDataType t : accepted)
        list += std::string(list.empty() ? "" : ", ") + anari::toString(t);
      report(ANARI_SEVERITY_WARNING,
          ANARI_STATUS_INVALID_ARGUMENT,
          "'%s' cannot be %s (accepted: %s); the channel is disabled",
          name.c_str(),
          anari::toString(format),
          list.c_str());
      continue;
    }
    channels[name].type = format;
  }
  m_channels = std::move(channels);
}

bool Frame::isValid() const
{
  return m_world && m_camera && m_renderer && m_width > 0 && m_height > 0
         && m_world->isValid() && m_camera->isValid() && m_renderer->isValid();
}

void Frame::renderAsync()
{
  waitUntilDone();
  if (!isValid()) {
    std::string missing;
    auto add = [&](bool ok, const char *what) {
      if (!ok)
        missing += std::string(missing.empty() ? "" : ", ") + what;
    };
    add(m_world && m_world->isValid(), "a valid 'world'");
    add(m_camera && m_camera->isValid(), "a valid 'camera'");
    add(m_renderer && m_renderer->isValid(), "a valid 'renderer'");
    add(m_width > 0 && m_height > 0, "a positive 'size'");
    report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_OPERATION,
        "anariRenderFrame: frame not rendered; it needs %s",
        missing.c_str());
    return;
  }
  if (!fitsInMemory()) {
    dropRenderedPixels();
    return;
  }
  {
    std::lock_guard lock(m_stateMutex);
    m_rendering = true;
  }
  // Any committed change (an epoch moved) restarts the accumulation.
  m_sampleIndex = nextSampleIndex();
  m_samplesDone = m_sampleIndex;
  m_accumulatedVersion = sceneVersion();
  // At the renderer's sampleLimit the accumulation has converged: the
  // render finishes at once, nothing traced, the image as it is.
  const uint32_t limit = m_renderer->sampleLimit();
  const bool converged = m_accumulation && limit > 0 && m_sampleIndex >= limit
                         && !m_accumulated.color.empty();
  // pixelSamples per render, never past the sampleLimit.
  m_samplesThisRender = m_renderer->pixelSamples();
  if (m_accumulation && limit > 0 && !converged)
    m_samplesThisRender =
        std::min(m_samplesThisRender, limit - std::min(limit, m_sampleIndex));
  m_samplesThisRender = std::max(m_samplesThisRender, 1u);
  m_averaging = m_accumulation || m_samplesThisRender > 1;
  m_cancel = false;
  m_tileSamplesDone = 0;
  m_start = std::chrono::steady_clock::now();
  device().frameStarted();
  // The callback is the one committed now: a commit may replace it while
  // the task is finishing.
  const Completion completion{m_completionCallback, m_completionUserPtr};
  device().taskPool().run([this, completion, converged] {
    try {
      if (!converged)
        render();
    } catch (const std::bad_alloc &) {
      dropRenderedPixels();
      report(ANARI_SEVERITY_ERROR,
          ANARI_STATUS_OUT_OF_MEMORY,
          "anariRenderFrame: out of memory rendering %ux%u; the frame is "
          "empty",
          m_width,
          m_height);
    }
    finish(completion); // the task's last touch of the frame
  });
}

size_t Frame::bytesNeeded() const
{
  size_t perPixel = sizeof(float4);
  for (const auto &[name, channel] : m_channels)
    perPixel += anari::sizeOf(channel.type);
  // Working buffers for every channel besides color, as a bound.
  size_t working = sizeof(float4) + sizeof(float) + 2 * sizeof(float3)
                   + 3 * sizeof(uint32_t);
  const bool averages =
      m_accumulation || (m_renderer && m_renderer->pixelSamples() > 1);
  perPixel += working * (averages ? 2 : 1);
  if (m_renderer && m_renderer->denoise())
    perPixel += 4 * sizeof(float4);
  return size_t(m_width) * m_height * perPixel;
}

bool Frame::fitsInMemory()
{
  const size_t needed = bytesNeeded();
  if (limits::fitsInMemory(needed))
    return true;
  report(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_OUT_OF_MEMORY,
      "anariRenderFrame: a %ux%u frame needs %s, more than %s; the frame is "
      "not rendered",
      m_width,
      m_height,
      limits::byteSize(needed).c_str(),
      limits::memoryLimitText().c_str());
  return false;
}

void Frame::dropRenderedPixels()
{
  m_buffers = FrameBuffers{};
  m_accumulated = FrameBuffers{};
  m_samplesDone = 0;
  m_accumulatedVersion = ~0ull;
  for (auto &[name, channel] : m_channels)
    std::vector<unsigned char>().swap(channel.pixels);
}

void Frame::render()
{
  // The denoiser is guided by depth, normal and albedo, mapped or not.
  m_denoise = m_renderer->denoise();
  const FrameBuffers::Needs needs{
      m_denoise || m_sharing.keepDepth || m_channels.count("channel.depth") > 0,
      m_denoise || m_channels.count("channel.normal") > 0,
      m_denoise || m_channels.count("channel.albedo") > 0,
      m_channels.count("channel.primitiveId") > 0,
      m_channels.count("channel.objectId") > 0,
      m_channels.count("channel.instanceId") > 0};
  if (m_buffers.width != m_width || m_buffers.height != m_height
      || !(m_buffers.needs == needs))
    m_buffers.resize(m_width, m_height, needs);
  if (m_averaging
      && (m_accumulated.width != m_width || m_accumulated.height != m_height
          || !(m_accumulated.needs == needs))) {
    m_accumulated.resize(m_width, m_height, needs);
    m_samplesDone = 0;
  }
  // A new average (restarted, resized, or every render without
  // accumulation) samples every tile again. In lockstep every process
  // renders every row, so there tiles never stop.
  if (m_samplesDone == 0) {
    m_convergence.reset(m_width,
        m_height,
        m_averaging && !m_sharing.lockstep ? m_renderer->errorThreshold()
                                           : 0.f);
  }
  const size_t pixels = size_t(m_width) * m_height;
  for (auto &[name, channel] : m_channels)
    channel.pixels.resize(pixels * anari::sizeOf(channel.type));

  const uint32_t tilesX = (m_width + kTileSize - 1) / kTileSize;
  const uint32_t tilesY = (m_height + kTileSize - 1) / kTileSize;
  m_tileSamplesTotal = uint64_t(tilesX) * tilesY * m_samplesThisRender;
  const std::unique_ptr<RayTransport> transport =
      device().transportFor(*m_world);
  RenderContext context{m_camera,
      m_world,
      transport.get(),
      m_width,
      m_height,
      m_sampleIndex,
      m_sharing.omitBackground};
  context.seed = m_renderer->seed();
  context.centresFirstSample = m_renderer->centresFirstSample();
  m_renderer->beginFrame(context);
  if (m_sharing.lockstep)
    renderInLockstep(context, tilesX, tilesY);
  else
    renderTileSamples(context, tilesX, tilesY);
  // Every tile's pixels happen before this (the increments form one
  // release sequence), in the C++ memory model itself rather than through
  // TBB's join, which ThreadSanitizer cannot see.
  (void)m_tileSamplesDone.load(std::memory_order_acquire);
  if (m_cancel) {
    m_samplesDone = 0; // a partial sample must not enter the average
    m_accumulatedVersion = ~0ull;
  } else if (m_averaging) {
    m_samplesDone += m_samplesThisRender;
  }
}

Tile Frame::tileAt(uint32_t tx, uint32_t ty) const
{
  return Tile{tx * kTileSize,
      ty * kTileSize,
      std::min((tx + 1) * kTileSize, m_width),
      std::min((ty + 1) * kTileSize, m_height)};
}

void Frame::renderTileSamples(
    const RenderContext &context, uint32_t tilesX, uint32_t tilesY)
{
  const uint32_t tiles = tilesX * tilesY;
  // Sample k of tile t is rendered, folded into the average and, at the
  // last sample, converted to the channels' types while still in cache.
  auto renderSample = [&](uint32_t index, uint32_t k) {
    const uint32_t tx = index % tilesX, ty = index / tilesX;
    if (!m_cancel && ty % m_sharing.tileRowParts == m_sharing.tileRowPart) {
      const Tile tile = tileAt(tx, ty);
      m_convergence.forEachActiveSpan(tile, [&](const Tile &span) {
        RenderContext sample = context;
        sample.sampleIndex = m_sampleIndex + k;
        m_renderer->renderTile(sample, span, m_buffers, m_cancel);
        if (m_averaging) {
          // An active block has taken every sample so far.
          accumulate(span, m_samplesDone + k);
          m_convergence.update(
              span, m_samplesDone + k, m_buffers.color, m_accumulated.color);
        }
      });
      if (k + 1 == m_samplesThisRender)
        resolve(tile);
    } // else another process renders this row of tiles
    m_tileSamplesDone.fetch_add(1, std::memory_order_release);
  };
  std::unique_ptr<TileSamples[]> queues(new TileSamples[tiles]);
  auto claim = [&](uint64_t pair) {
    TileSamples &queue = queues[pair % tiles];
    if (queue.pending.fetch_add(1, std::memory_order_acq_rel) != 0)
      return; // the owner renders it after the tile's earlier samples
    do {
      renderSample(uint32_t(pair % tiles), queue.next++);
    } while (queue.pending.fetch_sub(1, std::memory_order_acq_rel) != 1);
  };
  // Pairs are claimed sample after sample, so the threads stay busy
  // across sample boundaries: no barrier until the render's last tile.
  const uint64_t pairs = uint64_t(tiles) * m_samplesThisRender;
  std::atomic<uint64_t> cursor{0};
  const int workers = std::max(tbb::this_task_arena::max_concurrency(), 1);
  tbb::parallel_for(
      tbb::blocked_range<int>(0, workers, 1),
      [&](const tbb::blocked_range<int> &) {
        for (uint64_t pair; !m_cancel && (pair = cursor++) < pairs;)
          claim(pair);
      },
      tbb::simple_partitioner());
}

void Frame::renderInLockstep(
    const RenderContext &context, uint32_t tilesX, uint32_t tilesY)
{
  // A row of tiles at a time, in order: one wavefront large enough to be
  // traced and shaded on all the process's threads between two of the
  // transport's collectives (and fewer, larger messages). A process
  // stopping on its own would leave the others waiting in a collective:
  // in lockstep every row of every sample is rendered.
  const std::atomic<bool> never{false};
  for (uint32_t k = 0; k < m_samplesThisRender; k++) {
    RenderContext sample = context;
    sample.sampleIndex = m_sampleIndex + k;
    const bool last = k + 1 == m_samplesThisRender;
    for (uint32_t ty = 0; ty < tilesY; ty++) {
      const Tile row{
          0, ty * kTileSize, m_width, std::min((ty + 1) * kTileSize, m_height)};
      m_renderer->renderTile(sample, row, m_buffers, never);
      tbb::parallel_for(uint32_t(0), tilesX, [&](uint32_t tx) {
        const Tile tile = tileAt(tx, ty);
        if (m_averaging)
          accumulate(tile, m_samplesDone + k);
        if (last)
          resolve(tile);
      });
      m_tileSamplesDone.fetch_add(tilesX, std::memory_order_release);
    }
  }
}

uint64_t Frame::sceneVersion() const
{
  // Epochs only grow, so their sum changes whenever any of them does.
  return epoch() + m_world->epoch() + m_camera->epoch() + m_renderer->epoch()
         + (uint64_t(m_width) << 40) + (uint64_t(m_height) << 20);
}

void Frame::accumulate(const Tile &tile, uint32_t samplesBefore)
{
  FrameBuffers &sum = m_accumulated;
  const FrameBuffers &sample = m_buffers;
  const bool first = samplesBefore == 0;
  const float weight = 1.f / float(samplesBefore + 1);
  for (uint32_t y = tile.y0; y < tile.y1; y++) {
    const size_t begin = size_t(y) * m_width + tile.x0;
    const size_t end = size_t(y) * m_width + tile.x1;
    if (first) {
      // The first sample is the average; ids always stay the first's.
      auto copy = [&](auto &to, const auto &from) {
        if (!from.empty())
          std::copy(
              from.begin() + begin, from.begin() + end, to.begin() + begin);
      };
      copy(sum.color, sample.color);
      copy(sum.depth, sample.depth);
      copy(sum.normal, sample.normal);
      copy(sum.albedo, sample.albedo);
      copy(sum.primitiveId, sample.primitiveId);
      copy(sum.objectId, sample.objectId);
      copy(sum.instanceId, sample.instanceId);
      continue;
    }
    for (size_t i = begin; i < end; i++) {
      sum.color[i] = sum.color[i] + (sample.color[i] - sum.color[i]) * weight;
      if (sample.needs.depth)
        sum.depth[i] = std::min(sum.depth[i], sample.depth[i]);
      if (sample.needs.normal)
        sum.normal[i] =
            sum.normal[i] + (sample.normal[i] - sum.normal[i]) * weight;
      if (sample.needs.albedo)
        sum.albedo[i] =
            sum.albedo[i] + (sample.albedo[i] - sum.albedo[i]) * weight;
    }
  }
}

void Frame::resolve(const Tile &tile)
{
  // With accumulation the channels show the average so far.
  const FrameBuffers &source = m_averaging ? m_accumulated : m_buffers;
  const size_t count = tile.x1 - tile.x0;
  for (uint32_t y = tile.y0; y < tile.y1; y++) {
    const size_t begin = size_t(y) * m_width + tile.x0;
    for (auto &[name, channel] : m_channels) {
      unsigned char *out =
          channel.pixels.data() + begin * anari::sizeOf(channel.type);
      if (name == "channel.color") {
        writeColorPixels(channel.type, source.color.data() + begin, count, out);
      } else if (name == "channel.depth") {
        std::memcpy(out, source.depth.data() + begin, count * sizeof(float));
      } else if (name == "channel.normal") {
        writeVec3Pixels(channel.type, source.normal.data() + begin, count, out);
      } else if (name == "channel.albedo") {
        writeVec3Pixels(channel.type, source.albedo.data() + begin, count, out);
      } else {
        const auto &ids = name == "channel.primitiveId" ? source.primitiveId
                          : name == "channel.objectId"  ? source.objectId
                                                        : source.instanceId;
        std::memcpy(out, ids.data() + begin, count * sizeof(uint32_t));
      }
    }
  }
}

void Frame::denoiseColor()
{
  auto it = m_channels.find("channel.color");
  if (!m_denoise || it == m_channels.end() || m_denoisedRender == m_renders)
    return;
  m_denoisedRender = m_renders;
  const FrameBuffers &source = m_averaging ? m_accumulated : m_buffers;
  if (source.color.empty())
    return;
  auto guide = [](const auto &v) {
    return v.empty() ? nullptr : v.data();
  };
  std::vector<float4> filtered(source.color.size());
  m_denoiser.denoise({m_width,
                         m_height,
                         source.color.data(),
                         guide(source.albedo),
                         guide(source.normal),
                         guide(source.depth),
                         m_averaging ? std::max(m_samplesDone, 1u) : 1u},
      filtered.data());
  writeColorPixels(it->second.type,
      filtered.data(),
      filtered.size(),
      it->second.pixels.data());
}

void Frame::finish(const Completion &completion)
{
  m_renders++;
  m_duration =
      std::chrono::duration<float>(std::chrono::steady_clock::now() - m_start)
          .count();
  // NOTE: the device stops counting this frame before the continuation runs,
  // so API calls made from the callback never wait on this frame.
  device().frameFinished();
  if (completion.callback)
    completion.callback(
        completion.userPtr, device().apiHandle(), (ANARIFrame)handle());
  // Notified under the lock: a waiter can only return (and release the
  // frame) once this unlocks, the task's very last use of the frame.
  std::lock_guard lock(m_stateMutex);
  m_rendering = false;
  m_doneCondition.notify_all();
}

void Frame::waitUntilDone()
{
  std::unique_lock lock(m_stateMutex);
  m_doneCondition.wait(lock, [&] { return !m_rendering; });
}

bool Frame::ready(ANARIWaitMask mask)
{
  if (mask & ANARI_WAIT) {
    waitUntilDone();
    return true;
  }
  std::lock_guard lock(m_stateMutex);
  return !m_rendering;
}

void Frame::discard()
{
  m_cancel = true;
}

void Frame::abandon()
{
  discard();
  waitUntilDone();
}

const void *Frame::map(const char *channel,
    uint32_t &width,
    uint32_t &height,
    ANARIDataType &pixelType)
{
  waitUntilDone();
  auto it = m_channels.find(channel);
  if (it == m_channels.end() || it->second.pixels.empty()) {
    report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_ARGUMENT,
        "anariMapFrame: channel '%s' is %s",
        channel,
        it == m_channels.end() ? "not enabled on this frame"
                               : "empty (the frame was never rendered)");
    return nullptr;
  }
  if (it->first == "channel.color")
    denoiseColor();
  width = m_width;
  height = m_height;
  pixelType = it->second.type;
  return it->second.pixels.data();
}

void Frame::unmap(const char *) {}

void Frame::share(const Sharing &sharing)
{
  waitUntilDone();
  m_sharing = sharing;
  m_sharing.tileRowParts = std::max(sharing.tileRowParts, 1u);
  if (m_sharing.tileRowPart >= m_sharing.tileRowParts)
    m_sharing.tileRowPart = 0;
}

ANARIDataType Frame::channelType(const std::string &channel) const
{
  auto it = m_channels.find(channel);
  return it == m_channels.end() ? ANARI_UNKNOWN : it->second.type;
}

bool Frame::samplesProperty(
    ANARIDataType type, void *mem, uint64_t size, ANARIWaitMask mask)
{
  if ((type != ANARI_INT32 && type != ANARI_UINT32) || !mem
      || size < sizeof(uint32_t))
    return false;
  if (mask & ANARI_WAIT)
    waitUntilDone();
  else if (!ready(ANARI_NO_WAIT))
    return false; // the count changes under a render in flight
  // Without accumulation the channels hold one render's samples.
  const uint32_t samples =
      m_averaging ? m_samplesDone : (m_renders > 0 ? 1u : 0u);
  if (type == ANARI_INT32) {
    const int32_t value = int32_t(std::min<uint32_t>(samples, INT32_MAX));
    std::memcpy(mem, &value, sizeof(value));
  } else {
    std::memcpy(mem, &samples, sizeof(samples));
  }
  return true;
}

uint32_t Frame::nextSampleIndex() const
{
  return m_accumulation && sceneVersion() == m_accumulatedVersion
             ? m_samplesDone
             : 0;
}

void Frame::restartAccumulation()
{
  waitUntilDone();
  m_samplesDone = 0;
  m_accumulatedVersion = ~0ull;
}

const FrameBuffers &Frame::linearPixels()
{
  waitUntilDone();
  return m_averaging ? m_accumulated : m_buffers;
}

bool Frame::activePixelsProperty(
    ANARIDataType type, void *mem, uint64_t size, ANARIWaitMask mask)
{
  if (type != ANARI_UINT64 || !mem || size < sizeof(uint64_t))
    return false;
  if (mask & ANARI_WAIT)
    waitUntilDone();
  else if (!ready(ANARI_NO_WAIT))
    return false; // tiles stop under a render in flight
  // A process sharing the frame counts the rows it renders.
  const uint64_t pixels =
      m_renders > 0 ? m_convergence.activePixels(
          kTileSize, m_sharing.tileRowPart, m_sharing.tileRowParts)
                    : 0;
  std::memcpy(mem, &pixels, sizeof(pixels));
  return true;
}

bool Frame::getProperty(const std::string &name,
    ANARIDataType type,
    void *mem,
    uint64_t size,
    ANARIWaitMask mask)
{
  if (name == "numSamples")
    return samplesProperty(type, mem, size, mask);
  if (name == "activePixels")
    return activePixelsProperty(type, mem, size, mask);
  if (type != ANARI_FLOAT32 || !mem || size < sizeof(float))
    return false;
  float value;
  if (name == "duration") {
    if (mask & ANARI_WAIT)
      waitUntilDone();
    value = m_duration;
  } else if (name == "refinementProgress") {
    if (mask & ANARI_WAIT)
      waitUntilDone();
    // A sampleLimit is where the frame stops: progress is complete there.
    const uint32_t limit = m_renderer ? m_renderer->sampleLimit() : 0;
    const uint32_t target = limit > 0    ? limit
                            : m_renderer ? m_renderer->convergedSampleCount()
                                         : 1;
    value = m_accumulation ? std::min(
                1.f, float(m_samplesDone) / float(std::max(target, 1u)))
                           : 1.f;
  } else if (name == "renderProgress") {
    value = m_tileSamplesTotal
                ? float(m_tileSamplesDone) / float(m_tileSamplesTotal)
                : 0.f;
    if (ready(ANARI_NO_WAIT) && m_tileSamplesTotal)
      value = 1.f;
  } else {
    return false;
  }
  std::memcpy(mem, &value, sizeof(value));
  return true;
}

} // namespace prism
