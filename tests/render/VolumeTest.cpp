// Volumes: transferFunction1D over structuredRegular fields of every
// element type and filter, volumes composited with surfaces in depth
// order, by raycast and by the path tracer.
#include "RenderTest.h"

#include <nanovdb/util/GridBuilder.h>

#include <cmath>
#include <cstring>
#include <functional>

namespace {

class VolumeScene : public RenderTest
{
 protected:
  // A committed structuredRegular field of n^3 samples over [0, 1]^3
  // holding value(i, j, k) as `type` elements (written through `store`).
  ANARISpatialField newField(uint32_t n,
      ANARIDataType type,
      size_t elementBytes,
      const std::function<void(void *, uint32_t, uint32_t, uint32_t)> &store,
      const char *filter = "linear")
  {
    ANARIArray3D data =
        anariNewArray3D(device(), nullptr, nullptr, nullptr, type, n, n, n);
    auto *bytes = (unsigned char *)anariMapArray(device(), data);
    for (uint32_t k = 0; k < n; k++)
      for (uint32_t j = 0; j < n; j++)
        for (uint32_t i = 0; i < n; i++)
          store(bytes + ((size_t(k) * n + j) * n + i) * elementBytes, i, j, k);
    anariUnmapArray(device(), data);
    ANARISpatialField field =
        keep(anariNewSpatialField(device(), "structuredRegular"));
    setObject(field, "data", ANARI_ARRAY3D, data);
    anariRelease(device(), data);
    const float s = 1.f / float(n - 1);
    setVec3(field, "spacing", {s, s, s});
    setString(field, "filter", filter);
    anariCommitParameters(device(), field);
    return field;
  }
  ANARISpatialField newFloatField(uint32_t n,
      const std::function<float(uint32_t, uint32_t, uint32_t)> &value,
      const char *filter = "linear")
  {
    return newField(
        n,
        ANARI_FLOAT32,
        4,
        [&](void *p, uint32_t i, uint32_t j, uint32_t k) {
          const float v = value(i, j, k);
          std::memcpy(p, &v, 4);
        },
        filter);
  }
  // A committed volume: blue -> white -> red over [lo, hi], opacity ramp.
  ANARIVolume newVolume(ANARISpatialField field,
      float lo = 0.f,
      float hi = 1.f,
      float unitDistance = 0.25f)
  {
    ANARIVolume volume = keep(anariNewVolume(device(), "transferFunction1D"));
    setObject(volume, "value", ANARI_SPATIAL_FIELD, field);
    setArray(volume,
        "color",
        ANARI_FLOAT32_VEC3,
        std::vector<float>{0.1f, 0.2f, 0.9f, 1, 1, 1, 0.9f, 0.1f, 0.1f});
    setArray(volume,
        "opacity",
        ANARI_FLOAT32,
        std::vector<float>{0.05f, 0.4f, 0.9f});
    const float range[2] = {lo, hi};
    anariSetParameter(
        device(), volume, "valueRange", ANARI_FLOAT32_BOX1, range);
    setFloat(volume, "unitDistance", unitDistance);
    anariCommitParameters(device(), volume);
    return volume;
  }
  // A committed group of volumes (and surfaces).
  ANARIGroup newVolumeGroup(const std::vector<ANARIVolume> &volumes,
      const std::vector<ANARISurface> &surfaces = {})
  {
    ANARIGroup group = keep(anariNewGroup(device()));
    setObject(group,
        "volume",
        ANARI_ARRAY1D,
        anariNewArray1D(device(),
            volumes.data(),
            nullptr,
            nullptr,
            ANARI_VOLUME,
            volumes.size()));
    if (!surfaces.empty()) {
      setObject(group,
          "surface",
          ANARI_ARRAY1D,
          anariNewArray1D(device(),
              surfaces.data(),
              nullptr,
              nullptr,
              ANARI_SURFACE,
              surfaces.size()));
    }
    anariCommitParameters(device(), group);
    return group;
  }
  ANARIInstance placed(ANARIGroup group, const Mat4 &transform)
  {
    ANARIInstance instance = newInstance(group);
    setMat4(instance, "transform", transform);
    anariCommitParameters(device(), instance);
    return instance;
  }
  // Renders `world` (given one directional light) from `eye` along `view`
  // (z up) at 96 x 96 over a dark background, against the reference.
  void renderLit(ANARIWorld world,
      const Vec3 &lightDirection,
      float irradiance,
      const Vec3 &eye,
      const Vec3 &view,
      const char *subtype,
      uint32_t frames)
  {
    ANARILight light = keep(anariNewLight(device(), "directional"));
    setVec3(light, "direction", lightDirection);
    setFloat(light, "irradiance", irradiance);
    anariCommitParameters(device(), light);
    setObject(world,
        "light",
        ANARI_ARRAY1D,
        anariNewArray1D(device(), &light, nullptr, nullptr, ANARI_LIGHT, 1));
    anariCommitParameters(device(), world);
    ANARICamera camera = newPerspectiveCamera(eye, view, {0, 0, 1}, 1.f, 0.9f);
    ANARIRenderer renderer = newRenderer(subtype);
    setVec4(renderer, "background", {0.1f, 0.1f, 0.15f, 1.f});
    anariCommitParameters(device(), renderer);
    renderAndCompare(world, camera, renderer, 96, 96, {}, frames);
  }
  // Looking down -z at [0, width] x [0, 1] from above.
  ANARICamera topView(float width, uint32_t pixelsWide, uint32_t pixelsHigh)
  {
    return newOrthographicCamera({width / 2, 0.5f, 3.f},
        {0, 0, -1},
        {0, 1, 0},
        1.f,
        float(pixelsWide) / float(pixelsHigh));
  }
};

// A value per sample with structure at the scale of one cell.
float cellPattern(uint32_t i, uint32_t j, uint32_t k)
{
  return float((i * 7 + j * 3 + k * 5) % 5) / 4.f;
}

using VolumeFilters = VolumeScene;

// Left to right: the same 5^3 samples filtered nearest (blocks, one colour
// per cell around each sample), linear (smooth within cells, creases at
// cell faces) and cubic (smooth across faces, slightly overshooting).
TEST_F(VolumeFilters, Raycast)
{
  std::vector<ANARIInstance> instances;
  float x = 0.f;
  for (const char *filter : {"nearest", "linear", "cubic"}) {
    instances.push_back(placed(
        newVolumeGroup({newVolume(newFloatField(5, cellPattern, filter))}),
        translation({x, 0, 0})));
    x += 1.1f;
  }
  renderAndCompare(
      newWorld({}, instances), topView(3.2f, 192, 60), newRenderer(), 192, 60);
}

using VolumeElementTypes = VolumeScene;

// Five slabs side by side, a ramp from 0 at x = 0 to 1 at x = 1 stored as
// UFIXED8, FIXED16, UFIXED16, FLOAT32 and FLOAT64: decoded by the spec's
// rules (UFIXED / max, FIXED / max) every one is the same ramp, so the five
// look alike.
TEST_F(VolumeElementTypes, Raycast)
{
  struct Type
  {
    ANARIDataType type;
    size_t bytes;
    std::function<void(void *, bool)> store; // the ramp's low or high end
  };
  const std::vector<Type> types = {
      {ANARI_UFIXED8,
          1,
          [](void *p, bool high) {
            *(uint8_t *)p = high ? 255 : 0;
          }},
      {ANARI_FIXED16,
          2,
          [](void *p, bool high) {
            *(int16_t *)p = high ? 32767 : 0;
          }},
      {ANARI_UFIXED16,
          2,
          [](void *p, bool high) {
            *(uint16_t *)p = high ? 65535 : 0;
          }},
      {ANARI_FLOAT32,
          4,
          [](void *p, bool high) {
            *(float *)p = high ? 1.f : 0.f;
          }},
      {ANARI_FLOAT64,
          8,
          [](void *p, bool high) {
            *(double *)p = high ? 1.0 : 0.0;
          }},
  };
  std::vector<ANARIInstance> instances;
  float x = 0.f;
  for (const Type &t : types) {
    ANARISpatialField field = newField(
        2, t.type, t.bytes, [&](void *p, uint32_t i, uint32_t, uint32_t) {
          t.store(p, i == 1);
        });
    instances.push_back(
        placed(newVolumeGroup({newVolume(field)}), translation({x, 0, 0})));
    x += 1.25f;
  }
  const uint32_t slabPixels = 40;
  const prism::image::Image image = render(newWorld({}, instances),
      topView(6.25f, 5 * 50, slabPixels),
      newRenderer(),
      5 * 50,
      slabPixels);
  for (uint32_t s = 1; s < 5; s++) {
    expectSameImage(crop(image, 50 * s, 0, 50, slabPixels),
        crop(image, 0, 0, 50, slabPixels),
        "slab " + std::to_string(s) + " vs the UFIXED8 slab");
  }
  renderAndCompare(newWorld({}, instances),
      topView(6.25f, 5 * 50, slabPixels),
      newRenderer(),
      5 * 50,
      slabPixels);
}

// A soft ball of density around an opaque grey sphere, over a green floor:
// the sphere shows through the ball's haze, the floor through both where
// they are thin; raycast by the reference marcher, the path tracer (a
// directional light from above, 64 samples) with the ball's shadow on the
// floor.
class VolumeAndSurfaces : public VolumeScene
{
 protected:
  void renderScene(const char *subtype, uint32_t frames)
  {
    ANARIGeometry sphere = newGeometry("sphere");
    setArray(sphere,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<float>{0.5f, 0.5f, 0.5f});
    setFloat(sphere, "radius", 0.2f);
    ANARIGeometry floor = newGeometry("quad");
    setArray(floor,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<float>{
            -2, -2, -0.2f, 3, -2, -0.2f, 3, 3, -0.2f, -2, 3, -0.2f});
    auto ball = [](uint32_t i, uint32_t j, uint32_t k) {
      const float dx = float(i) / 16.f - 0.5f, dy = float(j) / 16.f - 0.5f,
                  dz = float(k) / 16.f - 0.5f;
      return std::max(0.f, 1.f - 2.f * std::sqrt(dx * dx + dy * dy + dz * dz));
    };
    ANARIGroup group = newVolumeGroup({newVolume(newFloatField(17, ball))},
        {newSurface(sphere, newMatte({0.6f, 0.6f, 0.6f})),
            newSurface(floor, newMatte({0.2f, 0.6f, 0.2f}))});
    ANARIWorld world = newWorld({}, {placed(group, translation({0, 0, 0}))});
    renderLit(world,
        {-0.3f, -0.2f, -1.f},
        2.f,
        {0.5f, -1.2f, 1.4f},
        {0, 1.7f, -1.2f},
        subtype,
        frames);
  }
};

TEST_F(VolumeAndSurfaces, Raycast)
{
  renderScene("raycast", 1);
}

TEST_F(VolumeAndSurfaces, PathTracer)
{
  renderScene("pathtracer", 64);
}

using VolumeNanoVdb = VolumeScene;

// A sparse NanoVDB float grid, built with NanoVDB's own GridBuilder: two
// balls of density (voxel size 1/32, the world's [0, 1] box), background
// 0 everywhere else, passed to the `nanovdb` field as a UINT8 blob. The
// larger ball on the left is brighter at its core; the grid's translation
// moves the smaller one to the right.
TEST_F(VolumeNanoVdb, Raycast)
{
  nanovdb::GridBuilder<float> builder(0.f);
  auto voxels = builder.getAccessor();
  auto ball = [&](int cx, int cy, int cz, int r) {
    for (int k = cz - r; k <= cz + r; k++)
      for (int j = cy - r; j <= cy + r; j++)
        for (int i = cx - r; i <= cx + r; i++) {
          const float d =
              std::sqrt(float((i - cx) * (i - cx) + (j - cy) * (j - cy)
                              + (k - cz) * (k - cz)))
              / float(r);
          if (d < 1.f)
            voxels.setValue(nanovdb::Coord(i, j, k), 1.f - d);
        }
  };
  ball(10, 16, 16, 9);
  ball(26, 16, 16, 5);
  const auto handle =
      builder.getHandle<>(1.0 / 32.0, nanovdb::Vec3d(0.25, 0.0, 0.0));
  ANARIArray1D blob = newArray1D(ANARI_UINT8, handle.data(), handle.size());
  ANARISpatialField field = keep(anariNewSpatialField(device(), "nanovdb"));
  setObject(field, "data", ANARI_ARRAY1D, blob);
  anariCommitParameters(device(), field);
  renderAndCompare(
      newWorld({},
          {placed(newVolumeGroup({newVolume(field)}), translation({0, 0, 0}))}),
      topView(1.5f, 144, 96),
      newRenderer(),
      144,
      96);
}

using VolumeUnstructured = VolumeScene;

// One cell of each kind the unstructured field knows, left to right: a
// tetrahedron, a hexahedron, a wedge and a pyramid (VTK ordering), their
// vertex values a ramp along x (blue to red); below them the same cells
// with one value each (cell.data: 0, 0.33, 0.67, 1), so each is flat.
TEST_F(VolumeUnstructured, Raycast)
{
  std::vector<float> positions;
  std::vector<uint32_t> index, offsets;
  std::vector<uint8_t> types;
  auto add = [&](uint8_t type, const std::vector<Vec3> &corners, float x0) {
    offsets.push_back(uint32_t(index.size()));
    types.push_back(type);
    for (const Vec3 &c : corners) {
      index.push_back(uint32_t(positions.size() / 3));
      positions.insert(positions.end(), {c[0] + x0, c[1], c[2]});
    }
  };
  add(10, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, 0.f);
  add(12,
      {{0, 0, 0},
          {1, 0, 0},
          {1, 1, 0},
          {0, 1, 0},
          {0, 0, 1},
          {1, 0, 1},
          {1, 1, 1},
          {0, 1, 1}},
      1.25f);
  add(13,
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}},
      2.5f);
  add(14, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5f, 0.5f, 1}}, 3.75f);
  std::vector<float> ramp;
  for (size_t v = 0; v < positions.size() / 3; v++)
    ramp.push_back(positions[3 * v] / 4.75f);
  auto mesh = [&](bool perCell) {
    ANARISpatialField field =
        keep(anariNewSpatialField(device(), "unstructured"));
    setArray(field, "vertex.position", ANARI_FLOAT32_VEC3, positions);
    setArray(field, "index", ANARI_UINT32, index);
    setArray(field, "cell.index", ANARI_UINT32, offsets);
    setArray(field, "cell.type", ANARI_UINT8, types);
    if (perCell) {
      setArray(field,
          "cell.data",
          ANARI_FLOAT32,
          std::vector<float>{0.f, 0.33f, 0.67f, 1.f});
    } else {
      setArray(field, "vertex.data", ANARI_FLOAT32, ramp);
    }
    anariCommitParameters(device(), field);
    return newVolumeGroup({newVolume(field, 0.f, 1.f, 0.2f)});
  };
  ANARIWorld world = newWorld({},
      {placed(mesh(false), translation({0, 1.2f, 0})),
          placed(mesh(true), translation({0, 0, 0}))});
  renderAndCompare(world,
      newOrthographicCamera(
          {2.375f, 1.1f, 3.f}, {0, 0, -1}, {0, 1, 0}, 2.4f, 2.2f),
      newRenderer(),
      176,
      80);
}

// Two isosurfaces (KHR_GEOMETRY_ISOSURFACE) of a structuredRegular
// distance field, found on its trilinear interpolant: the inner sphere
// (isovalue 0.2, primitive.color red) seen through the outer one (0.35,
// blue, half transparent); shaded by the field's gradient.
class Isosurface : public VolumeScene
{
 protected:
  void renderScene(const char *subtype, uint32_t frames)
  {
    ANARISpatialField field =
        newFloatField(17, [](uint32_t i, uint32_t j, uint32_t k) {
          const float x = float(i) / 16.f - 0.5f, y = float(j) / 16.f - 0.5f,
                      z = float(k) / 16.f - 0.5f;
          return std::sqrt(x * x + y * y + z * z);
        });
    ANARIGeometry iso = newGeometry("isosurface");
    setObject(iso, "field", ANARI_SPATIAL_FIELD, field);
    setArray(iso, "isovalue", ANARI_FLOAT32, std::vector<float>{0.2f, 0.35f});
    setArray(iso,
        "primitive.color",
        ANARI_FLOAT32_VEC4,
        std::vector<float>{0.9f, 0.2f, 0.1f, 1.f, 0.2f, 0.4f, 0.9f, 0.5f});
    ANARIMaterial material = keep(anariNewMaterial(device(), "matte"));
    setString(material, "color", "color");
    setString(material, "alphaMode", "blend");
    anariCommitParameters(device(), material);
    renderLit(newWorld({newSurface(iso, material)}),
        {-0.3f, -0.5f, -1.f},
        3.f,
        {0.5f, -0.6f, 1.3f},
        {0, 1.1f, -0.8f},
        subtype,
        frames);
  }
};

TEST_F(Isosurface, Raycast)
{
  renderScene("raycast", 1);
}

TEST_F(Isosurface, PathTracer)
{
  renderScene("pathtracer", 32);
}

} // namespace
