// Everything a renderer needs about the surface a ray hit: which surface,
// its material, the attributes there, and the normals in world space.
#pragma once

#include "../camera/Camera.h"
#include "../geometry/Attributes.h"
#include "../rt/Hit.h"
#include "../world/World.h"
#include "FrameBuffers.h"

namespace prism {

struct SurfaceHit
{
  const Surface *surface{nullptr};
  const World::Placement *placement{nullptr};
  AttributeValues attributes;
  float3 position;        // world space
  float3 shadingNormal;   // world space, unit, facing the ray
  float3 geometricNormal; // world space, unit, facing the ray
  bool backFacing{false}; // whether the ray hit the geometry's back side
  float distance{0.f};

  const Material &material() const
  {
    return *surface->material();
  }
};

// What resolveSurfaceHit() must compute beyond normals and ids.
enum class HitDetail : uint8_t {
  Full,        // every attribute (samplers, debug views, path tracing)
  ForMaterial, // only what the material's base color needs
  ForShading,  // only what the material's inputs need
};

// Resolves `hit` of `ray` in `world`; false if it names no live surface.
bool resolveSurfaceHit(const World &world,
    const Ray &ray,
    const rt::Hit &hit,
    SurfaceHit &out,
    HitDetail detail = HitDetail::Full);

// Fills the channels of `sample` a surface shows where a ray first meets
// it at `t`: depth, shading normal, `albedo` and the ids.
void recordSurfaceChannels(PixelSample &sample,
    float t,
    const SurfaceHit &surface,
    const float3 &albedo);

} // namespace prism
