#include "CameraFraming.h"

#include "Math.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace prism::render {

using scenes::Vec3;
// std::array vectors: their operators live in prism::scenes, out of ADL's
// reach.
using scenes::operator+;
using scenes::operator-;
using scenes::operator*;

CameraSetup frameCamera(const scenes::SuggestedCamera &suggested,
    const scenes::Bounds &bounds,
    float aspect,
    const Options &options)
{
  CameraSetup camera;
  scenes::Bounds box = bounds;
  if (box.empty()) {
    box.extend(Vec3{-1.f, -1.f, -1.f});
    box.extend(Vec3{1.f, 1.f, 1.f});
  }
  const Vec3 center = (box.lower + box.upper) * 0.5f;
  // A degenerate box (one point, a flat plane) still needs a distance.
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
    camera.fovyDegrees = options.fovyDegrees.value_or(40.f);
    const float halfFovy =
        0.5f * camera.fovyDegrees * std::numbers::pi_v<float> / 180.f;
    // The narrower of the two fields of view decides the distance.
    const float halfFovx = std::atan(std::tan(halfFovy) * aspect);
    const float distance = radius / std::sin(std::min(halfFovy, halfFovx));
    const Vec3 direction = scenes::normalize(Vec3{0.35f, 0.3f, 1.f});
    camera.at = center;
    camera.eye = center + direction * distance;
    camera.height = 2.f * radius;
  }

  if (options.fovyDegrees)
    camera.fovyDegrees = *options.fovyDegrees;
  if (options.up)
    camera.up = *options.up;
  if (options.eye && options.at) {
    camera.eye = *options.eye;
    camera.at = *options.at;
  } else if (options.eye) {
    // A new position keeps looking at what the view was aimed at.
    camera.eye = *options.eye;
  } else if (options.at) {
    // A new target keeps the viewing direction and distance.
    camera.eye = camera.eye + (*options.at - camera.at);
    camera.at = *options.at;
  }
  if (scenes::length(camera.at - camera.eye) <= 0.f)
    camera.at = camera.eye + Vec3{0.f, 0.f, -1.f};
  return camera;
}

} // namespace prism::render
