#include "ObjectFactory.h"

#include "../Device.h"
#include "../camera/Omnidirectional.h"
#include "../camera/Orthographic.h"
#include "../camera/Perspective.h"
#include "../frame/Frame.h"
#include "../geometry/Geometry.h"
#include "../light/Light.h"
#include "../material/Material.h"
#include "../renderer/AmbientOcclusion.h"
#include "../renderer/Debug.h"
#include "../renderer/PathTracer.h"
#include "../renderer/Raycast.h"
#include "../sampler/Sampler.h"
#include "../world/Group.h"
#include "../world/Instance.h"
#include "../world/Surface.h"
#include "../world/World.h"

namespace prism {
namespace {

Object *createCamera(Device &device, const std::string &subtype)
{
  if (subtype == "perspective")
    return new Perspective(device);
  if (subtype == "orthographic")
    return new Orthographic(device);
  if (subtype == "omnidirectional")
    return new Omnidirectional(device);
  return nullptr;
}

Object *createRenderer(Device &device, const std::string &subtype)
{
  // "default" is the first listed subtype (spec 5.3): the path tracer.
  if (subtype == "default" || subtype == "pathtracer")
    return new PathTracer(device, subtype);
  if (subtype == "raycast")
    return new Raycast(device, subtype);
  if (subtype == "debug")
    return new Debug(device);
  if (subtype == "ao")
    return new AmbientOcclusion(device);
  return nullptr;
}

bool isCreatable(ANARIDataType type)
{
  switch (int(type)) {
  case ANARI_CAMERA:
  case ANARI_FRAME:
  case ANARI_GEOMETRY:
  case ANARI_GROUP:
  case ANARI_INSTANCE:
  case ANARI_LIGHT:
  case ANARI_MATERIAL:
  case ANARI_RENDERER:
  case ANARI_SURFACE:
  case ANARI_SAMPLER:
  case ANARI_SPATIAL_FIELD:
  case ANARI_VOLUME:
  case ANARI_WORLD:
    return true;
  default:
    return false;
  }
}

} // namespace

void UnknownObject::commitParameters()
{
  // Read everything: the subtype was already reported as unknown, so its
  // parameters are not reported again one by one.
  readAll();
}

Object *createObject(
    Device &device, ANARIDataType type, const std::string &subtype)
{
  if (!isCreatable(type))
    return nullptr;
  Object *object = nullptr;
  switch (int(type)) {
  case ANARI_CAMERA:
    object = createCamera(device, subtype);
    break;
  case ANARI_RENDERER:
    object = createRenderer(device, subtype);
    break;
  case ANARI_GEOMETRY:
    object = createGeometry(device, subtype);
    break;
  case ANARI_MATERIAL:
    object = createMaterial(device, subtype);
    break;
  case ANARI_SAMPLER:
    object = createSampler(device, subtype);
    break;
  case ANARI_LIGHT:
    object = createLight(device, subtype);
    break;
  case ANARI_INSTANCE:
    object = createInstance(device, subtype);
    break;
  case ANARI_FRAME:
    return new Frame(device);
  case ANARI_SURFACE:
    return new Surface(device);
  case ANARI_GROUP:
    return new Group(device);
  case ANARI_WORLD:
    return new World(device);
  default:
    break;
  }
  if (object)
    return object;
  auto *unknown = new UnknownObject(device, type, subtype);
  unknown->report(ANARI_SEVERITY_WARNING,
      ANARI_STATUS_INVALID_ARGUMENT,
      "unknown subtype '%s'; the object will not render",
      subtype.c_str());
  return unknown;
}

} // namespace prism
