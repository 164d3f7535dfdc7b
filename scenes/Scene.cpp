#include "Scene.h"

#include <algorithm>

namespace prism::scenes {

bool Bounds::empty() const
{
  return !(
      lower[0] <= upper[0] && lower[1] <= upper[1] && lower[2] <= upper[2]);
}

void Bounds::extend(const Vec3 &point)
{
  for (int i = 0; i < 3; i++) {
    lower[i] = std::min(lower[i], point[i]);
    upper[i] = std::max(upper[i], point[i]);
  }
}

void Bounds::extend(const Bounds &other)
{
  if (other.empty())
    return;
  extend(other.lower);
  extend(other.upper);
}

ANARISurface newListedSurface(ANARIDevice device,
    std::vector<SceneSurface> &surfaces,
    ANARIGeometry geometry,
    const std::string &geometrySubtype,
    ANARIMaterial material,
    const std::string &materialSubtype,
    uint32_t id)
{
  ANARISurface surface = anariNewSurface(device);
  anariSetParameter(device, surface, "geometry", ANARI_GEOMETRY, &geometry);
  anariSetParameter(device, surface, "material", ANARI_MATERIAL, &material);
  anariSetParameter(device, surface, "id", ANARI_UINT32, &id);
  anariCommitParameters(device, surface);
  for (ANARIObject held :
      {(ANARIObject)surface, (ANARIObject)geometry, (ANARIObject)material})
    if (held)
      anariRetain(device, held);
  surfaces.push_back(
      {surface, geometry, geometrySubtype, material, materialSubtype, id});
  return surface;
}

void listLight(Scene &scene, ANARILight light, const std::string &subtype)
{
  if (light)
    scene.lightSubtypes.push_back({light, subtype});
}

std::string lightSubtype(const Scene &scene, ANARILight light)
{
  for (const SceneLight &listed : scene.lightSubtypes)
    if (listed.light == light)
      return listed.subtype;
  return {};
}

void releaseListedSurfaces(ANARIDevice device, Scene &scene)
{
  for (const SceneSurface &listed : scene.surfaces)
    for (ANARIObject held : {(ANARIObject)listed.surface,
             (ANARIObject)listed.geometry,
             (ANARIObject)listed.material})
      if (held)
        anariRelease(device, held);
  scene.surfaces.clear();
}

void releaseScene(ANARIDevice device, Scene &scene)
{
  releaseListedSurfaces(device, scene);
  scene.lightSubtypes.clear();
  for (ANARILight light : scene.lights)
    anariRelease(device, light);
  scene.lights.clear();
  if (scene.world)
    anariRelease(device, scene.world);
  scene.world = nullptr;
}

} // namespace prism::scenes
