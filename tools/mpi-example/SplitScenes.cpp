#include "SplitScenes.h"

#include "BoxGrid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace prism::mpiexample {
namespace {

// Shared arrays over vectors this file keeps alive until the device
// releases them: the device copies nothing it does not have to.
template <typename T>
ANARIArray1D newArray(ANARIDevice device,
    ANARIDataType type,
    const std::vector<T> &values,
    size_t componentsPerElement)
{
  auto *copy = new std::vector<T>(values);
  return anariNewArray1D(
      device,
      copy->data(),
      [](const void *user, const void *) {
        delete static_cast<const std::vector<T> *>(user);
      },
      copy,
      type,
      values.size() / componentsPerElement);
}

void setArray(ANARIDevice device,
    ANARIObject object,
    const char *name,
    ANARIArray1D array)
{
  anariSetParameter(device, object, name, ANARI_ARRAY1D, &array);
  anariRelease(device, array);
}

ANARISurface newSurface(
    ANARIDevice device, ANARIGeometry geometry, ANARIMaterial material)
{
  ANARISurface surface = anariNewSurface(device);
  anariSetParameter(device, surface, "geometry", ANARI_GEOMETRY, &geometry);
  anariSetParameter(device, surface, "material", ANARI_MATERIAL, &material);
  anariCommitParameters(device, surface);
  anariRelease(device, geometry);
  anariRelease(device, material);
  return surface;
}

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
  std::vector<float> centers, colors;
  for (uint32_t i = 0; i < kSpheres; i++) {
    if (int(i % uint32_t(processes)) != process)
      continue;
    centers.insert(centers.end(),
        {8.f * hashed(i, 0) - 4.f,
            0.2f + 2.f * hashed(i, 1),
            8.f * hashed(i, 2) - 4.f});
    colors.insert(colors.end(),
        {0.2f + 0.8f * hashed(i, 3),
            0.2f + 0.8f * hashed(i, 4),
            0.2f + 0.8f * hashed(i, 5),
            1.f});
  }
  std::vector<ANARISurface> surfaces;
  if (!centers.empty()) {
    ANARIGeometry geometry = anariNewGeometry(device, "sphere");
    setArray(device,
        geometry,
        "vertex.position",
        newArray(device, ANARI_FLOAT32_VEC3, centers, 3));
    setArray(device,
        geometry,
        "vertex.color",
        newArray(device, ANARI_FLOAT32_VEC4, colors, 4));
    const float radius = 0.25f;
    anariSetParameter(device, geometry, "radius", ANARI_FLOAT32, &radius);
    anariCommitParameters(device, geometry);
    ANARIMaterial material = anariNewMaterial(device, "matte");
    anariSetParameter(device, material, "color", ANARI_STRING, "color");
    anariCommitParameters(device, material);
    surfaces.push_back(newSurface(device, geometry, material));
  }
  if (process == 0) { // the floor
    const std::vector<float> corners = {
        -6.f, 0.f, -6.f, 6.f, 0.f, -6.f, 6.f, 0.f, 6.f, -6.f, 0.f, 6.f};
    const std::vector<uint32_t> quads = {0, 3, 2, 1};
    ANARIGeometry geometry = anariNewGeometry(device, "quad");
    setArray(device,
        geometry,
        "vertex.position",
        newArray(device, ANARI_FLOAT32_VEC3, corners, 3));
    setArray(device,
        geometry,
        "primitive.index",
        newArray(device, ANARI_UINT32_VEC4, quads, 4));
    anariCommitParameters(device, geometry);
    ANARIMaterial material = anariNewMaterial(device, "matte");
    anariCommitParameters(device, material);
    surfaces.push_back(newSurface(device, geometry, material));
  }
  SplitScene scene;
  scene.world = anariNewWorld(device);
  if (!surfaces.empty()) {
    ANARIArray1D array = anariNewArray1D(device,
        surfaces.data(),
        nullptr,
        nullptr,
        ANARI_SURFACE,
        surfaces.size());
    setArray(device, scene.world, "surface", array);
    for (ANARISurface surface : surfaces)
      anariRelease(device, surface);
  }
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
  auto *copy = new std::vector<float>(std::move(samples));
  ANARIArray3D data = anariNewArray3D(
      device,
      copy->data(),
      [](const void *user, const void *) {
        delete static_cast<const std::vector<float> *>(user);
      },
      copy,
      ANARI_FLOAT32,
      kSide,
      kSide,
      uint64_t(layers));
  anariSetParameter(device, field, "data", ANARI_ARRAY3D, &data);
  anariRelease(device, data);
  const float spacing[3] = {
      4.f / float(cells), 4.f / float(cells), 4.f / float(cells)};
  const float origin[3] = {-2.f, -2.f, -2.f + spacing[2] * float(first)};
  anariSetParameter(device, field, "origin", ANARI_FLOAT32_VEC3, origin);
  anariSetParameter(device, field, "spacing", ANARI_FLOAT32_VEC3, spacing);
  anariCommitParameters(device, field);

  // The same transfer function on every process.
  const std::vector<float> colors = {
      0.1f, 0.1f, 0.6f, 0.2f, 0.8f, 0.6f, 1.f, 0.9f, 0.2f, 1.f, 0.3f, 0.1f};
  const std::vector<float> opacities = {0.f, 0.3f, 0.7f, 1.f};
  ANARIVolume volume = anariNewVolume(device, "transferFunction1D");
  anariSetParameter(device, volume, "value", ANARI_SPATIAL_FIELD, &field);
  anariRelease(device, field);
  setArray(
      device, volume, "color", newArray(device, ANARI_FLOAT32_VEC3, colors, 3));
  setArray(
      device, volume, "opacity", newArray(device, ANARI_FLOAT32, opacities, 1));
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
