// The data-parallel paper's test scene: a grid of boxes (4x4x4 unless
// asked), each owned by one process of a random but reproducible
// interleaving, built through the public C API only (so the same code
// drives prism and prism_mpi). Header-only: the MPI tests and benchmark use
// it without the scenes library.
#pragma once

#include <anari/anari.h>
#include <anari/frontend/type_utility.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace prism::scenes {

constexpr int kBoxesPerSide = 4;

// Which of `processes` owns each of the side^3 boxes: a shuffle seeded by
// `seed`, dealt out in turn, so every process holds a scattered, near-equal
// share.
inline std::vector<int> boxOwners(
    int processes, uint32_t seed, int side = kBoxesPerSide)
{
  const int kBoxCount = side * side * side;
  std::vector<int> order(kBoxCount);
  for (int i = 0; i < kBoxCount; i++)
    order[i] = i;
  uint32_t state = seed * 747796405u + 2891336453u;
  for (int i = kBoxCount - 1; i > 0; i--) {
    state = state * 1664525u + 1013904223u;
    std::swap(order[i], order[(state >> 8) % uint32_t(i + 1)]);
  }
  std::vector<int> owner(kBoxCount);
  for (int i = 0; i < kBoxCount; i++)
    owner[order[i]] = i % processes;
  return owner;
}

// The boxes `process` owns (every box when `process` is negative).
inline std::vector<int> boxesOf(const std::vector<int> &owners, int process)
{
  std::vector<int> boxes;
  for (int i = 0; i < int(owners.size()); i++) {
    if (process < 0 || owners[i] == process)
      boxes.push_back(i);
  }
  return boxes;
}

// Sets `world`'s array parameter `name` to the one `object` and commits.
inline void setWorldObjects(ANARIDevice device,
    ANARIWorld world,
    const char *name,
    ANARIDataType type,
    ANARIObject object)
{
  ANARIArray1D array =
      anariNewArray1D(device, &object, nullptr, nullptr, type, 1);
  anariSetParameter(device, world, name, ANARI_ARRAY1D, &array);
  anariCommitParameters(device, world);
  anariRelease(device, array);
}

// One triangle geometry holding `boxes` of a side^3 grid (unit spacing,
// centered on x = `offsetX`, y = z = 0), each with its own color (a
// primitive attribute), in a surface with a matte material reading it.
inline ANARIWorld newBoxesWorld(ANARIDevice device,
    const std::vector<int> &boxes,
    int side = kBoxesPerSide,
    float offsetX = 0.f)
{
  std::vector<float> positions;
  std::vector<uint32_t> indices;
  std::vector<float> colors;
  const int faces[6][4] = {{0, 2, 3, 1},
      {4, 5, 7, 6},
      {0, 1, 5, 4},
      {2, 6, 7, 3},
      {0, 4, 6, 2},
      {1, 3, 7, 5}};
  for (int box : boxes) {
    const int gx = box % side, gy = (box / side) % side,
              gz = box / (side * side);
    const float middle = float(side - 1) / 2.f;
    const float center[3] = {offsetX + (gx - middle), gy - middle, gz - middle};
    const float half = 0.3f;
    const uint32_t first = uint32_t(positions.size() / 3);
    for (int corner = 0; corner < 8; corner++) {
      positions.push_back(center[0] + (corner & 1 ? half : -half));
      positions.push_back(center[1] + (corner & 2 ? half : -half));
      positions.push_back(center[2] + (corner & 4 ? half : -half));
    }
    const float last = float(std::max(side - 1, 1));
    const float color[4] = {0.2f + 0.8f * float(gx) / last,
        0.2f + 0.8f * float(gy) / last,
        0.2f + 0.8f * float(gz) / last,
        1.f};
    for (const auto &face : faces) {
      const uint32_t quad[6] = {0, 1, 2, 0, 2, 3};
      for (uint32_t corner : quad)
        indices.push_back(first + uint32_t(face[corner]));
      for (int triangle = 0; triangle < 2; triangle++)
        colors.insert(colors.end(), color, color + 4);
    }
  }
  ANARIWorld world = anariNewWorld(device);
  if (boxes.empty()) {
    anariCommitParameters(device, world);
    return world;
  }
  ANARIGeometry geometry = anariNewGeometry(device, "triangle");
  auto setArray = [&](const char *name,
                      ANARIDataType type,
                      const void *data,
                      uint64_t count) {
    ANARIArray1D array =
        anariNewArray1D(device, nullptr, nullptr, nullptr, type, count);
    void *mapped = anariMapArray(device, array);
    std::memcpy(mapped, data, count * anari::sizeOf(type));
    anariUnmapArray(device, array);
    anariSetParameter(device, geometry, name, ANARI_ARRAY1D, &array);
    anariRelease(device, array);
  };
  setArray("vertex.position",
      ANARI_FLOAT32_VEC3,
      positions.data(),
      positions.size() / 3);
  setArray(
      "primitive.index", ANARI_UINT32_VEC3, indices.data(), indices.size() / 3);
  setArray(
      "primitive.color", ANARI_FLOAT32_VEC4, colors.data(), colors.size() / 4);
  anariCommitParameters(device, geometry);

  ANARIMaterial material = anariNewMaterial(device, "matte");
  anariSetParameter(device, material, "color", ANARI_STRING, "color");
  anariCommitParameters(device, material);
  ANARISurface surface = anariNewSurface(device);
  anariSetParameter(device, surface, "geometry", ANARI_GEOMETRY, &geometry);
  anariSetParameter(device, surface, "material", ANARI_MATERIAL, &material);
  anariCommitParameters(device, surface);
  setWorldObjects(device, world, "surface", ANARI_SURFACE, surface);
  anariRelease(device, surface);
  anariRelease(device, material);
  anariRelease(device, geometry);
  return world;
}

// Where addSunlight's light shines unless asked otherwise.
constexpr float kSunDirection[3] = {-0.3f, -1.f, -0.5f};

// A directional light from above for `world`, so boxes shadow the ones
// below them; commits the world.
inline void addSunlight(ANARIDevice device,
    ANARIWorld world,
    const float *direction = kSunDirection)
{
  ANARILight light = anariNewLight(device, "directional");
  anariSetParameter(device, light, "direction", ANARI_FLOAT32_VEC3, direction);
  anariCommitParameters(device, light);
  setWorldObjects(device, world, "light", ANARI_LIGHT, light);
  anariRelease(device, light);
}

// A camera looking at the grid's center from `eye`.
inline ANARICamera newCamera(
    ANARIDevice device, const float eye[3], float aspect)
{
  ANARICamera camera = anariNewCamera(device, "perspective");
  const float length =
      std::sqrt(eye[0] * eye[0] + eye[1] * eye[1] + eye[2] * eye[2]);
  const float direction[3] = {
      -eye[0] / length, -eye[1] / length, -eye[2] / length};
  const float up[3] = {0.f, 1.f, 0.f};
  anariSetParameter(device, camera, "position", ANARI_FLOAT32_VEC3, eye);
  anariSetParameter(device, camera, "direction", ANARI_FLOAT32_VEC3, direction);
  anariSetParameter(device, camera, "up", ANARI_FLOAT32_VEC3, up);
  anariSetParameter(device, camera, "aspect", ANARI_FLOAT32, &aspect);
  anariCommitParameters(device, camera);
  return camera;
}

// A renderer of `subtype` with an opaque, non-black background.
inline ANARIRenderer newRenderer(ANARIDevice device, const char *subtype)
{
  ANARIRenderer renderer = anariNewRenderer(device, subtype);
  const float background[4] = {0.1f, 0.2f, 0.3f, 1.f};
  anariSetParameter(
      device, renderer, "background", ANARI_FLOAT32_VEC4, background);
  anariCommitParameters(device, renderer);
  return renderer;
}

// A frame of these objects with FLOAT32_VEC4 color, FLOAT32 depth and
// FLOAT32_VEC3 normal and albedo.
inline ANARIFrame newFrame(ANARIDevice device,
    ANARIWorld world,
    ANARICamera camera,
    ANARIRenderer renderer,
    uint32_t width,
    uint32_t height)
{
  ANARIFrame frame = anariNewFrame(device);
  const uint32_t size[2] = {width, height};
  const ANARIDataType colorType = ANARI_FLOAT32_VEC4;
  const ANARIDataType depthType = ANARI_FLOAT32;
  anariSetParameter(device, frame, "size", ANARI_UINT32_VEC2, size);
  anariSetParameter(
      device, frame, "channel.color", ANARI_DATA_TYPE, &colorType);
  anariSetParameter(
      device, frame, "channel.depth", ANARI_DATA_TYPE, &depthType);
  const ANARIDataType vectorType = ANARI_FLOAT32_VEC3;
  anariSetParameter(
      device, frame, "channel.normal", ANARI_DATA_TYPE, &vectorType);
  anariSetParameter(
      device, frame, "channel.albedo", ANARI_DATA_TYPE, &vectorType);
  anariSetParameter(device, frame, "world", ANARI_WORLD, &world);
  anariSetParameter(device, frame, "camera", ANARI_CAMERA, &camera);
  anariSetParameter(device, frame, "renderer", ANARI_RENDERER, &renderer);
  anariCommitParameters(device, frame);
  return frame;
}

// One mapped frame, copied out.
struct Image
{
  uint32_t width{0};
  uint32_t height{0};
  std::vector<float> color; // RGBA per pixel
  std::vector<float> depth;
  std::vector<float> normal; // XYZ per pixel
  std::vector<float> albedo; // RGB per pixel
};

inline Image readFrame(ANARIDevice device, ANARIFrame frame)
{
  Image image;
  uint32_t width = 0, height = 0;
  ANARIDataType type = ANARI_UNKNOWN;
  const void *color =
      anariMapFrame(device, frame, "channel.color", &width, &height, &type);
  if (color && type == ANARI_FLOAT32_VEC4) {
    image.width = width;
    image.height = height;
    image.color.assign((const float *)color,
        (const float *)color + size_t(width) * height * 4);
  }
  anariUnmapFrame(device, frame, "channel.color");
  const void *depth =
      anariMapFrame(device, frame, "channel.depth", &width, &height, &type);
  if (depth && type == ANARI_FLOAT32 && width == image.width
      && height == image.height)
    image.depth.assign(
        (const float *)depth, (const float *)depth + size_t(width) * height);
  anariUnmapFrame(device, frame, "channel.depth");
  for (const char *channel : {"channel.normal", "channel.albedo"}) {
    const void *pixels =
        anariMapFrame(device, frame, channel, &width, &height, &type);
    if (pixels && type == ANARI_FLOAT32_VEC3 && width == image.width
        && height == image.height) {
      auto &to = std::string(channel) == "channel.normal" ? image.normal
                                                          : image.albedo;
      to.assign((const float *)pixels,
          (const float *)pixels + size_t(width) * height * 3);
    }
    anariUnmapFrame(device, frame, channel);
  }
  return image;
}

} // namespace prism::scenes
