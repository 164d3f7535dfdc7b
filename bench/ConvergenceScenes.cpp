#include "ConvergenceScenes.h"

#include "DemoScenes.h"
#include "Environment.h"
#include "GltfLoader.h"
#include "Meshes.h"
#include "Objects.h"

#include <cstdint>

namespace prism::bench {
namespace {

using scenes::Vec3;
using scenes::operator*;

// Emissive triangles of the many-light hall: 4 colours of this many.
constexpr int kTrianglesPerColour = 272;

ANARIMaterial newEmitter(ANARIDevice device, const Vec3 &radiance)
{
  ANARIMaterial material = anariNewMaterial(device, "physicallyBased");
  scenes::setVec3(device, material, "baseColor", {0.f, 0.f, 0.f});
  scenes::setVec3(device, material, "emissive", radiance);
  anariCommitParameters(device, material);
  return material;
}

void addSurface(ANARIDevice device,
    std::vector<ANARIObject> &surfaces,
    const scenes::TriangleMesh &mesh,
    ANARIMaterial material)
{
  ANARIGeometry geometry = scenes::newTriangleGeometry(device, mesh);
  surfaces.push_back(scenes::newSurface(device, geometry, material));
  anariRelease(device, geometry);
  anariRelease(device, material);
}

// A room [-1, 1] x [0, 2] x [1 - depth, 1] open towards +z (white floor,
// ceiling and back wall, red left and green right wall) with two white
// blocks, and the camera looking in.
scenes::Scene room(
    ANARIDevice device, std::vector<ANARIObject> &surfaces, float depth)
{
  scenes::TriangleMesh white, red, green;
  const float back = 1.f - depth;
  white.addQuad({-1, 0, 1}, {2, 0, 0}, {0, 0, -depth});   // floor
  white.addQuad({-1, 2, back}, {2, 0, 0}, {0, 0, depth}); // ceiling
  white.addQuad({-1, 0, back}, {2, 0, 0}, {0, 2, 0});     // back
  red.addQuad({-1, 0, 1}, {0, 0, -depth}, {0, 2, 0});     // left
  green.addQuad({1, 0, back}, {0, 0, depth}, {0, 2, 0});  // right
  white.addBox(scenes::translationMatrix({-0.35f, 0.6f, -0.3f})
               * scenes::rotationYMatrix(0.3f)
               * scenes::scaleMatrix({0.6f, 1.2f, 0.6f}));
  white.addBox(scenes::translationMatrix({0.4f, 0.3f, 0.3f})
               * scenes::rotationYMatrix(-0.3f)
               * scenes::scaleMatrix({0.6f, 0.6f, 0.6f}));
  addSurface(
      device, surfaces, white, scenes::newMatte(device, {.73f, .73f, .73f}));
  addSurface(
      device, surfaces, red, scenes::newMatte(device, {.65f, .05f, .05f}));
  addSurface(
      device, surfaces, green, scenes::newMatte(device, {.12f, .45f, .15f}));
  scenes::Scene scene;
  scene.camera.valid = true;
  scene.camera.eye = {0.f, 1.f, 3.4f};
  scene.camera.at = {0.f, 1.f, 0.f};
  scene.camera.fovyDegrees = 40.f;
  return scene;
}

scenes::Scene emissivePanelRoom(ANARIDevice device)
{
  std::vector<ANARIObject> surfaces;
  scenes::Scene scene = room(device, surfaces, 2.f);
  scenes::TriangleMesh panel;
  panel.addQuad({-0.25f, 1.999f, -0.25f}, {0.5f, 0, 0}, {0, 0, 0.5f});
  addSurface(device, surfaces, panel, newEmitter(device, {12.f, 10.2f, 7.2f}));
  scenes::finishWorld(device, scene, surfaces, {}, {});
  return scene;
}

// A deterministic number in [0, 1) from `state` (a 32-bit LCG).
float nextUniform(uint32_t &state)
{
  state = state * 1664525u + 1013904223u;
  return float(state >> 8) * (1.f / 16777216.f);
}

// Triangles scattered over the ceiling and the upper half of the side walls
// of a room of `depth` (as room()), 1 mm in front of them.
scenes::TriangleMesh scatteredTriangles(uint32_t &state, int count, float depth)
{
  scenes::TriangleMesh mesh;
  const float size = 0.1f;
  for (int i = 0; i < count; i++) {
    const float a = 2.f * nextUniform(state) - 1.f;
    const float z = 0.9f - (depth - 0.2f) * nextUniform(state);
    Vec3 corner, edge1, edge2;
    switch (int(nextUniform(state) * 3.f)) {
    case 0: // ceiling
      corner = {a * 0.9f, 1.999f, z};
      edge1 = {size, 0, 0}, edge2 = {0, 0, -size};
      break;
    case 1: // left wall
      corner = {-0.999f, 1.45f + 0.45f * a, z};
      edge1 = {0, size, 0}, edge2 = {0, 0, -size};
      break;
    default: // right wall
      corner = {0.999f, 1.45f + 0.45f * a, z};
      edge1 = {0, 0, -size}, edge2 = {0, size, 0};
    }
    const auto first = uint32_t(mesh.positions.size());
    mesh.positions.push_back(corner);
    mesh.positions.push_back(
        {corner[0] + edge1[0], corner[1] + edge1[1], corner[2] + edge1[2]});
    mesh.positions.push_back(
        {corner[0] + edge2[0], corner[1] + edge2[1], corner[2] + edge2[2]});
    const Vec3 normal = scenes::normalize(scenes::cross(edge1, edge2));
    mesh.normals.insert(mesh.normals.end(), 3, normal);
    mesh.triangles.push_back({first, first + 1, first + 2});
  }
  return mesh;
}

scenes::Scene manyLightRoom(ANARIDevice device)
{
  std::vector<ANARIObject> surfaces;
  const float depth = 16.f; // a hall: most emitters are far from most points
  scenes::Scene scene = room(device, surfaces, depth);
  const Vec3 colours[] = {
      {2.f, .4f, .2f}, {.3f, 1.8f, .4f}, {.3f, .5f, 2.2f}, {1.5f, 1.5f, 1.2f}};
  uint32_t state = 12345u;
  for (const Vec3 &radiance : colours)
    addSurface(device,
        surfaces,
        scatteredTriangles(state, kTrianglesPerColour, depth),
        newEmitter(device, radiance));
  scenes::finishWorld(device, scene, surfaces, {}, {});
  return scene;
}

scenes::Scene skyLitModel(ANARIDevice device, std::string &error)
{
  const std::string root = PRISM_SOURCE_DIR;
  scene_io::LoadResult loaded = scene_io::loadGltf(
      device, root + "/tests/cli/data/lightless-box.gltf", {});
  if (!loaded.ok()) {
    error = loaded.error;
    return {};
  }
  scene_io::EnvironmentChoice sky;
  sky.source = root + "/bench/data/sun-sky.hdr";
  sky.given = true;
  scene_io::Environment environment =
      scene_io::makeEnvironment(device, sky, {0.f, 1.f, 0.f});
  if (!environment.error.empty()) {
    error = environment.error;
    scenes::releaseScene(device, loaded.scene);
    return {};
  }
  scene_io::addWorldLight(device, loaded.scene, environment.light);
  scenes::Scene scene = std::move(loaded.scene);
  if (!scene.bounds.empty()) {
    // Close enough that the model fills most of the frame (the sky seen
    // directly has no noise to measure), a little from above.
    const scenes::Bounds &b = scene.bounds;
    const Vec3 centre{0.5f * (b.lower[0] + b.upper[0]),
        0.5f * (b.lower[1] + b.upper[1]),
        0.5f * (b.lower[2] + b.upper[2])};
    const float size = scenes::length(scenes::Vec3{b.upper[0] - b.lower[0],
        b.upper[1] - b.lower[1],
        b.upper[2] - b.lower[2]});
    scene.camera = {};
    scene.camera.valid = true;
    scene.camera.at = centre;
    scene.camera.eye = {centre[0] + 0.6f * size,
        centre[1] + 0.45f * size,
        centre[2] + 1.f * size};
  }
  return scene;
}

} // namespace

const std::vector<std::string> &convergenceSceneNames()
{
  static const std::vector<std::string> names = {
      "cornell-box", "emissive-panel", "many-lights", "sky-gltf"};
  return names;
}

scenes::Scene buildConvergenceScene(
    ANARIDevice device, const std::string &name, std::string &error)
{
  if (name == "cornell-box")
    return scenes::findDemoScene("cornell-box")->build(device);
  if (name == "emissive-panel")
    return emissivePanelRoom(device);
  if (name == "many-lights")
    return manyLightRoom(device);
  if (name == "sky-gltf")
    return skyLitModel(device, error);
  error = "unknown scene " + name;
  return {};
}

} // namespace prism::bench
