// A material ball, the way glTF sample viewers show a material: a textured
// physicallyBased sphere (procedural checker as an image2D sampler over the
// mesh's uv) on a two-step cylinder stand, over a checkered floor.
#include "DemoScenes.h"
#include "Meshes.h"
#include "Objects.h"

#include <cstdint>

namespace prism::scenes {
namespace {

// A square checker of `size` texels with `cells` squares per side, as 8-bit
// sRGB RGBA texels, row 0 first.
std::vector<std::array<uint8_t, 4>> checkerTexels(uint32_t size,
    uint32_t cells,
    const std::array<uint8_t, 4> &a,
    const std::array<uint8_t, 4> &b)
{
  std::vector<std::array<uint8_t, 4>> texels(size_t(size) * size);
  const uint32_t cell = size / cells;
  for (uint32_t y = 0; y < size; y++)
    for (uint32_t x = 0; x < size; x++)
      texels[size_t(y) * size + x] = ((x / cell + y / cell) % 2) ? b : a;
  return texels;
}

// A committed image2D sampler over `texels`, repeating, with nearest
// filtering so the checks stay crisp; uv scaled by `scale` first.
ANARISampler newChecker(ANARIDevice device,
    const std::vector<std::array<uint8_t, 4>> &texels,
    uint32_t size,
    float uScale,
    float vScale)
{
  ANARIArray2D image = newArray2D(device,
      ANARI_UFIXED8_RGBA_SRGB,
      texels.data(),
      size,
      size,
      sizeof(texels[0]));
  ANARISampler sampler = anariNewSampler(device, "image2D");
  setObject(device, sampler, "image", ANARI_ARRAY2D, image);
  anariRelease(device, image);
  setString(device, sampler, "inAttribute", "attribute0");
  setString(device, sampler, "filter", "nearest");
  setString(device, sampler, "wrapMode1", "repeat");
  setString(device, sampler, "wrapMode2", "repeat");
  const Mat4 scale = scaleMatrix({uScale, vScale, 1.f});
  anariSetParameter(
      device, sampler, "inTransform", ANARI_FLOAT32_MAT4, scale.data());
  anariCommitParameters(device, sampler);
  return sampler;
}

ANARIGeometry newCylinder(
    ANARIDevice device, const Vec3 &bottom, const Vec3 &top, float radius)
{
  ANARIGeometry geometry = anariNewGeometry(device, "cylinder");
  setArray(device,
      geometry,
      "vertex.position",
      ANARI_FLOAT32_VEC3,
      std::vector<Vec3>{bottom, top});
  setFloat(device, geometry, "radius", radius);
  setString(device, geometry, "caps", "both");
  anariCommitParameters(device, geometry);
  return geometry;
}

} // namespace

Scene buildMaterialBall(ANARIDevice device)
{
  Scene scene;
  scene.name = "material-ball";
  scene.description = "a material ball";
  scene.camera.valid = true;
  scene.camera.eye = {0.f, 2.3f, 4.6f};
  scene.camera.at = {0.f, 1.1f, 0.f};
  scene.camera.fovyDegrees = 35.f;
  scene.hasBackground = true;
  scene.background = {0.18f, 0.19f, 0.21f, 1.f};

  constexpr uint32_t kTextureSize = 64;
  const auto ballTexels =
      checkerTexels(kTextureSize, 8, {230, 110, 30, 255}, {245, 235, 215, 255});
  const auto floorTexels = checkerTexels(
      kTextureSize, 2, {200, 200, 200, 255}, {120, 120, 120, 255});
  ANARISampler ballTexture =
      newChecker(device, ballTexels, kTextureSize, 2.f, 1.f);
  ANARISampler floorTexture =
      newChecker(device, floorTexels, kTextureSize, 1.f, 1.f);

  ANARIMaterial ballMaterial = anariNewMaterial(device, "physicallyBased");
  setObject(device, ballMaterial, "baseColor", ANARI_SAMPLER, ballTexture);
  setFloat(device, ballMaterial, "metallic", 0.f);
  setFloat(device, ballMaterial, "roughness", 0.35f);
  setFloat(device, ballMaterial, "clearcoat", 0.5f);
  setFloat(device, ballMaterial, "clearcoatRoughness", 0.05f);
  anariCommitParameters(device, ballMaterial);
  ANARIMaterial floorMaterial = anariNewMaterial(device, "physicallyBased");
  setObject(device, floorMaterial, "baseColor", ANARI_SAMPLER, floorTexture);
  setFloat(device, floorMaterial, "metallic", 0.f);
  setFloat(device, floorMaterial, "roughness", 0.8f);
  anariCommitParameters(device, floorMaterial);
  ANARIMaterial standMaterial = anariNewMaterial(device, "physicallyBased");
  setVec3(device, standMaterial, "baseColor", {0.08f, 0.08f, 0.09f});
  setFloat(device, standMaterial, "metallic", 1.f);
  setFloat(device, standMaterial, "roughness", 0.3f);
  anariCommitParameters(device, standMaterial);
  anariRelease(device, ballTexture);
  anariRelease(device, floorTexture);

  TriangleMesh ball, floor;
  ball.addUvSphere({0.f, 1.45f, 0.f}, 1.f, 64, 32);
  floor.addQuad({-4.f, 0.f, 4.f}, {8.f, 0.f, 0.f}, {0.f, 0.f, -8.f}, 4.f, 4.f);
  scene.bounds = floor.bounds();
  scene.bounds.extend(ball.bounds());

  std::vector<ANARIObject> surfaces;
  ANARIGeometry geometries[4] = {newTriangleGeometry(device, ball),
      newTriangleGeometry(device, floor),
      newCylinder(device, {0.f, 0.f, 0.f}, {0.f, 0.15f, 0.f}, 0.7f),
      newCylinder(device, {0.f, 0.15f, 0.f}, {0.f, 0.6f, 0.f}, 0.25f)};
  const ANARIMaterial materials[4] = {
      ballMaterial, floorMaterial, standMaterial, standMaterial};
  const char *geometrySubtypes[4] = {
      "triangle", "triangle", "cylinder", "cylinder"};
  for (int i = 0; i < 4; i++) {
    surfaces.push_back(newListedSurface(device,
        scene.surfaces,
        geometries[i],
        geometrySubtypes[i],
        materials[i],
        "physicallyBased",
        uint32_t(i)));
    anariRelease(device, geometries[i]);
  }
  for (ANARIMaterial m : {ballMaterial, floorMaterial, standMaterial})
    anariRelease(device, m);

  std::vector<ANARIObject> lights;
  if (ANARILight sun =
          newLightIfSupported(device, "directional", scene, lights)) {
    setVec3(device, sun, "direction", normalize({-0.5f, -1.f, -0.7f}));
    setFloat(device, sun, "irradiance", 2.5f);
    anariCommitParameters(device, sun);
  }
  finishWorld(device, scene, surfaces, {}, lights);
  return scene;
}

} // namespace prism::scenes
