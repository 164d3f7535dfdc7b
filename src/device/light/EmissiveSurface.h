// A surface whose material emits a constant radiance, as a light (triangles
// and spheres in world space). Next-event estimation picks one primitive
// with a light tree (by power, distance and orientation from the shading
// point), then a point on it: uniformly in the solid angle a triangle
// subtends when that is large (spherical triangles), uniformly by area when
// it is small or far. Rays that hit the surface are weighted against this
// sampling where they hit it (pdfOfHit()); radianceAlong() gives nothing, as
// finding the surface along a ray is the tracer's job.
#pragma once

#include "../geometry/EmitterShape.h"
#include "LightTree.h"
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
    return m_primitiveArea.size();
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
  LightSample sampleFacing(const float3 &point,
      const float3 &normal,
      const float2 &u) const override;
  float3 radianceAlong(const float3 &point,
      const float3 &direction,
      float &distance,
      float &pdf) const override;
  float3 power() const override;
  // The density (per steradian at `origin`) with which sampleFacing() from
  // `origin` with `normal` picks the point at `distance` along `direction`,
  // where the ray hit the surface's primitive `primitiveId` (of its
  // geometry: a quad is two triangles) with cosine `cosine` to its normal.
  float pdfOfHit(const float3 &origin,
      const float3 &normal,
      const float3 &direction,
      uint32_t primitiveId,
      float distance,
      float cosine) const;

 private:
  // Of triangle `index` from `point`: its solid angle when sampled by solid
  // angle, else 0 (sampled by area).
  float sampledSolidAngle(const float3 &point, size_t index) const;
  // The emitter of the shape (triangles then spheres) a hit on
  // `primitiveId` at `position` found.
  size_t emitterOfHit(const float3 &position, uint32_t primitiveId) const;
  float pdfOfPoint(const float3 &origin,
      const float3 &normal,
      size_t index,
      float distance,
      float cosine) const;

  EmitterShape m_shape;
  float3 m_radiance;
  std::vector<float> m_primitiveArea; // triangles then spheres
  light::LightTree m_tree;
  float m_area{0.f};
};

} // namespace prism
