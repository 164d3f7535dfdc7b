// Quad meshes, indexed or as a soup (KHR_GEOMETRY_QUAD).
#pragma once

#include "Geometry.h"

namespace prism {

class Quad : public Geometry
{
 public:
  explicit Quad(DeviceState &device) : Geometry(device, "quad") {}
  void addTo(rt::Scene &scene, uint32_t id) const override;
  void appendEmitterShape(EmitterShape &shape) const override;

 protected:
  void readShape() override;
  Corners cornersAt(uint32_t primitive, float u, float v) const override;
  uint32_t faceVaryingCorners() const override
  {
    return 4;
  }
};

} // namespace prism
