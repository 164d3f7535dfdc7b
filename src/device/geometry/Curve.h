// Curves of round linear segments (KHR_GEOMETRY_CURVE), traced as Embree's
// native round linear curves.
#pragma once

#include "Geometry.h"
#include "SharedElements.h"

namespace prism {

class Curve : public Geometry
{
 public:
  explicit Curve(DeviceState &device) : Geometry(device, "curve") {}
  void addTo(rt::Scene &scene, uint32_t id) const override;

 protected:
  void readShape() override;
  Corners cornersAt(uint32_t primitive, float u, float v) const override;
  size_t copiedBytes() const override;

 private:
  // 'vertex.positionRadius' in place when 16-byte aligned and Embree may
  // read one element past its end, else copied.
  bool readPositionRadiusShape();

  SharedElements<float4> m_positionRadius; // per vertex (+1 padding)
};

} // namespace prism
