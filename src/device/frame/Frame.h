// ANARIFrame: size, channels, the world/camera/renderer to draw, and the
// asynchronous render of them on the device's task pool (spec 5.1).
#pragma once

#include "../denoise/Denoiser.h"
#include "../object/Object.h"
#include "../renderer/FrameBuffers.h"
#include "TileConvergence.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <map>
#include <mutex>

namespace prism {

class Camera;
class Renderer;
struct RenderContext;
class World;

class Frame : public Object
{
 public:
  explicit Frame(DeviceState &device);
  ~Frame() override;

  bool isValid() const override;
  // Starts rendering the committed scene; returns immediately.
  void renderAsync();
  // NO_WAIT: whether the last render finished; WAIT: blocks until it has.
  bool ready(ANARIWaitMask mask);
  // Asks the render in flight to stop as soon as possible.
  void discard();
  // Stops and waits for the render in flight; called before the frame's
  // last public reference goes, since nothing else keeps a frame alive.
  void abandon();
  // The channel's pixels (waits for the render); NULL if not enabled.
  const void *map(const char *channel,
      uint32_t &width,
      uint32_t &height,
      ANARIDataType &pixelType);
  void unmap(const char *channel);

  // Square tiles a render is split into, in pixels.
  static constexpr uint32_t kTileSize = 32;
  static_assert(kTileSize % TileConvergence::kBlockSize == 0);
  // The committed size, renderer and camera (the data-parallel device
  // compares them across processes before a collective render).
  uint32_t width() const
  {
    return m_width;
  }
  uint32_t height() const
  {
    return m_height;
  }
  const Renderer *renderer() const
  {
    return m_renderer;
  }
  const Camera *camera() const
  {
    return m_camera;
  }
  const World *world() const
  {
    return m_world;
  }
  World *world()
  {
    return m_world;
  }
  // How a data-parallel device shares the next renders among processes
  // (the default: one process renders the whole frame alone).
  struct Sharing
  {
    // Only the tile rows whose index modulo `tileRowParts` is
    // `tileRowPart`.
    uint32_t tileRowPart{0};
    uint32_t tileRowParts{1};
    // The depth buffer even when channel.depth is not enabled (compositing
    // sorts by it).
    bool keepDepth{false};
    // A transparent background, for a device that composites the
    // processes' pixels and adds the background itself.
    bool omitBackground{false};
    // Rows of tiles rendered one after another, in the same order on
    // every process, so the collectives of a transport line up.
    bool lockstep{false};
  };
  void share(const Sharing &sharing);
  // The sample the next render draws (0 when accumulation restarts: off,
  // or something the frame shows changed), and a restart forced, so
  // processes rendering in lockstep start their paths from the same one
  // (asked between renders).
  uint32_t nextSampleIndex() const;
  void restartAccumulation();
  // The committed pixel type of `channel`; ANARI_UNKNOWN when not enabled.
  ANARIDataType channelType(const std::string &channel) const;
  // The linear color and depth the channels were converted from (the
  // average so far with accumulation); waits for the render in flight.
  const FrameBuffers &linearPixels();

  // Besides the spec's duration and progress: "numSamples" (INT32 or
  // UINT32), the samples per pixel the channels hold (accumulated so far;
  // 1 after a render without accumulation), as hdAnari asks; with
  // adaptive sampling, those of the tiles sampled longest.
  // "activePixels" (UINT64): the pixels the next render would sample (all
  // of them but with the renderer's errorThreshold; 0 before a render).
  bool getProperty(const std::string &name,
      ANARIDataType type,
      void *mem,
      uint64_t size,
      ANARIWaitMask mask) override;

 protected:
  void commitParameters() override;

 private:
  struct Channel
  {
    ANARIDataType type{ANARI_UNKNOWN};
    std::vector<unsigned char> pixels;
  };
  void render();
  // The render's (tile, sample) pairs on all threads, each tile's samples
  // in order; or, in lockstep, sample after sample, a row of tiles at a
  // time.
  void renderTileSamples(
      const RenderContext &context, uint32_t tilesX, uint32_t tilesY);
  void renderInLockstep(
      const RenderContext &context, uint32_t tilesX, uint32_t tilesY);
  Tile tileAt(uint32_t tx, uint32_t ty) const;
  bool samplesProperty(
      ANARIDataType type, void *mem, uint64_t size, ANARIWaitMask mask);
  bool activePixelsProperty(
      ANARIDataType type, void *mem, uint64_t size, ANARIWaitMask mask);
  // Folds one tile of a sample into the average of the `samplesBefore`
  // samples before it (KHR_FRAME_ACCUMULATION, or pixelSamples > 1).
  void accumulate(const Tile &tile, uint32_t samplesBefore);
  // Converts one tile to the channels' types.
  void resolve(const Tile &tile);
  // Filters the color shown by channel.color (once per render).
  void denoiseColor();
  // Epochs of everything a frame shows: a change restarts accumulation.
  uint64_t sceneVersion() const;
  // The memory a render of the committed size and channels takes, and
  // whether the machine has it (reported when not).
  size_t bytesNeeded() const;
  bool fitsInMemory();
  // Forgets every pixel, so nothing of another size is ever mapped.
  void dropRenderedPixels();
  struct Completion
  {
    ANARIFrameCompletionCallback callback;
    const void *userPtr;
  };
  void finish(const Completion &completion);
  void waitUntilDone();

  // Committed state.
  World *m_world{nullptr};
  Camera *m_camera{nullptr};
  Renderer *m_renderer{nullptr};
  uint32_t m_width{0};
  uint32_t m_height{0};
  std::map<std::string, Channel> m_channels;
  ANARIFrameCompletionCallback m_completionCallback{nullptr};
  const void *m_completionUserPtr{nullptr};

  FrameBuffers m_buffers;
  Sharing m_sharing;
  bool m_accumulation{false};
  uint32_t m_sampleIndex{0};       // the first of the render in flight
  uint32_t m_samplesThisRender{1}; // the renderer's pixelSamples, limited
  // Whether the channels show m_accumulated: with accumulation, or when
  // one render takes several samples.
  bool m_averaging{false};
  uint32_t m_samplesDone{0}; // accumulated into m_accumulated
  uint64_t m_accumulatedVersion{~0ull};
  FrameBuffers m_accumulated;    // averages (depth: minimum) over samples
  TileConvergence m_convergence; // which blocks still take samples
  // KHR_RENDERER_DENOISE: filtered when color is mapped, not every frame
  // (the filter costs far more than a sample).
  Denoiser m_denoiser;
  bool m_denoise{false};
  uint64_t m_renders{0};
  uint64_t m_denoisedRender{~0ull};

  std::mutex m_stateMutex;
  std::condition_variable m_doneCondition;
  bool m_rendering{false};
  std::atomic<bool> m_cancel{false};
  // (tile, sample) pairs of the render in flight, for renderProgress.
  std::atomic<uint64_t> m_tileSamplesDone{0};
  uint64_t m_tileSamplesTotal{0};
  float m_duration{0.f};
  std::chrono::steady_clock::time_point m_start;
};

} // namespace prism
