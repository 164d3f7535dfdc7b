// Camera rays for packets of pixels, written straight into the packet
// Embree traces: every renderer's primary rays (the path tracer's too, one
// at a time, through Renderer::cameraRay: the same pixel, lens and time
// samples).
#pragma once

#include "Renderer.h"

namespace prism {

class PrimaryRays
{
 public:
  // Asks the camera once whether it is a pinhole, for every packet after.
  explicit PrimaryRays(const RenderContext &context);

  // Fills the rays of `packet` through `count` (1..8) pixels of row y from
  // x0; active[i] is -1 for those lanes, 0 for the idle ones, which repeat
  // the last pixel's ray so the packet stays coherent.
  void generate(uint32_t x0,
      uint32_t y,
      int count,
      rt::RayHitPacket &packet,
      int active[rt::kPacketSize]) const;

 private:
  const RenderContext &m_context;
  bool m_isPinhole{false};
  Camera::Pinhole m_pinhole{};
  float m_invWidth{0.f};
};

} // namespace prism
