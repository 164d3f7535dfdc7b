#include "DemoScenes.h"

#include "Objects.h"

#include <cctype>

namespace prism::scenes {

const std::vector<DemoScene> &demoScenes()
{
  static const std::vector<DemoScene> scenes = {
      {"cornell-box",
          "the Cornell box: red and green walls, two white boxes, a ceiling "
          "light",
          buildCornellBox},
      {"random-spheres",
          "hundreds of random matte, metal and glass spheres on a plane",
          buildRandomSpheres},
      {"material-ball",
          "a glTF-style physicallyBased ball with a procedural checker "
          "texture on a stand",
          buildMaterialBall},
      {"instanced-forest",
          "one tree group (cone trunk, cone canopy) instanced 4096 times",
          buildInstancedForest},
      {"furnished-room",
          "a living room lit by a ceiling panel and a floor lamp: sofa, "
          "tables, chairs, a bookshelf full of books, metal and glass",
          buildFurnishedRoom},
      {"volume",
          "soft blobs of a 128^3 structuredRegular field in a "
          "transferFunction1D volume (inferno map) over a ground plane",
          buildVolumeBlobs,
          volumeBlobsStyle,
          buildVolumeBlobsWithStyle},
  };
  return scenes;
}

const DemoScene *findDemoScene(const std::string &name)
{
  for (const DemoScene &scene : demoScenes())
    if (name == scene.name)
      return &scene;
  return nullptr;
}

ANARILight newLightIfSupported(ANARIDevice device,
    const char *subtype,
    Scene &scene,
    std::vector<ANARIObject> &lights)
{
  if (!hasSubtype(device, ANARI_LIGHT, subtype)) {
    std::string extension = subtype;
    for (char &c : extension)
      c = char(std::toupper((unsigned char)c));
    scene.notes.push_back(std::string("the device does not implement '")
                          + subtype + "' lights (KHR_LIGHT_" + extension
                          + "); the scene's lights are ignored");
    return nullptr;
  }
  ANARILight light = anariNewLight(device, subtype);
  lights.push_back(light);
  listLight(scene, light, subtype);
  return light;
}

void finishWorld(ANARIDevice device,
    Scene &scene,
    std::vector<ANARIObject> surfaces,
    std::vector<ANARIObject> instances,
    std::vector<ANARIObject> lights)
{
  ANARIWorld world = anariNewWorld(device);
  if (!surfaces.empty())
    setObjectArray(device, world, "surface", ANARI_SURFACE, surfaces);
  if (!instances.empty())
    setObjectArray(device, world, "instance", ANARI_INSTANCE, instances);
  if (!lights.empty())
    setObjectArray(device, world, "light", ANARI_LIGHT, lights);
  anariCommitParameters(device, world);
  for (auto *list : {&surfaces, &instances})
    for (ANARIObject object : *list)
      anariRelease(device, object);
  for (ANARIObject light : lights)
    scene.lights.push_back((ANARILight)light);
  scene.world = world;
}

} // namespace prism::scenes
