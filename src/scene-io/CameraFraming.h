// Where the camera goes: what the user gives (prism-render's
// --eye/--at/--up/--fovy) over the scene's own camera, over a view framed to
// the world bounds.
#pragma once

#include "Scene.h"

#include <optional>
#include <vector>

namespace prism::scene_io {

// What the user fixed of the view; the rest comes from the scene.
struct CameraOverrides
{
  std::optional<scenes::Vec3> eye, at, up;
  std::optional<float> fovyDegrees;
};

struct CameraSetup
{
  scenes::Vec3 eye{0.f, 0.f, 1.f};
  scenes::Vec3 at{0.f, 0.f, 0.f};
  scenes::Vec3 up{0.f, 1.f, 0.f};
  float fovyDegrees{45.f};
  bool orthographic{false};
  float height{1.f};  // orthographic view height, world units
  bool framed{false}; // true when placed from the bounds
};

// How much of the frame (of its narrower side) a framed scene fills: a
// margin of 4 % on each side.
constexpr float kFill = 0.92f;

// The camera for an image of `aspect` (width / height). Without a scene
// camera the view looks at `bounds` from the front (+z), slightly from above
// and the right, centred and just far enough back that the scene's
// `outline` (scenes::Scene::outline; empty: the box's eight corners) fills
// kFill of the frame along its tighter direction. Empty bounds frame the
// unit cube.
CameraSetup frameCamera(const scenes::SuggestedCamera &suggested,
    const scenes::Bounds &bounds,
    float aspect,
    const CameraOverrides &overrides,
    const std::vector<scenes::Vec3> &outline = {});

} // namespace prism::scene_io
