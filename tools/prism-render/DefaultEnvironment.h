// The environment prism-render lights a scene with when nothing in it emits
// light (most glTF and OBJ files carry no lights): a neutral procedural
// studio, or any equirectangular image, as an `hdri` light. Without it the
// path tracer (ambient radiance 0, the spec's default) renders black.
#pragma once

#include "Math.h"

#include <anari/anari.h>

#include <string>

namespace prism::render {

struct EnvironmentChoice
{
  // "studio" (procedural), "none", or the path of a .hdr/.exr (or any
  // image prism-render reads) in equirectangular layout.
  std::string source{"studio"};
  float intensity{1.f};
  float rotateDegrees{0.f}; // about `up`
};

struct Environment
{
  ANARILight light{nullptr}; // the caller releases it
  std::string description;   // for the one line on stderr
  std::string error;         // empty on success
};

// The hdri light of `choice` with `up` as the environment's up (the
// scene's; glTF is +y), or no light for "none".
Environment makeEnvironment(ANARIDevice device,
    const EnvironmentChoice &choice,
    const scenes::Vec3 &up);

// Sets `light` as the world's only light and recommits the world.
void lightWorldWith(ANARIDevice device, ANARIWorld world, ANARILight light);

} // namespace prism::render
