#include "Orthographic.h"

#include <cmath>

namespace prism {

Orthographic::Orthographic(DeviceState &device) : Camera(device, "orthographic")
{}

void Orthographic::commitParameters()
{
  Camera::commitParameters();
  m_height = param<float>("height");
  if (!(m_height > 0.f && std::isfinite(m_height))) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'height' (%g) must be > 0; using 1",
        m_height);
    m_height = 1.f;
  }
  readAspect();
  readNearFar(m_near, m_far);
}

Ray Orthographic::rayThroughSensor(
    float2 sensor, float eyeShift, float2 lensSample, float frameAspect) const
{
  const float aspect = eyeAspect(frameAspect);
  const float3 origin =
      m_position + m_right * ((sensor.x - 0.5f) * m_height * aspect + eyeShift)
      + m_up * ((sensor.y - 0.5f) * m_height);
  // The spec gives no orthographic lens; this one is telecentric: a lens
  // disk around each sensor ray, all of it focused at focusDistance.
  Ray ray = throughLens(
      origin, m_direction, m_focusDistance, m_right, m_up, lensSample);
  clipAlongView(ray, m_near, m_far);
  return ray;
}

} // namespace prism
