// Triangle meshes, indexed or as a soup (KHR_GEOMETRY_TRIANGLE).
#pragma once

#include "Geometry.h"

namespace prism {

class Triangle : public Geometry
{
 public:
  explicit Triangle(DeviceState &device) : Geometry(device, "triangle") {}
  void addTo(rt::Scene &scene, uint32_t id) const override;
  void appendEmitterShape(EmitterShape &shape) const override;

 protected:
  void readShape() override;
  Corners cornersAt(uint32_t primitive, float u, float v) const override;
  uint32_t faceVaryingCorners() const override
  {
    return 3;
  }
};

} // namespace prism
