// ANARIRenderer: how a frame turns the world into pixels. The base owns the
// background (color or image, KHR_RENDERER_BACKGROUND_*) and the per-tile
// entry point every renderer subtype implements.
#pragma once

#include "../camera/Camera.h"
#include "../object/Object.h"
#include "../rt/Scene.h"
#include "FrameBuffers.h"
#include "SampleSequence.h"
#include "SurfaceHit.h"

#include <atomic>

namespace prism {

class RayTransport;

class Camera;
class PrimaryRays;
class World;

// What one frame renders, fixed for the duration of the render.
struct RenderContext
{
  const Camera *camera;
  const World *world;
  // Where wavefront renderers trace their queues: the device decides
  // (locally the world's BVH; across ranks for the data-parallel device).
  const RayTransport *transport;
  uint32_t width;
  uint32_t height;
  // Which accumulated sample this frame renders (0: the first); seeds every
  // random choice with the pixel.
  uint32_t sampleIndex;
  // Render as if the background were transparent black: a compositing
  // device blends the processes' pixels first and the background under
  // the result (a background under each process's pixels would hide
  // everything behind its volumes and see-through surfaces).
  bool transparentBackground{false};
  // The renderer's `seed`: which scrambling of the sample sequences.
  uint32_t seed{0};
  // Whether the first sample is centred (Renderer::centresFirstSample()).
  bool centresFirstSample{true};

  // Whether this sample looks through pixel centres, the lens's centre and
  // the middle of the exposure rather than its sequences' points.
  bool centredSample() const
  {
    return sampleIndex == 0 && centresFirstSample;
  }
  // Where this sample of pixel (x, y) looks within the pixel, in [0,1)^2.
  float2 offsetInPixel(uint32_t x, uint32_t y) const
  {
    return centredSample() ? float2{0.5f, 0.5f}
                           : pixelOffset(x, y, sampleIndex, seed);
  }
  // The point on the lens it passes through, in [0,1)^2 (the centre for a
  // camera without depth of field).
  float2 lensPoint(uint32_t x, uint32_t y, bool depthOfField) const
  {
    return centredSample() || !depthOfField
               ? float2{0.5f, 0.5f}
               : lensSample(x, y, sampleIndex, seed);
  }
  // When in the exposure it looks, in [0, 1).
  float exposureTime(uint32_t x, uint32_t y) const
  {
    return centredSample() ? 0.5f : exposureSample(x, y, sampleIndex, seed);
  }
  // The camera ray of pixel (x, y) for this sample.
  Ray cameraRay(uint32_t x, uint32_t y) const;
};

// One tile's work as the tile loop, runTile(), drives it:
// packet() for the tile's pixels row by row, in packets of up to
// rt::kPacketSize, then bounce() until nothing is left to trace, then
// finish(). Each renderer's renderTile() makes its own (a final class), on
// the stack, and runs it through runTile() (TileLoop.h); the loop stops,
// storing nothing more, once the frame is cancelled.
class TileWork
{
 public:
  virtual ~TileWork() = default;
  // The camera rays of `count` pixels of row y from x0: traced, shaded and
  // stored as one coherent packet, or made and kept for the first bounce
  // of a wavefront.
  virtual void packet(uint32_t x0, uint32_t y, int count) = 0;
  // Whether packet() may run for different rows at once: rows then go to
  // the process's threads in blocks (a lockstep render's row of tiles).
  virtual bool packetsInParallel() const
  {
    return false;
  }
  // Traces the queued rays together and shades their hits, queueing the
  // rays that follow; false when there was nothing to trace.
  virtual bool bounce()
  {
    return false;
  }
  // Stores what the bounces gathered.
  virtual void finish() {}
};

class Renderer : public Object
{
 public:
  Renderer(DeviceState &device, const std::string &subtype);

  // Called once per frame before any tile.
  virtual void beginFrame(const RenderContext &context) {}
  // Renders the pixels of `tile` through runTile() with the renderer's
  // TileWork (by default packets of primary rays, each pixel shaded by
  // shadeSample()); returns early once `cancel` is set.
  virtual void renderTile(const RenderContext &context,
      const Tile &tile,
      FrameBuffers &buffers,
      const std::atomic<bool> &cancel) const;

  // KHR_RENDERER_DENOISE: whether frames filter the color they show.
  bool denoise() const
  {
    return m_denoise;
  }
  // Chooses independent sample sequences (RenderContext::seed).
  uint32_t seed() const
  {
    return m_seed;
  }

  // The background seen at pixel (x, y) of a width x height frame.
  float4 background(
      uint32_t x, uint32_t y, uint32_t width, uint32_t height) const;
  // What a render shows behind pixel (x, y): background(), or nothing
  // when the context asks for a transparent background.
  float4 background(const RenderContext &context, uint32_t x, uint32_t y) const
  {
    return context.transparentBackground
               ? float4{0.f, 0.f, 0.f, 0.f}
               : background(x, y, context.width, context.height);
  }
  // Whether background() is the same everywhere (no background image).
  bool uniformBackground() const
  {
    return m_backgroundImage.empty();
  }

  // The 'sampleLimit' (hdAnari's convergence control): how many samples
  // per pixel an accumulating frame gathers at most; 0: no limit.
  uint32_t sampleLimit() const
  {
    return m_sampleLimit;
  }
  // The 'pixelSamples': how many samples per pixel one render takes.
  uint32_t pixelSamples() const
  {
    return m_pixelSamples;
  }
  // The 'errorThreshold' (adaptive sampling, frame/TileConvergence.h): a
  // block of pixels whose average's estimated RMS error is below it takes
  // no more samples until the accumulation restarts; 0 samples every
  // pixel.
  float errorThreshold() const
  {
    return m_errorThreshold;
  }
  // Whether the first sample looks through pixel centres (the lens's
  // centre, the middle of the exposure), so single-sample images are exact
  // (no sample jitter): true but for renderers that accumulate many
  // samples, whose sequences stay stratified only with their own first
  // points (RenderContext::centredSample()).
  virtual bool centresFirstSample() const
  {
    return true;
  }
  // Samples per pixel after which accumulating more changes little
  // (refinementProgress reaches 1 there).
  virtual uint32_t convergedSampleCount() const
  {
    return 16;
  }
  // Whether it traces paths in wavefronts through the frame's RayTransport
  // (shades, shareBounce), lit by the world's lights: a data-parallel
  // device can then trace its paths across processes.
  virtual bool tracesWavefronts() const
  {
    return false;
  }

  // Whether the renderer shades without the world's lights (and ambient
  // light), by an eye light, occlusion or false colors; answered to
  // applications as the "ignoresLights" property (BOOL).
  virtual bool ignoresLights() const
  {
    return false;
  }

  bool getProperty(const std::string &name,
      ANARIDataType type,
      void *mem,
      uint64_t size,
      ANARIWaitMask mask) override;

 protected:
  void commitParameters() override;
  // One pixel's sample from its primary ray and what that ray hit; by
  // default the background.
  virtual PixelSample shadeSample(const RenderContext &context,
      const Ray &ray,
      const rt::Hit &hit,
      uint32_t x,
      uint32_t y) const;
  // Traces the camera rays through `count` (<= rt::kPacketSize) pixels of
  // row y starting at x0 together, as one coherent packet.
  void tracePrimary(const RenderContext &context,
      const PrimaryRays &primaryRays,
      uint32_t x0,
      uint32_t y,
      int count,
      Ray rays[rt::kPacketSize],
      rt::Hit hits[rt::kPacketSize]) const;
  // The next hit along `ray` beyond `previous` (for see-through surfaces).
  static rt::Hit traceBeyond(
      const World &world, const Ray &ray, const rt::Hit &previous);
  // Writes one pixel's results into the frame's buffers.
  static void store(const RenderContext &context,
      FrameBuffers &buffers,
      uint32_t x,
      uint32_t y,
      const PixelSample &sample);

  bool m_denoise{false};
  uint32_t m_sampleLimit{0};
  uint32_t m_pixelSamples{1};
  float m_errorThreshold{0.f};
  uint32_t m_seed{0}; // read by the renderers that declare `seed`
  float3 m_ambientColor{1, 1, 1};
  float m_ambientRadiance{0.f};

 private:
  class PrimaryPackets;

  float4 m_backgroundColor{0, 0, 0, 1};
  std::vector<float4> m_backgroundImage; // linear RGBA, row 0 at the bottom
  uint32_t m_backgroundWidth{0};
  uint32_t m_backgroundHeight{0};
};

} // namespace prism
