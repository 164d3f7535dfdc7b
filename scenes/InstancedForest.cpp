// An instanced forest: one tree group (a cone trunk under three stacked cone
// canopies) placed 4096 times by one `transform` instance with an array of
// matrices (KHR_INSTANCE_TRANSFORM_ARRAY), or by one instance per tree on
// devices without transform arrays.
#include "DemoScenes.h"
#include "Meshes.h"
#include "Objects.h"

#include <numbers>

namespace prism::scenes {
namespace {

constexpr int kTreesPerSide = 64;
constexpr float kForestHalfWidth = 30.f;

// A committed cone geometry of segments (bottom[i], top[i]) with radii.
ANARIGeometry newCones(ANARIDevice device,
    const std::vector<Vec3> &positions,
    const std::vector<float> &radii)
{
  ANARIGeometry geometry = anariNewGeometry(device, "cone");
  setArray(device, geometry, "vertex.position", ANARI_FLOAT32_VEC3, positions);
  setArray(device, geometry, "vertex.radius", ANARI_FLOAT32, radii);
  setString(device, geometry, "caps", "first");
  anariCommitParameters(device, geometry);
  return geometry;
}

// The tree in object space: base at the origin, up +y, 1.8 units tall.
ANARIGroup newTree(ANARIDevice device, Bounds &bounds)
{
  ANARIGeometry trunk =
      newCones(device, {{0.f, 0.f, 0.f}, {0.f, 0.6f, 0.f}}, {0.09f, 0.05f});
  const std::vector<Vec3> canopyPositions = {{0.f, 0.4f, 0.f},
      {0.f, 1.2f, 0.f},
      {0.f, 0.8f, 0.f},
      {0.f, 1.5f, 0.f},
      {0.f, 1.15f, 0.f},
      {0.f, 1.8f, 0.f}};
  ANARIGeometry canopy =
      newCones(device, canopyPositions, {0.55f, 0.f, 0.42f, 0.f, 0.3f, 0.f});
  bounds.extend(Vec3{-0.55f, 0.f, -0.55f});
  bounds.extend(Vec3{0.55f, 1.8f, 0.55f});

  ANARIMaterial bark = newMatte(device, {0.3f, 0.18f, 0.08f});
  ANARIMaterial needles = newMatte(device, {0.1f, 0.35f, 0.12f});
  std::vector<ANARIObject> surfaces = {
      newSurface(device, trunk, bark), newSurface(device, canopy, needles)};
  ANARIGroup group = anariNewGroup(device);
  setObjectArray(device, group, "surface", ANARI_SURFACE, surfaces);
  anariCommitParameters(device, group);
  for (ANARIObject o : surfaces)
    anariRelease(device, o);
  for (ANARIObject o : {(ANARIObject)trunk,
           (ANARIObject)canopy,
           (ANARIObject)bark,
           (ANARIObject)needles})
    anariRelease(device, o);
  return group;
}

} // namespace

Scene buildInstancedForest(ANARIDevice device)
{
  Scene scene;
  scene.name = "instanced-forest";
  scene.description = "an instanced forest";
  scene.camera.valid = true;
  scene.camera.eye = {42.f, 24.f, 42.f};
  scene.camera.at = {0.f, -3.f, 0.f};
  scene.camera.fovyDegrees = 40.f;
  scene.hasBackground = true;
  scene.background = {0.62f, 0.75f, 0.9f, 1.f};

  Bounds treeBounds;
  ANARIGroup tree = newTree(device, treeBounds);
  // A jittered grid keeps trees from overlapping while looking natural.
  std::vector<Mat4> placements;
  Random random(7);
  const float spacing = 2.f * kForestHalfWidth / float(kTreesPerSide);
  for (int i = 0; i < kTreesPerSide; i++) {
    for (int j = 0; j < kTreesPerSide; j++) {
      const Vec3 position{
          -kForestHalfWidth + spacing * (float(i) + random.uniform(0.2f, 0.8f)),
          0.f,
          -kForestHalfWidth
              + spacing * (float(j) + random.uniform(0.2f, 0.8f))};
      const float angle = random.uniform(0.f, 2.f * std::numbers::pi_v<float>);
      const float size = random.uniform(0.6f, 1.4f);
      const Mat4 m = translationMatrix(position) * rotationYMatrix(angle)
                     * scaleMatrix({size, size, size});
      placements.push_back(m);
      scene.bounds.extend(transformPoint(m, treeBounds.lower));
      scene.bounds.extend(transformPoint(m, treeBounds.upper));
    }
  }

  std::vector<ANARIObject> instances;
  if (hasExtension(device, "ANARI_KHR_INSTANCE_TRANSFORM_ARRAY")) {
    ANARIInstance instance = anariNewInstance(device, "transform");
    setObject(device, instance, "group", ANARI_GROUP, tree);
    setArray(device, instance, "transform", ANARI_FLOAT32_MAT4, placements);
    anariCommitParameters(device, instance);
    instances.push_back(instance);
  } else {
    scene.notes.push_back(
        "the device has no transform arrays "
        "(KHR_INSTANCE_TRANSFORM_ARRAY); one instance per tree instead");
    for (const Mat4 &m : placements) {
      ANARIInstance instance = anariNewInstance(device, "transform");
      setObject(device, instance, "group", ANARI_GROUP, tree);
      anariSetParameter(
          device, instance, "transform", ANARI_FLOAT32_MAT4, m.data());
      anariCommitParameters(device, instance);
      instances.push_back(instance);
    }
  }
  anariRelease(device, tree);

  TriangleMesh ground;
  const float half = kForestHalfWidth + 2.f;
  ground.addQuad(
      {-half, 0.f, half}, {2.f * half, 0.f, 0.f}, {0.f, 0.f, -2.f * half});
  scene.bounds.extend(ground.bounds());
  ANARIGeometry groundGeometry = newTriangleGeometry(device, ground);
  ANARIMaterial soil = newMatte(device, {0.33f, 0.28f, 0.18f});
  std::vector<ANARIObject> surfaces = {
      newSurface(device, groundGeometry, soil)};
  anariRelease(device, groundGeometry);
  anariRelease(device, soil);

  std::vector<ANARIObject> lights;
  if (ANARILight sun =
          newLightIfSupported(device, "directional", scene, lights)) {
    setVec3(device, sun, "direction", normalize({-0.4f, -1.f, -0.3f}));
    setFloat(device, sun, "irradiance", 3.f);
    anariCommitParameters(device, sun);
  }
  finishWorld(device, scene, surfaces, instances, lights);
  return scene;
}

} // namespace prism::scenes
