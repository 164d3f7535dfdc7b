// The fast preview and conformance renderer: one primary ray per pixel,
// surface color shaded with an eye light, see-through surfaces and the
// volumes between them blended front to back (volumes by the spec's
// reference ray marcher, skipping empty space). Lights and ambient light
// are ignored by design.
#pragma once

#include "Renderer.h"

namespace prism {

class Raycast : public Renderer
{
 public:
  Raycast(DeviceState &device, const std::string &subtype)
      : Renderer(device, subtype)
  {}

  bool ignoresLights() const override
  {
    return true; // eye-light shading
  }

 protected:
  void commitParameters() override;
  // Traces whole packets and shades, in line, hits on surfaces whose color
  // is constant and whose first layer hides everything behind; every other
  // pixel goes through shadeSample(). Both give the same image.
  void renderTile(const RenderContext &context,
      const Tile &tile,
      FrameBuffers &buffers,
      const std::atomic<bool> &cancel) const override;
  PixelSample shadeSample(const RenderContext &context,
      const Ray &ray,
      const rt::Hit &hit,
      uint32_t x,
      uint32_t y) const override;

 private:
  class Packets;

  float m_eyeLightBlendRatio{0.5f};
  float m_volumeSamplingRate{1.f};
  bool m_volumeMajorantGrid{true};
};

} // namespace prism
