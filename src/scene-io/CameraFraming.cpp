#include "CameraFraming.h"

#include "Math.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace prism::scene_io {

using scenes::Vec3;
// std::array vectors: their operators live in prism::scenes, out of ADL's
// reach.
using scenes::operator+;
using scenes::operator-;
using scenes::operator*;

namespace {

// Fits `points` (inside `box`) into a perspective view looking along
// -`towardsEye` with the half-field tangents `tanY` (vertical) and `tanX`:
// the points projected, the eye moved back until every one is inside kFill
// of the frame, the view shifted sideways until the projection is centred
// (a few rounds; the last distance is computed for the last centre, so the
// fit holds whatever the shift).
void fitPoints(const std::vector<Vec3> &points,
    const scenes::Bounds &box,
    const Vec3 &towardsEye,
    const Vec3 &upHint,
    float tanY,
    float tanX,
    Vec3 &eye,
    Vec3 &at)
{
  const Vec3 forward = towardsEye * -1.f;
  Vec3 right = scenes::normalize(scenes::cross(forward, upHint));
  if (scenes::length(right) == 0.f)
    right = scenes::normalize(scenes::cross(forward, Vec3{0.f, 0.f, 1.f}));
  const Vec3 up = scenes::cross(right, forward);
  const float size = std::max(scenes::length(box.upper - box.lower), 1e-3f);
  Vec3 center = (box.lower + box.upper) * 0.5f;
  float distance = size;
  for (int round = 0; round < 4; round++) {
    // The distance from `center` that fits every corner.
    distance = 0.f;
    for (const Vec3 &point : points) {
      const Vec3 p = point - center;
      const float x = scenes::dot(p, right), y = scenes::dot(p, up),
                  z = scenes::dot(p, forward);
      distance = std::max(distance, std::abs(x) / (tanX * kFill) - z);
      distance = std::max(distance, std::abs(y) / (tanY * kFill) - z);
      distance = std::max(distance, 1e-3f * size - z); // in front of the eye
    }
    // Where the projection's middle falls, moved to the frame's centre.
    float lowX = 1e30f, highX = -1e30f, lowY = 1e30f, highY = -1e30f;
    for (const Vec3 &point : points) {
      const Vec3 p = point - center;
      const float depth = distance + scenes::dot(p, forward);
      const float sx = scenes::dot(p, right) / depth;
      const float sy = scenes::dot(p, up) / depth;
      lowX = std::min(lowX, sx), highX = std::max(highX, sx);
      lowY = std::min(lowY, sy), highY = std::max(highY, sy);
    }
    if (round == 3)
      break;
    center = center + right * (0.5f * (lowX + highX) * distance)
             + up * (0.5f * (lowY + highY) * distance);
  }
  at = center;
  eye = center + towardsEye * distance;
}

std::vector<Vec3> corners(const scenes::Bounds &box)
{
  std::vector<Vec3> points(8);
  for (int c = 0; c < 8; c++)
    points[size_t(c)] = {(c & 1) ? box.upper[0] : box.lower[0],
        (c & 2) ? box.upper[1] : box.lower[1],
        (c & 4) ? box.upper[2] : box.lower[2]};
  return points;
}

} // namespace

CameraSetup frameCamera(const scenes::SuggestedCamera &suggested,
    const scenes::Bounds &bounds,
    float aspect,
    const CameraOverrides &overrides,
    const std::vector<Vec3> &outline)
{
  CameraSetup camera;
  scenes::Bounds box = bounds;
  if (box.empty()) {
    box.extend(Vec3{-1.f, -1.f, -1.f});
    box.extend(Vec3{1.f, 1.f, 1.f});
  }
  // A degenerate box (one point) still needs a size.
  const float radius =
      std::max(0.5f * scenes::length(box.upper - box.lower), 1e-3f);

  if (suggested.valid) {
    camera.eye = suggested.eye;
    camera.at = suggested.at;
    camera.up = suggested.up;
    camera.fovyDegrees = suggested.fovyDegrees;
    camera.orthographic = suggested.orthographic;
    camera.height = suggested.height;
  } else {
    camera.framed = true;
    camera.fovyDegrees = overrides.fovyDegrees.value_or(40.f);
    const float halfFovy =
        0.5f * camera.fovyDegrees * std::numbers::pi_v<float> / 180.f;
    const Vec3 direction = scenes::normalize(Vec3{0.35f, 0.3f, 1.f});
    const Vec3 up = overrides.up.value_or(camera.up);
    fitPoints(outline.empty() ? corners(box) : outline,
        box,
        direction,
        up,
        std::tan(halfFovy),
        std::tan(halfFovy) * aspect,
        camera.eye,
        camera.at);
    camera.height = 2.f * radius;
  }

  if (overrides.fovyDegrees)
    camera.fovyDegrees = *overrides.fovyDegrees;
  if (overrides.up)
    camera.up = *overrides.up;
  if (overrides.eye && overrides.at) {
    camera.eye = *overrides.eye;
    camera.at = *overrides.at;
  } else if (overrides.eye) {
    // A new position keeps looking at what the view was aimed at.
    camera.eye = *overrides.eye;
  } else if (overrides.at) {
    // A new target keeps the viewing direction and distance.
    camera.eye = camera.eye + (*overrides.at - camera.at);
    camera.at = *overrides.at;
  }
  if (scenes::length(camera.at - camera.eye) <= 0.f)
    camera.at = camera.eye + Vec3{0.f, 0.f, -1.f};
  return camera;
}

} // namespace prism::scene_io
