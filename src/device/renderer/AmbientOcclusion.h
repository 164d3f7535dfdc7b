// The `ao` renderer: the base color at the first hit, darkened by how much
// of the hemisphere above it is blocked within `aoDistance`, estimated with
// `aoSamples` cosine-distributed rays per pixel and sample.
#pragma once

#include "Renderer.h"

namespace prism {

class AmbientOcclusion : public Renderer
{
 public:
  explicit AmbientOcclusion(Device &device) : Renderer(device, "ao") {}

  uint32_t convergedSampleCount() const override
  {
    return std::max(1u, 256u / m_samples); // ~256 rays per pixel
  }

 protected:
  void commitParameters() override;
  PixelSample shadeSample(const RenderContext &context,
      const Ray &ray,
      const rt::Hit &hit,
      uint32_t x,
      uint32_t y) const override;

 private:
  uint32_t m_samples{1};
  float m_distance{1e20f};
};

} // namespace prism
