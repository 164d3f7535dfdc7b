// The `ao` renderer: the base color at the first hit, darkened by how much
// of the hemisphere above it is blocked within `aoDistance`, estimated with
// `aoSamples` cosine-distributed rays per pixel and sample. Like the path
// tracer it runs as a wavefront: a tile's camera rays (and continuations
// through see-through surfaces) as one queue, all occlusion rays as another.
#pragma once

#include "Renderer.h"
#include "wavefront/WorkspacePool.h"

namespace prism {

class AmbientOcclusion : public Renderer
{
 public:
  explicit AmbientOcclusion(DeviceState &device) : Renderer(device, "ao") {}

  bool ignoresLights() const override
  {
    return true; // occlusion alone
  }
  uint32_t convergedSampleCount() const override
  {
    return std::max(1u, 256u / m_samples); // ~256 rays per pixel
  }

 protected:
  void commitParameters() override;
  void renderTile(const RenderContext &context,
      const Tile &tile,
      FrameBuffers &buffers,
      const std::atomic<bool> &cancel) const override;

 private:
  class Wavefront;

  // What a tile works in, reused tile after tile.
  struct TileWorkspace
  {
    std::vector<PixelSample> samples;
    std::vector<float> times;
    std::vector<float> open; // per pixel: the occlusion rays' transmittance
    std::vector<uint16_t> layers;
    rt::RayQueue rays, next, occlusion;
  };
  mutable WorkspacePool<TileWorkspace> m_workspaces;
  uint32_t m_samples{1};
  float m_distance{1e20f};
};

} // namespace prism
