// Spheres, one per vertex or per index (KHR_GEOMETRY_SPHERE), traced as
// Embree's native sphere points.
#pragma once

#include "Geometry.h"
#include "SharedElements.h"

namespace prism {

class Sphere : public Geometry
{
 public:
  explicit Sphere(DeviceState &device) : Geometry(device, "sphere") {}
  void addTo(rt::Scene &scene, uint32_t id) const override;
  void appendEmitterShape(EmitterShape &shape) const override;

 protected:
  void readShape() override;
  Corners cornersAt(uint32_t primitive, float u, float v) const override;
  float3 surfaceNormal(
      const rt::Hit &hit, const float3 &objectPosition) const override;
  size_t copiedBytes() const override;
  bool hasAnalyticNormal() const override
  {
    return true;
  }

 private:
  uint32_t vertexOf(uint32_t sphere) const
  {
    return m_indexed ? m_indices[sphere] : sphere;
  }

  // 'vertex.positionRadius': read in place unless indexed or not 16-byte
  // aligned (then gathered).
  void readPositionRadiusShape();

  bool m_indexed{false};
  SharedElements<float4> m_centerRadius; // per sphere, for Embree
};

} // namespace prism
