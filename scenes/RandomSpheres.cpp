// Random spheres: a jittered grid of small matte, metal and glass spheres
// around three large ones, on a ground plane. Seeded, so every run and every
// platform builds the same scene.
#include "DemoScenes.h"
#include "Meshes.h"
#include "Objects.h"

namespace prism::scenes {
namespace {

// One sphere geometry per material class; per-sphere color (vertex.color)
// and roughness (vertex.attribute0) drive the material through attributes.
struct SphereSet
{
  std::vector<Vec3> centers;
  std::vector<float> radii;
  std::vector<Vec3> colors;
  std::vector<float> roughness;

  void add(const Vec3 &center, float radius, const Vec3 &color, float rough)
  {
    centers.push_back(center);
    radii.push_back(radius);
    colors.push_back(color);
    roughness.push_back(rough);
  }
};

ANARIGeometry newSpheres(ANARIDevice device, const SphereSet &set)
{
  ANARIGeometry geometry = anariNewGeometry(device, "sphere");
  setArray(
      device, geometry, "vertex.position", ANARI_FLOAT32_VEC3, set.centers);
  setArray(device, geometry, "vertex.radius", ANARI_FLOAT32, set.radii);
  setArray(device, geometry, "vertex.color", ANARI_FLOAT32_VEC3, set.colors);
  setArray(device, geometry, "vertex.attribute0", ANARI_FLOAT32, set.roughness);
  anariCommitParameters(device, geometry);
  return geometry;
}

} // namespace

Scene buildRandomSpheres(ANARIDevice device)
{
  Scene scene;
  scene.name = "random-spheres";
  scene.description = "random spheres";
  scene.camera.valid = true;
  scene.camera.eye = {13.f, 2.2f, 4.5f};
  scene.camera.at = {0.f, 0.f, 0.f};
  scene.camera.fovyDegrees = 24.f;
  scene.hasBackground = true;
  scene.background = {0.5f, 0.7f, 1.f, 1.f};

  SphereSet matte, metal, glass;
  matte.add({-4.f, 1.f, 0.f}, 1.f, {0.4f, 0.2f, 0.1f}, 1.f);
  glass.add({0.f, 1.f, 0.f}, 1.f, {1.f, 1.f, 1.f}, 0.f);
  metal.add({4.f, 1.f, 0.f}, 1.f, {0.7f, 0.6f, 0.5f}, 0.05f);
  Random random(20240601);
  for (int a = -9; a < 9; a++) {
    for (int b = -9; b < 9; b++) {
      const float choice = random.uniform();
      const Vec3 center{float(a) + 0.9f * random.uniform(),
          0.2f,
          float(b) + 0.9f * random.uniform()};
      // Keep clear of the large spheres.
      bool clear = true;
      for (float x : {-4.f, 0.f, 4.f})
        clear = clear && length(center - Vec3{x, 0.2f, 0.f}) > 1.3f;
      if (!clear)
        continue;
      if (choice < 0.7f) {
        const Vec3 c{random.uniform() * random.uniform(),
            random.uniform() * random.uniform(),
            random.uniform() * random.uniform()};
        matte.add(center, 0.2f, c, 1.f);
      } else if (choice < 0.9f) {
        const Vec3 c{random.uniform(0.5f, 1.f),
            random.uniform(0.5f, 1.f),
            random.uniform(0.5f, 1.f)};
        metal.add(center, 0.2f, c, random.uniform(0.f, 0.5f));
      } else {
        glass.add(center, 0.2f, {1.f, 1.f, 1.f}, 0.f);
      }
    }
  }

  TriangleMesh ground;
  ground.addQuad({-12.f, 0.f, 12.f}, {24.f, 0.f, 0.f}, {0.f, 0.f, -24.f});
  scene.bounds = ground.bounds();
  for (const SphereSet *set : {&matte, &metal, &glass})
    for (size_t i = 0; i < set->centers.size(); i++) {
      const float r = set->radii[i];
      scene.bounds.extend(set->centers[i] - Vec3{r, r, r});
      scene.bounds.extend(set->centers[i] + Vec3{r, r, r});
    }

  ANARIMaterial groundMaterial = newMatte(device, {0.5f, 0.5f, 0.5f});
  ANARIMaterial matteMaterial = anariNewMaterial(device, "matte");
  setString(device, matteMaterial, "color", "color");
  anariCommitParameters(device, matteMaterial);
  ANARIMaterial metalMaterial = anariNewMaterial(device, "physicallyBased");
  setString(device, metalMaterial, "baseColor", "color");
  setFloat(device, metalMaterial, "metallic", 1.f);
  setString(device, metalMaterial, "roughness", "attribute0");
  anariCommitParameters(device, metalMaterial);
  ANARIMaterial glassMaterial = anariNewMaterial(device, "physicallyBased");
  setVec3(device, glassMaterial, "baseColor", {1.f, 1.f, 1.f});
  setFloat(device, glassMaterial, "metallic", 0.f);
  setFloat(device, glassMaterial, "roughness", 0.f);
  setFloat(device, glassMaterial, "transmission", 1.f);
  setFloat(device, glassMaterial, "ior", 1.5f);
  anariCommitParameters(device, glassMaterial);

  std::vector<ANARIObject> surfaces;
  ANARIGeometry groundGeometry = newTriangleGeometry(device, ground);
  uint32_t id = 0;
  surfaces.push_back(newListedSurface(device,
      scene.surfaces,
      groundGeometry,
      "triangle",
      groundMaterial,
      "matte",
      id++));
  anariRelease(device, groundGeometry);
  struct SphereSurface
  {
    const SphereSet *set;
    ANARIMaterial material;
    const char *materialSubtype;
  };
  const SphereSurface sets[] = {{&matte, matteMaterial, "matte"},
      {&metal, metalMaterial, "physicallyBased"},
      {&glass, glassMaterial, "physicallyBased"}};
  for (const SphereSurface &s : sets) {
    ANARIGeometry geometry = newSpheres(device, *s.set);
    surfaces.push_back(newListedSurface(device,
        scene.surfaces,
        geometry,
        "sphere",
        s.material,
        s.materialSubtype,
        id++));
    anariRelease(device, geometry);
  }
  for (ANARIMaterial m :
      {groundMaterial, matteMaterial, metalMaterial, glassMaterial})
    anariRelease(device, m);

  std::vector<ANARIObject> lights;
  if (ANARILight sun =
          newLightIfSupported(device, "directional", scene, lights)) {
    setVec3(device, sun, "direction", normalize({-1.f, -2.f, -0.5f}));
    setFloat(device, sun, "irradiance", 3.f);
    anariCommitParameters(device, sun);
  }
  finishWorld(device, scene, surfaces, {}, lights);
  return scene;
}

} // namespace prism::scenes
