#include "Perspective.h"

#include <cmath>

namespace prism {

Perspective::Perspective(Device &device) : Camera(device, "perspective") {}

void Perspective::commitParameters()
{
  Camera::commitParameters();
  constexpr float kDefaultFovy = float(M_PI / 3.0);
  float fovy = read<float>("fovy", ANARI_FLOAT32, kDefaultFovy);
  if (!(fovy > 0.f && fovy < float(M_PI))) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'fovy' (%g) must be in (0, pi); using pi/3",
        fovy);
    fovy = kDefaultFovy;
  }
  m_halfHeight = std::tan(0.5f * fovy);
  float aspect = read<float>("aspect", ANARI_FLOAT32, 1.f);
  if (!(aspect > 0.f && std::isfinite(aspect))) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'aspect' (%g) must be > 0; using 1",
        aspect);
    aspect = 1.f;
  }
  m_aspect = aspect * m_eyeAspectScale;
  readNearFar(m_near, m_far);
}

Ray Perspective::rayThroughSensor(
    float2 sensor, float eyeShift, float2 lensSample) const
{
  const float3 onPlane =
      m_direction + m_right * ((2.f * sensor.x - 1.f) * m_halfHeight * m_aspect)
      + m_up * ((2.f * sensor.y - 1.f) * m_halfHeight);
  const float3 direction = normalize(onPlane);
  // Parallel eyes: the same view frustum, shifted along the baseline.
  const float3 eye = m_position + m_right * eyeShift;
  // The focal plane lies focusDistance along the view direction.
  const float focusT = m_focusDistance / dot(direction, m_direction);
  Ray ray = throughLens(eye, direction, focusT, m_right, m_up, lensSample);
  clipAlongView(ray, m_near, m_far);
  return ray;
}

} // namespace prism
