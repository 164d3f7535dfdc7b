#include "OrbitCamera.h"

#include "Math.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace prism::viewer {

using scenes::operator-;
using scenes::operator+;
using scenes::operator*;

namespace {

constexpr float kDegrees = std::numbers::pi_v<float> / 180.f;
// Orbiting stops this far (in degrees) from looking straight along up.
constexpr float kPoleMargin = 1.f;

float angleBetween(const Vec3 &a, const Vec3 &b)
{
  const float c = scenes::dot(scenes::normalize(a), scenes::normalize(b));
  return std::acos(std::clamp(c, -1.f, 1.f)) / kDegrees;
}

} // namespace

Vec3 rotateAbout(const Vec3 &v, const Vec3 &axis, float degrees)
{
  // Rodrigues' rotation formula.
  const float c = std::cos(degrees * kDegrees),
              s = std::sin(degrees * kDegrees);
  return v * c + scenes::cross(axis, v) * s
         + axis * (scenes::dot(axis, v) * (1.f - c));
}

void OrbitCamera::reset(const scene_io::CameraSetup &setup, const Vec3 &pivot)
{
  m_pose.eye = setup.eye;
  m_pose.at = setup.at;
  m_pose.up = scenes::normalize(setup.up);
  m_pose.fovyDegrees = setup.fovyDegrees;
  m_pose.orthographic = setup.orthographic;
  m_pose.height = setup.height;
  m_pose.focusDistance = distance();
  m_pivot = pivot;
}

float OrbitCamera::distance() const
{
  return scenes::length(m_pose.at - m_pose.eye);
}

void OrbitCamera::orbit(float yawDegrees, float pitchDegrees)
{
  const Vec3 up = m_pose.up;
  // Positive yaw moves the eye to its right (the scene turns left).
  Vec3 eye = rotateAbout(m_pose.eye - m_pivot, up, yawDegrees);
  Vec3 at = rotateAbout(m_pose.at - m_pivot, up, yawDegrees);
  const Vec3 view = at - eye;
  const Vec3 right = scenes::normalize(scenes::cross(view, up));
  if (pitchDegrees != 0.f && scenes::length(right) > 0.f) {
    // Positive pitch raises the eye, tilting the view down, towards -up;
    // the view stays off the poles.
    const float fromUp = angleBetween(view, up);
    const float limited = std::clamp(
        pitchDegrees, kPoleMargin - fromUp, 180.f - fromUp - kPoleMargin);
    eye = rotateAbout(eye, right, -limited);
    at = rotateAbout(at, right, -limited);
  }
  m_pose.eye = eye + m_pivot;
  m_pose.at = at + m_pivot;
}

void OrbitCamera::pan(float right, float up)
{
  const Vec3 view = scenes::normalize(m_pose.at - m_pose.eye);
  const Vec3 r = scenes::normalize(scenes::cross(view, m_pose.up));
  const Vec3 u = scenes::cross(r, view);
  const float height =
      m_pose.orthographic
          ? m_pose.height
          : 2.f * distance() * std::tan(0.5f * m_pose.fovyDegrees * kDegrees);
  const Vec3 shift = r * (right * height) + u * (up * height);
  m_pose.eye = m_pose.eye + shift;
  m_pose.at = m_pose.at + shift;
  m_pivot = m_pivot + shift;
}

void OrbitCamera::zoom(float factor)
{
  if (!(factor > 0.f) || !std::isfinite(factor))
    return;
  if (m_pose.orthographic) {
    m_pose.height *= factor;
    return;
  }
  const Vec3 back = m_pose.eye - m_pose.at;
  const float d = scenes::length(back);
  // Never closer than a millionth of the start: the view stays defined.
  const float next = std::max(d * factor, 1e-6f * std::max(d, 1.f));
  m_pose.eye = m_pose.at + scenes::normalize(back) * next;
}

void OrbitCamera::fly(float forward, float right, float upward)
{
  const Vec3 view = scenes::normalize(m_pose.at - m_pose.eye);
  const Vec3 r = scenes::normalize(scenes::cross(view, m_pose.up));
  const Vec3 shift = view * forward + r * right + m_pose.up * upward;
  m_pose.eye = m_pose.eye + shift;
  m_pose.at = m_pose.at + shift;
  m_pivot = m_pivot + shift;
}

void OrbitCamera::look(float yawDegrees, float pitchDegrees)
{
  Vec3 view = rotateAbout(m_pose.at - m_pose.eye, m_pose.up, -yawDegrees);
  const Vec3 right = scenes::normalize(scenes::cross(view, m_pose.up));
  const float fromUp = angleBetween(view, m_pose.up);
  const float limited = std::clamp(
      pitchDegrees, kPoleMargin - (180.f - fromUp), fromUp - kPoleMargin);
  view = rotateAbout(view, right, limited);
  m_pose.at = m_pose.eye + view;
}

void OrbitCamera::setFovy(float degrees)
{
  if (std::isfinite(degrees))
    m_pose.fovyDegrees = std::clamp(degrees, 1.f, 170.f);
}

void OrbitCamera::focusOn(const Vec3 &point)
{
  const Vec3 view = scenes::normalize(m_pose.at - m_pose.eye);
  const float d = scenes::dot(point - m_pose.eye, view);
  if (d > 0.f && std::isfinite(d))
    m_pose.focusDistance = d;
}

void OrbitCamera::setAperture(float radius)
{
  if (std::isfinite(radius))
    m_pose.apertureRadius = std::max(radius, 0.f);
}

} // namespace prism::viewer
