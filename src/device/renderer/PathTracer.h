// The `pathtracer` renderer: unidirectional path tracing with next-event
// estimation and multiple importance sampling (power heuristic) for every
// light, emissive surfaces and the renderer's ambient light; Russian
// roulette after three bounces. One path per pixel per frame: with frame
// accumulation the image converges.
//
// This is the per-path form of the integrator; the wavefront form (ray
// queues traced bounce by bounce, the interface the MPI device forwards)
// replaces its loop without changing what it computes.
#pragma once

#include "Renderer.h"

namespace prism {

class PlacedLight;

class PathTracer : public Renderer
{
 public:
  PathTracer(Device &device, const std::string &subtype)
      : Renderer(device, subtype)
  {}

  uint32_t convergedSampleCount() const override
  {
    return 256;
  }

 protected:
  void commitParameters() override;
  PixelSample shadeSample(const RenderContext &context,
      const Ray &ray,
      const rt::Hit &hit,
      uint32_t x,
      uint32_t y) const override;

 private:
  // Radiance arriving along a ray that escapes the scene (or reaches a
  // light before `hitDistance`), weighted against light sampling.
  float3 lightsAlong(const RenderContext &context,
      const float3 &origin,
      const float3 &direction,
      float hitDistance,
      float bsdfPdf,
      bool bsdfWasDelta,
      bool cameraRay) const;

  int m_maxPathLength{8};
  float3 m_ambient{0.f, 0.f, 0.f}; // ambientColor * ambientRadiance
};

} // namespace prism
