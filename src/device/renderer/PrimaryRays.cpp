#include "PrimaryRays.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace prism {

PrimaryRays::PrimaryRays(const RenderContext &context)
    : m_context(context), m_invWidth(1.f / float(context.width))
{
  m_isPinhole = context.camera->pinhole(
      m_pinhole, float(context.width) / float(context.height));
}

void PrimaryRays::generate(uint32_t x0,
    uint32_t y,
    int count,
    rt::RayHitPacket &packet,
    int active[rt::kPacketSize]) const
{
  if (m_isPinhole) {
    // The common camera: screen positions first, then the directions in
    // one straight loop the compiler vectorises.
    alignas(32) float sx[rt::kPacketSize], sy[rt::kPacketSize],
        time[rt::kPacketSize];
    const float invWidth = m_invWidth;
    const float height = float(m_context.height);
    for (int i = 0; i < rt::kPacketSize; i++) {
      const uint32_t x = x0 + uint32_t(std::min(i, count - 1));
      const float2 offset = m_context.offsetInPixel(x, y);
      sx[i] = (float(x) + offset.x) * invWidth;
      sy[i] = (float(y) + offset.y) / height;
      time[i] = m_context.camera->rayTime(
          {sx[i], sy[i]}, m_context.exposureTime(x, y));
    }
    const Camera::Pinhole p = m_pinhole; // a copy the stores cannot alias
    for (int i = 0; i < rt::kPacketSize; i++) {
      const float3 d = p.corner + p.dx * sx[i] + p.dy * sy[i];
      const float inv = 1.f / std::sqrt(dot(d, d));
      packet.originX[i] = p.origin.x;
      packet.originY[i] = p.origin.y;
      packet.originZ[i] = p.origin.z;
      packet.directionX[i] = d.x * inv;
      packet.directionY[i] = d.y * inv;
      packet.directionZ[i] = d.z * inv;
      packet.tMin[i] = 0.f;
      packet.tMax[i] = std::numeric_limits<float>::infinity();
      packet.time[i] = time[i];
      active[i] = i < count ? -1 : 0;
    }
    return;
  }
  for (int i = 0; i < rt::kPacketSize; i++) {
    const uint32_t x = x0 + uint32_t(std::min(i, count - 1));
    const Ray ray = m_context.cameraRay(x, y);
    packet.originX[i] = ray.origin.x;
    packet.originY[i] = ray.origin.y;
    packet.originZ[i] = ray.origin.z;
    packet.directionX[i] = ray.direction.x;
    packet.directionY[i] = ray.direction.y;
    packet.directionZ[i] = ray.direction.z;
    packet.tMin[i] = ray.tMin;
    packet.tMax[i] = ray.tMax;
    packet.time[i] = ray.time;
    active[i] = i < count ? -1 : 0;
  }
}

} // namespace prism
