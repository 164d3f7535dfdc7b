#include "SplitScenes.h"

#include "BoxGrid.h"
#include "Objects.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace prism::mpiexample {
namespace {

// A deterministic number in [0, 1) for sphere i and component k: every
// process computes the same scene and keeps its share.
float hashed(uint32_t i, uint32_t k)
{
  uint32_t x = i * 0x9e3779b9u ^ (k + 1u) * 0x85ebca6bu;
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return float(x >> 8) * (1.f / 16777216.f);
}

SplitScene spheres(ANARIDevice device, int process, int processes)
{
  constexpr uint32_t kSpheres = 300;
  std::vector<scenes::Vec3> centers;
  std::vector<scenes::Vec4> colors;
  for (uint32_t i = 0; i < kSpheres; i++) {
    if (int(i % uint32_t(processes)) != process)
      continue;
    centers.push_back({8.f * hashed(i, 0) - 4.f,
        0.2f + 2.f * hashed(i, 1),
        8.f * hashed(i, 2) - 4.f});
    colors.push_back({0.2f + 0.8f * hashed(i, 3),
        0.2f + 0.8f * hashed(i, 4),
        0.2f + 0.8f * hashed(i, 5),
        1.f});
  }
  std::vector<ANARIObject> surfaces;
  auto addSurface = [&](ANARIGeometry geometry, ANARIMaterial material) {
    anariCommitParameters(device, geometry);
    anariCommitParameters(device, material);
    surfaces.push_back(scenes::newSurface(device, geometry, material));
    anariRelease(device, geometry);
    anariRelease(device, material);
  };
  if (!centers.empty()) {
    ANARIGeometry geometry = anariNewGeometry(device, "sphere");
    scenes::setArray(
        device, geometry, "vertex.position", ANARI_FLOAT32_VEC3, centers);
    scenes::setArray(
        device, geometry, "vertex.color", ANARI_FLOAT32_VEC4, colors);
    scenes::setFloat(device, geometry, "radius", 0.25f);
    ANARIMaterial material = anariNewMaterial(device, "matte");
    scenes::setString(device, material, "color", "color");
    addSurface(geometry, material);
  }
  if (process == 0) { // the floor
    const std::vector<scenes::Vec3> corners = {
        {-6.f, 0.f, -6.f}, {6.f, 0.f, -6.f}, {6.f, 0.f, 6.f}, {-6.f, 0.f, 6.f}};
    const std::vector<std::array<uint32_t, 4>> quads = {{0, 3, 2, 1}};
    ANARIGeometry geometry = anariNewGeometry(device, "quad");
    scenes::setArray(
        device, geometry, "vertex.position", ANARI_FLOAT32_VEC3, corners);
    scenes::setArray(
        device, geometry, "primitive.index", ANARI_UINT32_VEC4, quads);
    addSurface(geometry, anariNewMaterial(device, "matte"));
  }
  SplitScene scene;
  scene.world = anariNewWorld(device);
  if (!surfaces.empty())
    scenes::setObjectArray(
        device, scene.world, "surface", ANARI_SURFACE, surfaces);
  for (ANARIObject surface : surfaces)
    anariRelease(device, surface);
  scenes::addSunlight(device, scene.world);
  scene.eye[0] = 6.f;
  scene.eye[1] = 6.f;
  scene.eye[2] = 8.f;
  return scene;
}

SplitScene volume(ANARIDevice device, int process, int processes)
{
  // Slabs of the 64 z-layers of samples: process p holds layers
  // [first, last], the last shared with the next slab.
  constexpr int kSide = 64;
  const int cells = kSide - 1;
  const int first = cells * process / processes;
  const int last = cells * (process + 1) / processes;
  const int layers = last - first + 1;
  std::vector<float> samples(size_t(kSide) * kSide * size_t(layers));
  const float blobs[3][4] = {{0.35f, 0.4f, 0.3f, 0.12f},
      {0.65f, 0.55f, 0.6f, 0.15f},
      {0.45f, 0.6f, 0.75f, 0.1f}};
  for (int z = 0; z < layers; z++)
    for (int y = 0; y < kSide; y++)
      for (int x = 0; x < kSide; x++) {
        const float p[3] = {
            float(x) / cells, float(y) / cells, float(first + z) / cells};
        float value = 0.f;
        for (const auto &blob : blobs) {
          const float dx = p[0] - blob[0], dy = p[1] - blob[1],
                      dz = p[2] - blob[2];
          value += std::exp(
              -(dx * dx + dy * dy + dz * dz) / (2.f * blob[3] * blob[3]));
        }
        samples[(size_t(z) * kSide + y) * kSide + x] = value;
      }
  ANARISpatialField field = anariNewSpatialField(device, "structuredRegular");
  ANARIArray3D data = scenes::newArray3D(device,
      ANARI_FLOAT32,
      samples.data(),
      kSide,
      kSide,
      uint64_t(layers),
      sizeof(float));
  anariSetParameter(device, field, "data", ANARI_ARRAY3D, &data);
  anariRelease(device, data);
  const float spacing[3] = {
      4.f / float(cells), 4.f / float(cells), 4.f / float(cells)};
  const float origin[3] = {-2.f, -2.f, -2.f + spacing[2] * float(first)};
  anariSetParameter(device, field, "origin", ANARI_FLOAT32_VEC3, origin);
  anariSetParameter(device, field, "spacing", ANARI_FLOAT32_VEC3, spacing);
  anariCommitParameters(device, field);

  // The same transfer function on every process.
  const std::vector<scenes::Vec3> colors = {{0.1f, 0.1f, 0.6f},
      {0.2f, 0.8f, 0.6f},
      {1.f, 0.9f, 0.2f},
      {1.f, 0.3f, 0.1f}};
  const std::vector<float> opacities = {0.f, 0.3f, 0.7f, 1.f};
  ANARIVolume volume = anariNewVolume(device, "transferFunction1D");
  anariSetParameter(device, volume, "value", ANARI_SPATIAL_FIELD, &field);
  anariRelease(device, field);
  scenes::setArray(device, volume, "color", ANARI_FLOAT32_VEC3, colors);
  scenes::setArray(device, volume, "opacity", ANARI_FLOAT32, opacities);
  const float range[2] = {0.1f, 1.f};
  anariSetParameter(device, volume, "valueRange", ANARI_FLOAT32_BOX1, range);
  const float unitDistance = 0.2f;
  anariSetParameter(
      device, volume, "unitDistance", ANARI_FLOAT32, &unitDistance);
  anariCommitParameters(device, volume);

  SplitScene scene;
  scene.world = anariNewWorld(device);
  scenes::setWorldObjects(device, scene.world, "volume", ANARI_VOLUME, volume);
  anariRelease(device, volume);
  scene.eye[0] = 3.f;
  scene.eye[1] = 2.f;
  scene.eye[2] = 6.f;
  scene.renderer = "raycast";
  return scene;
}

} // namespace

SplitScene buildSplitScene(
    ANARIDevice device, const std::string &name, int process, int processes)
{
  if (name == "boxes") {
    SplitScene scene;
    scene.world = scenes::newBoxesWorld(
        device, scenes::boxesOf(scenes::boxOwners(processes, 7), process));
    scenes::addSunlight(device, scene.world);
    scene.eye[0] = 4.f;
    scene.eye[1] = 5.f;
    scene.eye[2] = 9.f;
    return scene;
  }
  if (name == "spheres")
    return spheres(device, process, processes);
  if (name == "volume")
    return volume(device, process, processes);
  return {};
}

} // namespace prism::mpiexample
