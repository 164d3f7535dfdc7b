#include "Camera.h"

#include "../array/Array.h"
#include "../math/SphereSampling.h"

#include <algorithm>
#include <cmath>

namespace prism {

Camera::Camera(DeviceState &device, const std::string &subtype)
    : MovingObject(device, ANARI_CAMERA, subtype)
{}

void Camera::commitParameters()
{
  m_position = param<float3>("position");
  float3 direction = param<float3>("direction");
  float3 up = param<float3>("up");
  struct Box2
  {
    float2 lower, upper;
  };
  const auto region =
      read<Box2>("imageRegion", ANARI_FLOAT32_BOX2, {{0, 0}, {1, 1}});
  m_regionLower = region.lower;
  m_regionUpper = region.upper;

  if (length(direction) == 0.f) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'direction' is zero; using (0, 0, -1)");
    direction = {0, 0, -1};
  }
  m_direction = normalize(direction);
  m_right = cross(m_direction, up);
  if (length(m_right) < 1e-12f) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'up' is parallel to 'direction'; choosing another up vector");
    m_right = cross(m_direction,
        std::abs(m_direction.y) < 0.9f ? float3{0, 1, 0} : float3{1, 0, 0});
  }
  m_right = normalize(m_right);
  m_up = cross(m_right, m_direction);

  m_apertureRadius = param<float>("apertureRadius");
  if (!(m_apertureRadius >= 0.f && std::isfinite(m_apertureRadius))) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'apertureRadius' (%g) must be >= 0; using 0",
        m_apertureRadius);
    m_apertureRadius = 0.f;
  }
  m_focusDistance = param<float>("focusDistance");
  if (!(m_focusDistance > 0.f && std::isfinite(m_focusDistance))) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'focusDistance' (%g) must be > 0; using 1",
        m_focusDistance);
    m_focusDistance = 1.f;
  }

  const std::string stereoMode = param<std::string>("stereoMode");
  m_stereoMode = StereoMode::kNone;
  if (stereoMode == "left")
    m_stereoMode = StereoMode::kLeft;
  else if (stereoMode == "right")
    m_stereoMode = StereoMode::kRight;
  else if (stereoMode == "sideBySide")
    m_stereoMode = StereoMode::kSideBySide;
  else if (stereoMode == "topBottom")
    m_stereoMode = StereoMode::kTopBottom;
  // 'aspect' describes the whole frame, so each eye's half keeps square
  // pixels only with half (side by side) or twice (stacked) the ratio.
  m_eyeAspectScale = m_stereoMode == StereoMode::kSideBySide  ? 0.5f
                     : m_stereoMode == StereoMode::kTopBottom ? 2.f
                                                              : 1.f;
  m_interpupillaryDistance = param<float>("interpupillaryDistance");
  if (!(m_interpupillaryDistance >= 0.f
          && std::isfinite(m_interpupillaryDistance))) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'interpupillaryDistance' (%g) must be >= 0; using 0.0635",
        m_interpupillaryDistance);
    m_interpupillaryDistance = 0.0635f;
  }

  readShutter();
  m_motion = readMotion(kMatrixKeys | kDecomposedKeys);
}

void Camera::readShutter()
{
  // FLOAT32_BOX1 is (lower, upper); the spec clamps both to [0, 1].
  m_shutter = read<float2>("shutter", ANARI_FLOAT32_BOX1, {0.5f, 0.5f});
  m_shutter = clamp(m_shutter, 0.f, 1.f);
  if (!(m_shutter.x <= m_shutter.y)) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'shutter' opens (%g) after it closes (%g); using [0.5, 0.5]",
        m_shutter.x,
        m_shutter.y);
    m_shutter = {0.5f, 0.5f};
  }

  const std::string rolling = param<std::string>("rollingShutterDirection");
  m_rollingShutter = RollingShutter::kNone;
  if (rolling == "left")
    m_rollingShutter = RollingShutter::kLeft;
  else if (rolling == "right")
    m_rollingShutter = RollingShutter::kRight;
  else if (rolling == "down")
    m_rollingShutter = RollingShutter::kDown;
  else if (rolling == "up")
    m_rollingShutter = RollingShutter::kUp;
  const float duration = param<float>("rollingShutterDuration");
  // The spec clamps the open time per line to the shutter's length.
  m_rollingShutterDuration =
      std::isnan(duration)
          ? 0.f
          : std::clamp(duration, 0.f, m_shutter.y - m_shutter.x);
}

float Camera::rayTime(float2 screen, float sample) const
{
  const float open = m_shutter.y - m_shutter.x;
  // How far along the roll the line through `screen` is: 0 opens first.
  float line = 0.f;
  switch (m_rollingShutter) {
  case RollingShutter::kNone:
    return m_shutter.x + open * sample;
  case RollingShutter::kRight:
    line = screen.x;
    break;
  case RollingShutter::kLeft:
    line = 1.f - screen.x;
    break;
  case RollingShutter::kUp:
    line = screen.y;
    break;
  case RollingShutter::kDown:
    line = 1.f - screen.y;
    break;
  }
  line = std::clamp(line, 0.f, 1.f);
  return m_shutter.x + (open - m_rollingShutterDuration) * line
         + m_rollingShutterDuration * sample;
}

void Camera::readNearFar(float &near, float &far)
{
  // The definitions give neither a default: unset, nothing is clipped.
  near = isSet("near") ? param<float>("near") : 0.f;
  far = isSet("far") ? param<float>("far")
                     : std::numeric_limits<float>::infinity();
  if (!(near >= 0.f && near < far)) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'near' (%g) and 'far' (%g) must satisfy 0 <= near < far; ignored",
        near,
        far);
    near = 0.f;
    far = std::numeric_limits<float>::infinity();
  }
}

void Camera::readAspect()
{
  m_aspect = 0.f;
  if (!isSet("aspect"))
    return;
  const float aspect = param<float>("aspect");
  if (!(aspect > 0.f && std::isfinite(aspect))) {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'aspect' (%g) must be > 0; using the frame's width / height",
        aspect);
    return;
  }
  m_aspect = aspect;
}

Ray Camera::generateRay(
    float2 screen, float2 lensSample, float time, float frameAspect) const
{
  const float halfBaseline = 0.5f * m_interpupillaryDistance;
  float eyeShift = 0.f;
  switch (m_stereoMode) {
  case StereoMode::kNone:
    break;
  case StereoMode::kLeft:
    eyeShift = -halfBaseline;
    break;
  case StereoMode::kRight:
    eyeShift = halfBaseline;
    break;
  case StereoMode::kSideBySide: {
    const bool left = screen.x < 0.5f;
    eyeShift = left ? -halfBaseline : halfBaseline;
    screen.x = left ? 2.f * screen.x : 2.f * screen.x - 1.f;
    break;
  }
  case StereoMode::kTopBottom: {
    // Screen y grows upwards and the left eye is the top half.
    const bool left = screen.y >= 0.5f;
    eyeShift = left ? -halfBaseline : halfBaseline;
    screen.y = left ? 2.f * screen.y - 1.f : 2.f * screen.y;
    break;
  }
  }
  const float2 sensor{
      m_regionLower.x + screen.x * (m_regionUpper.x - m_regionLower.x),
      m_regionLower.y + screen.y * (m_regionUpper.y - m_regionLower.y)};
  Ray ray = rayThroughSensor(sensor, eyeShift, lensSample, frameAspect);
  ray.time = time;
  if (m_motion.isSet()) {
    // The camera frame moves as a whole; distances along the ray scale
    // with the transform, so the clip range stays where it was.
    const mat3x4 worldFromCamera = m_motion.at(time);
    const float3 direction = transformDirection(worldFromCamera, ray.direction);
    const float scale = length(direction);
    ray.origin = transformPoint(worldFromCamera, ray.origin);
    ray.direction = direction / scale;
    ray.tMin *= scale;
    ray.tMax *= scale;
  }
  return ray;
}

Ray Camera::throughLens(float3 origin,
    float3 direction,
    float focusT,
    float3 lensU,
    float3 lensV,
    float2 lensSample) const
{
  if (m_apertureRadius <= 0.f)
    return {origin, direction};
  const float2 disk = sampleConcentricDisk(lensSample) * m_apertureRadius;
  const float3 lensPoint = origin + lensU * disk.x + lensV * disk.y;
  const float3 focusPoint = origin + direction * focusT;
  return {lensPoint, normalize(focusPoint - lensPoint)};
}

void Camera::clipAlongView(Ray &ray, float near, float far) const
{
  // The default, unclipped view needs no division per ray.
  if (near == 0.f && std::isinf(far)) {
    ray.tMin = 0.f;
    ray.tMax = far;
    return;
  }
  const float cosine = dot(ray.direction, m_direction);
  ray.tMin = near / cosine;
  ray.tMax = far / cosine;
}

} // namespace prism
