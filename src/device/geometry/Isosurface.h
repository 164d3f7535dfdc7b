// Surfaces where a spatial field takes given values (KHR_GEOMETRY_ISOSURFACE),
// intersected on the field's own interpolant: the field's bounds are cut
// into blocks a few cells wide, the blocks whose value range holds an
// isovalue become Embree user primitives, and rays march through them to a
// sign change of (value - isovalue) refined by bisection. The primitive a
// hit reports is the isovalue's index; its normal is the field's gradient
// (pointing towards increasing values).
#pragma once

#include "../rt/UserGeometry.h"
#include "Geometry.h"

namespace prism {

class SpatialField;

class Isosurface : public Geometry, public rt::UserGeometry
{
 public:
  explicit Isosurface(DeviceState &device) : Geometry(device, "isosurface") {}
  void addTo(rt::Scene &scene, uint32_t id) const override;

  box3 primitiveBounds(uint32_t block) const override;
  bool intersectPrimitive(uint32_t block,
      const float3 &origin,
      const float3 &direction,
      float tMin,
      float tMax,
      float &t,
      float &u,
      float &v,
      float3 &normal,
      uint32_t &isovalueIndex) const override;

 protected:
  void readShape() override;
  Corners cornersAt(uint32_t, float, float) const override
  {
    return {}; // no vertices: only primitive.* and uniform attributes
  }
  float3 surfaceNormal(
      const rt::Hit &hit, const float3 &objectPosition) const override;
  bool hasAnalyticNormal() const override
  {
    return true;
  }

 private:
  bool readIsovalues();
  void buildBlocks();
  // The crossing of `isovalue` between ta and tb (the field's values there
  // lie on either side of it), refined to a small fraction of a cell.
  float refineCrossing(const float3 &origin,
      const float3 &direction,
      float ta,
      float tb,
      float isovalue) const;

  // Held by the commit's dependency on it (see Object::dependOn).
  const SpatialField *m_field{nullptr};
  std::vector<float> m_isovalues;
  std::vector<box3> m_blocks;
  float m_step{1.f}; // marching step, object-space distance
};

} // namespace prism
