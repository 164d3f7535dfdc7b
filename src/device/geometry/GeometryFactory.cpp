#include "Cone.h"
#include "Curve.h"
#include "Cylinder.h"
#include "Isosurface.h"
#include "Quad.h"
#include "Sphere.h"
#include "Triangle.h"

namespace prism {

Geometry *createGeometry(DeviceState &device, const std::string &subtype)
{
  if (subtype == "triangle")
    return new Triangle(device);
  if (subtype == "quad")
    return new Quad(device);
  if (subtype == "sphere")
    return new Sphere(device);
  if (subtype == "curve")
    return new Curve(device);
  if (subtype == "cone")
    return new Cone(device);
  if (subtype == "cylinder")
    return new Cylinder(device);
  if (subtype == "isosurface")
    return new Isosurface(device);
  return nullptr;
}

} // namespace prism
