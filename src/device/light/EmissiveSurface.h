// A surface whose material emits a constant radiance, as a light: next-event
// estimation picks a point uniformly over its area (triangles and spheres in
// world space). Rays that hit the surface are weighted against this sampling
// where they hit it (pdfOfHit()); radianceAlong() gives nothing, as finding
// the surface along a ray is the tracer's job.
#pragma once

#include "../geometry/EmitterShape.h"
#include "PlacedLight.h"

#include <vector>

namespace prism {

class EmissiveSurface final : public PlacedLight
{
 public:
  // `shape` in world space; `radiance` leaves both sides of the surface.
  EmissiveSurface(EmitterShape shape, const float3 &radiance);

  bool isEmpty() const
  {
    return !(m_area > 0.f);
  }
  bool reachableByRays() const override
  {
    return false; // the tracer finds the surface itself
  }
  size_t primitiveCount() const
  {
    return m_cdf.size();
  }
  // What it was made of (a data-parallel device sends it to the other
  // processes, which make the same light of it).
  const EmitterShape &shape() const
  {
    return m_shape;
  }
  const float3 &radiance() const
  {
    return m_radiance;
  }
  LightSample sample(const float3 &point, const float2 &u) const override;
  float3 radianceAlong(const float3 &point,
      const float3 &direction,
      float &distance,
      float &pdf) const override;
  float3 power() const override;
  // The density (per steradian at the shading point) with which sample()
  // picks the point at `distance` along a ray whose cosine with the
  // surface's normal there is `cosine`.
  float pdfOfHit(float distance, float cosine) const;

 private:
  EmitterShape m_shape;
  float3 m_radiance;
  std::vector<float> m_cdf; // over triangles then spheres, by area
  float m_area{0.f};
};

} // namespace prism
