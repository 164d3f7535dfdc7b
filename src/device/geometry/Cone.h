// Cones between vertex pairs with per-vertex radii and optional flat caps
// (KHR_GEOMETRY_CONE), intersected exactly as Embree user geometry; the
// cylinder subtype is the same shape with one radius per primitive.
#pragma once

#include "../rt/UserGeometry.h"
#include "Geometry.h"

namespace prism {

class Cone : public Geometry, public rt::UserGeometry
{
 public:
  explicit Cone(DeviceState &device, const std::string &subtype = "cone")
      : Geometry(device, subtype)
  {}
  void addTo(rt::Scene &scene, uint32_t id) const override;

  box3 primitiveBounds(uint32_t primitive) const override;
  bool intersectPrimitive(uint32_t primitive,
      const float3 &origin,
      const float3 &direction,
      float tMin,
      float tMax,
      float &t,
      float &u,
      float &v,
      float3 &normal,
      uint32_t &reportedPrimitive) const override;

 protected:
  struct Segment
  {
    uint32_t vertex[2];
    float radius[2];
    bool cap[2];
  };
  void readShape() override;
  Corners cornersAt(uint32_t primitive, float u, float v) const override;
  // Reads the subtype's radius parameters; checkRadii() sizes them.
  virtual void readRadii();
  void checkRadii(size_t segmentCount);
  // Radius of one end of a segment.
  float segmentRadius(size_t segment, int end) const;

  std::vector<float> m_vertexRadii;  // cone: per vertex
  std::vector<float> m_segmentRadii; // cylinder: per primitive
  float m_uniformRadius{1.f};

 private:
  std::vector<Segment> m_segments;
};

} // namespace prism
