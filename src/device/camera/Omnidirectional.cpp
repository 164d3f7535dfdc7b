#include "Omnidirectional.h"

#include <cmath>

namespace prism {

Omnidirectional::Omnidirectional(DeviceState &device)
    : Camera(device, "omnidirectional")
{}

void Omnidirectional::commitParameters()
{
  Camera::commitParameters();
  // 'equirectangular' is the only layout the spec defines; param() reports
  // any other.
  param<std::string>("layout");
}

Ray Omnidirectional::rayThroughSensor(
    float2 sensor, float eyeShift, float2 lensSample, float) const
{
  // Longitude grows towards 'right' as x grows, so the image reads like the
  // view from inside the sphere (not mirrored); x = 0 and 1 look backwards.
  const float longitude = float(2.0 * M_PI) * (sensor.x - 0.5f);
  const float latitude = float(M_PI) * (sensor.y - 0.5f);
  const float cosLatitude = std::cos(latitude);
  const float sinLongitude = std::sin(longitude);
  const float cosLongitude = std::cos(longitude);
  const float3 direction = normalize(
      (m_right * sinLongitude + m_direction * cosLongitude) * cosLatitude
      + m_up * std::sin(latitude));
  // Omnidirectional stereo: the baseline turns with longitude so both eyes
  // stay side by side whichever way the column looks.
  const float3 localRight = m_right * cosLongitude - m_direction * sinLongitude;
  const float3 eye = m_position + localRight * eyeShift;
  // The lens faces each ray; everything at focusDistance is sharp.
  return throughLens(eye,
      direction,
      m_focusDistance,
      localRight,
      cross(localRight, direction),
      lensSample);
}

} // namespace prism
