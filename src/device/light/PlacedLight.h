// A light in world space, as an instance placed it: what a renderer samples
// for next-event estimation and evaluates for multiple importance sampling.
// Units: radiance W/sr/m^2, irradiance W/m^2, distances in world units,
// pdfs per steradian of the direction leaving the shading point.
#pragma once

#include "../math/Vec.h"

namespace prism {

// One sample of a light seen from a shading point.
struct LightSample
{
  float3 direction{0.f, 0.f, 1.f}; // unit, from the point towards the light
  float distance{0.f}; // to the sampled point; +inf for distant lights
  // Incident radiance (W/sr/m^2) along -direction before visibility. For
  // delta lights it is the irradiance (W/m^2) across `direction` instead,
  // so radiance * cos / pdf is the estimator's weight in both cases.
  float3 radiance{0.f, 0.f, 0.f};
  float pdf{0.f}; // per steradian; 1 for delta lights; 0 means no sample
  bool delta{false};
};

// A sphere around all of a light that rays can reach.
struct LightBounds
{
  float3 center{0.f, 0.f, 0.f};
  float radius{0.f};
};

// NOTE: immutable once placed, so render threads share one without locks;
// subtypes share their tables (hdri image, photometric data) by
// shared_ptr<const>, so a placement outlives a recommit of its light.
class PlacedLight
{
 public:
  virtual ~PlacedLight() = default;

  // A direction towards the light from `point` (world space), chosen with
  // `u` uniform in [0,1)^2.
  virtual LightSample sample(const float3 &point, const float2 &u) const = 0;
  // The same, for a receiver that takes light only from the side its unit
  // `normal` faces (zero: from every side, as in a medium or through a
  // transmissive surface): a light made of many parts can then prefer
  // those above the receiver's horizon. Others sample as without it.
  virtual LightSample sampleFacing(
      const float3 &point, const float3 &normal, const float2 &u) const
  {
    (void)normal;
    return sample(point, u);
  }
  // What a ray leaving `point` along the unit `direction` receives from
  // this light if nothing occludes it: the radiance, the distance at which
  // it reaches the light (+inf for distant lights and misses) and the pdf
  // sample() would have chosen that direction with. Zero radiance and pdf
  // for misses and delta lights, which no ray can hit.
  virtual float3 radianceAlong(const float3 &point,
      const float3 &direction,
      float &distance,
      float &pdf) const = 0;
  // radianceAlong() for a ray leaving a receiver facing the unit `normal`
  // (as sampleFacing() was given): the pdf is sampleFacing()'s.
  virtual float3 radianceAlongFacing(const float3 &point,
      const float3 &normal,
      const float3 &direction,
      float &distance,
      float &pdf) const
  {
    (void)normal;
    return radianceAlong(point, direction, distance, pdf);
  }
  // Point, spot, zero-radius ring and zero-diameter directional lights.
  virtual bool isDelta() const
  {
    return false;
  }
  // Whether radianceAlong() can find it: false for delta lights and for
  // lights whose surfaces rays hit as geometry (emissive surfaces).
  virtual bool reachableByRays() const
  {
    return !isDelta();
  }
  // Where radianceAlong() can find the light, so rays passing elsewhere
  // need not ask it; false for lights at infinity (and any without
  // bounds), which every ray must ask.
  virtual bool bounds(LightBounds &) const
  {
    return false;
  }
  // Directional and hdri lights: at infinity, outside every scene bound.
  virtual bool isInfinite() const
  {
    return false;
  }
  // The radiant flux emitted (W, times color), to choose lights in
  // proportion. Infinite lights return it per square metre of the scene's
  // cross-section (W/m^2): multiply by pi * sceneRadius^2.
  virtual float3 power() const = 0;

  // KHR_LIGHT_PRIMARY_VISIBILITY: whether camera rays see the emitter.
  bool visibleToCamera{true};
};

} // namespace prism
