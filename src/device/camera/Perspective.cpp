#include "Perspective.h"

#include <cmath>

namespace prism {

Perspective::Perspective(DeviceState &device) : Camera(device, "perspective") {}

void Perspective::commitParameters()
{
  Camera::commitParameters();
  constexpr float kDefaultFovy = float(M_PI / 3.0);
  float fovy = param<float>("fovy");
  if (!(fovy > 0.f && fovy < float(M_PI))) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'fovy' (%g) must be in (0, pi); using pi/3",
        fovy);
    fovy = kDefaultFovy;
  }
  m_halfHeight = std::tan(0.5f * fovy);
  readAspect();
  readNearFar(m_near, m_far);
}

Ray Perspective::rayThroughSensor(
    float2 sensor, float eyeShift, float2 lensSample, float frameAspect) const
{
  const float aspect = eyeAspect(frameAspect);
  const float3 onPlane =
      m_direction + m_right * ((2.f * sensor.x - 1.f) * m_halfHeight * aspect)
      + m_up * ((2.f * sensor.y - 1.f) * m_halfHeight);
  const float3 direction = normalize(onPlane);
  // Parallel eyes: the same view frustum, shifted along the baseline.
  const float3 eye = m_position + m_right * eyeShift;
  Ray ray{eye, direction};
  if (hasDepthOfField()) {
    // The focal plane lies focusDistance along the view direction.
    const float focusT = m_focusDistance / dot(direction, m_direction);
    ray = throughLens(eye, direction, focusT, m_right, m_up, lensSample);
  }
  clipAlongView(ray, m_near, m_far);
  return ray;
}

bool Perspective::pinhole(Pinhole &out, float frameAspect) const
{
  if (hasDepthOfField() || m_stereoMode != StereoMode::kNone || m_near != 0.f
      || !std::isinf(m_far) || hasMotion())
    return false;
  const float aspect = eyeAspect(frameAspect);
  // The sensor point of screen (x, y) is regionLower + (x, y) * regionSize;
  // rayThroughSensor maps sensor s to direction + right*(2s.x-1)*h*a + ...
  const float w = 2.f * m_halfHeight * aspect, h = 2.f * m_halfHeight;
  const float2 size = m_regionUpper - m_regionLower;
  out.origin = m_position;
  out.corner =
      m_direction
      + m_right * ((2.f * m_regionLower.x - 1.f) * m_halfHeight * aspect)
      + m_up * ((2.f * m_regionLower.y - 1.f) * m_halfHeight);
  out.dx = m_right * (w * size.x);
  out.dy = m_up * (h * size.y);
  return true;
}

} // namespace prism
