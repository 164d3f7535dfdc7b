// The environment a viewer lights scene files with, as glTF viewers do: a
// neutral procedural studio, or any equirectangular image, as an `hdri`
// light. glTF and OBJ files are made to be seen that way (most carry no
// lights, and an emissive label or LED lights nothing around it); without
// it the path tracer (ambient radiance 0, the spec's default) renders them
// black.
#pragma once

#include "Math.h"
#include "Scene.h"

#include <anari/anari.h>

#include <string>

namespace prism::scene_io {

struct EnvironmentChoice
{
  // "studio" (procedural), "none", or the path of a .hdr/.exr (or any
  // image prism-render reads) in equirectangular layout.
  std::string source{"studio"};
  float intensity{1.f};
  float rotateDegrees{0.f}; // about `up`
  // Whether the user chose it (prism-render's --env): a chosen environment
  // lights every scene; the default one only scenes that expect it.
  bool given{false};
};

// How much of the studio lights a file that has lights of its own: enough
// to see every side of it, dim beside its lights.
constexpr float kFillIntensity = 0.25f;

// What lights `scene`, by one rule: "none" lights nothing more; an
// environment the user chose always joins the scene's lights; by default,
// files (scenes that expect an environment) get the studio at full
// intensity when they hold no light objects, at kFillIntensity when they
// do (KHR_lights_punctual); emissive materials change nothing; demos stay
// as built. `add` false: leave the scene as it is.
struct Lighting
{
  bool add{false};
  EnvironmentChoice environment;
};
Lighting lightingFor(
    const scenes::Scene &scene, const EnvironmentChoice &choice);

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

// Adds `light` to the scene's own lights in its world and recommits it;
// `scene.lights` takes over the reference.
void addWorldLight(ANARIDevice device, scenes::Scene &scene, ANARILight light);

} // namespace prism::scene_io
