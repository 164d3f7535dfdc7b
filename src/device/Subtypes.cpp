#include "Subtypes.h"

#include "camera/Omnidirectional.h"
#include "camera/Orthographic.h"
#include "camera/Perspective.h"
#include "frame/Frame.h"
#include "geometry/Geometry.h"
#include "light/Light.h"
#include "material/Material.h"
#include "renderer/AmbientOcclusion.h"
#include "renderer/Debug.h"
#include "renderer/PathTracer.h"
#include "renderer/Raycast.h"
#include "sampler/Sampler.h"
#include "volume/SpatialField.h"
#include "volume/Volume.h"
#include "world/Group.h"
#include "world/Instance.h"
#include "world/Surface.h"
#include "world/World.h"

namespace prism {
namespace {

Object *createCamera(DeviceState &device, const std::string &subtype)
{
  if (subtype == "perspective")
    return new Perspective(device);
  if (subtype == "orthographic")
    return new Orthographic(device);
  if (subtype == "omnidirectional")
    return new Omnidirectional(device);
  return nullptr;
}

Object *createRenderer(DeviceState &device, const std::string &subtype)
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

// Types without subtypes: any subtype string names the one kind.
template <typename T>
SubtypeRegistry::Factory only()
{
  return [](DeviceState &device, const std::string &) -> Object * {
    return new T(device);
  };
}

} // namespace

void addPrismSubtypes(SubtypeRegistry &registry)
{
  registry.add(ANARI_CAMERA, createCamera);
  registry.add(ANARI_RENDERER, createRenderer);
  registry.add(ANARI_GEOMETRY, createGeometry);
  registry.add(ANARI_MATERIAL, createMaterial);
  registry.add(ANARI_SAMPLER, createSampler);
  registry.add(ANARI_LIGHT, createLight);
  registry.add(ANARI_INSTANCE, createInstance);
  registry.add(ANARI_FRAME, only<Frame>());
  registry.add(ANARI_SURFACE, only<Surface>());
  registry.add(ANARI_GROUP, only<Group>());
  registry.add(ANARI_WORLD, only<World>());
  registry.add(ANARI_SPATIAL_FIELD, createSpatialField);
  registry.add(ANARI_VOLUME, createVolume);
}

} // namespace prism
