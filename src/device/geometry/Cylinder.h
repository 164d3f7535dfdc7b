// Cylinders (KHR_GEOMETRY_CYLINDER): cones whose two radii are equal, one
// radius per primitive or a uniform one.
#pragma once

#include "Cone.h"

namespace prism {

class Cylinder : public Cone
{
 public:
  explicit Cylinder(DeviceState &device) : Cone(device, "cylinder") {}

 protected:
  void readRadii() override
  {
    m_segmentRadii = readFloats("primitive.radius");
    m_uniformRadius = read<float>("radius", ANARI_FLOAT32, 1.f);
  }
};

} // namespace prism
