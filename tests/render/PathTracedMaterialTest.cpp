// Each lobe of the physicallyBased material (spec 5.11, the glTF BRDF and
// its KHR_materials_* extensions) through the path tracer: one sphere of
// the material on a floor before a striped wall, under a quad light and a
// little ambient light, 64 samples per pixel. Plus depth of field with the
// path tracer.
#include "RenderTest.h"

#include <cmath>
#include <cstring>
#include <functional>

namespace {

constexpr uint32_t kWidth = 80, kHeight = 64, kSamples = 64;

class MaterialBall : public RenderTest
{
 protected:
  // A committed physicallyBased material; `configure` sets its parameters.
  ANARIMaterial pbr(const std::function<void(ANARIMaterial)> &configure)
  {
    ANARIMaterial material =
        keep(anariNewMaterial(device(), "physicallyBased"));
    configure(material);
    anariCommitParameters(device(), material);
    return material;
  }
  ANARIWorld scene(ANARIMaterial ballMaterial)
  {
    ANARIGeometry floor = newGeometry("quad");
    setArray(floor,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{-3, -3, 0}, {3, -3, 0}, {3, 2, 0}, {-3, 2, 0}});
    // Vertical stripes on the wall show what refraction and reflection
    // bend.
    std::vector<Vec3> stripes;
    std::vector<uint32_t> stripeIndices;
    for (int i = 0; i < 6; i++) {
      const float x0 = -3.f + float(i), x1 = x0 + 0.5f;
      const auto first = uint32_t(stripes.size());
      stripes.insert(stripes.end(),
          {{x0, 1.99f, 0}, {x1, 1.99f, 0}, {x1, 1.99f, 4}, {x0, 1.99f, 4}});
      for (uint32_t k = 0; k < 4; k++)
        stripeIndices.push_back(first + k);
    }
    ANARIGeometry stripeGeometry = newGeometry("quad");
    setArray(stripeGeometry, "vertex.position", ANARI_FLOAT32_VEC3, stripes);
    setArray(
        stripeGeometry, "primitive.index", ANARI_UINT32_VEC4, stripeIndices);
    ANARIGeometry wall = newGeometry("quad");
    setArray(wall,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{-3, 2, 0}, {3, 2, 0}, {3, 2, 4}, {-3, 2, 4}});
    ANARIGeometry sphere = newGeometry("sphere");
    setArray(sphere,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{0, 0, 0.8f}});
    setFloat(sphere, "radius", 0.8f);
    ANARIWorld world =
        newWorld({newSurface(floor, newMatte({0.7f, 0.7f, 0.7f})),
            newSurface(wall, newMatte({0.8f, 0.8f, 0.75f})),
            newSurface(stripeGeometry, newMatte({0.1f, 0.2f, 0.6f})),
            newSurface(sphere, ballMaterial)});
    ANARILight light = keep(anariNewLight(device(), "quad"));
    setVec3(light, "position", {-2.f, -2.f, 3.5f});
    // Facing down (the front side is edge2 x edge1).
    setVec3(light, "edge1", {1.5f, 0.f, 0.f});
    setVec3(light, "edge2", {0.f, 1.5f, 0.f});
    setFloat(light, "radiance", 6.f);
    anariCommitParameters(device(), light);
    setObject(
        world, "light", ANARI_ARRAY1D, newArray1D(ANARI_LIGHT, &light, 1));
    anariCommitParameters(device(), world);
    return world;
  }
  ANARICamera camera()
  {
    return newPerspectiveCamera({0.f, -4.5f, 1.6f},
        {0.f, 4.5f, -0.8f},
        {0.f, 0.f, 1.f},
        float(kWidth) / float(kHeight),
        0.7f);
  }
  // A sampler of tangent-space normals rippling along x, read at the world
  // position (repeating every 0.25 units), for normal and clearcoatNormal.
  ANARISampler rippleNormals()
  {
    ANARIDevice device = this->device();
    constexpr uint32_t size = 16;
    std::vector<Vec3> normals(size * size);
    for (uint32_t y = 0; y < size; y++) {
      for (uint32_t x = 0; x < size; x++) {
        const float slope =
            0.6f * std::sin(2.f * 3.14159265f * float(x) / size);
        const float length = std::sqrt(1.f + slope * slope);
        normals[y * size + x] = {slope / length, 0.f, 1.f / length};
      }
    }
    ANARISampler sampler = anariNewSampler(device, "image2D");
    ANARIArray2D image = anariNewArray2D(
        device, nullptr, nullptr, nullptr, ANARI_FLOAT32_VEC3, size, size);
    std::memcpy(anariMapArray(device, image),
        normals.data(),
        normals.size() * sizeof(Vec3));
    anariUnmapArray(device, image);
    anariSetParameter(device, sampler, "image", ANARI_ARRAY2D, &image);
    anariRelease(device, image);
    anariSetParameter(
        device, sampler, "inAttribute", ANARI_STRING, "worldPosition");
    anariSetParameter(device, sampler, "filter", ANARI_STRING, "linear");
    anariSetParameter(device, sampler, "wrapMode1", ANARI_STRING, "repeat");
    anariSetParameter(device, sampler, "wrapMode2", ANARI_STRING, "repeat");
    const Mat4 scale = scaling({4.f, 4.f, 4.f});
    anariSetParameter(
        device, sampler, "inTransform", ANARI_FLOAT32_MAT4, scale.data());
    anariCommitParameters(device, sampler);
    return keep(sampler);
  }
  void expectReference(ANARIWorld world, ANARICamera camera)
  {
    ANARIRenderer renderer = keep(anariNewRenderer(device(), "pathtracer"));
    setVec4(renderer, "background", {0.f, 0.f, 0.f, 1.f});
    setFloat(renderer, "ambientRadiance", 0.15f);
    anariCommitParameters(device(), renderer);
    renderAndCompare(world, camera, renderer, kWidth, kHeight, {}, kSamples);
  }
  void expectReference(const std::function<void(ANARIMaterial)> &configure)
  {
    expectReference(scene(pbr(configure)), camera());
  }
};

using RoughMetal = MaterialBall;
TEST_F(RoughMetal, Pathtracer)
{
  expectReference([&](ANARIMaterial m) {
    setVec3(m, "baseColor", {0.95f, 0.64f, 0.54f}); // copper
    setFloat(m, "metallic", 1.f);
    setFloat(m, "roughness", 0.35f);
  });
}

using MirrorMetal = MaterialBall;
TEST_F(MirrorMetal, Pathtracer)
{
  expectReference([&](ANARIMaterial m) {
    setVec3(m, "baseColor", {0.9f, 0.9f, 0.9f});
    setFloat(m, "metallic", 1.f);
    setFloat(m, "roughness", 0.f);
  });
}

using GlossyDielectric = MaterialBall; // base color under a specular layer
TEST_F(GlossyDielectric, Pathtracer)
{
  expectReference([&](ANARIMaterial m) {
    setVec3(m, "baseColor", {0.1f, 0.5f, 0.15f});
    setFloat(m, "metallic", 0.f);
    setFloat(m, "roughness", 0.2f);
    setFloat(m, "specular", 1.f);
    setVec3(m, "specularColor", {1.f, 0.8f, 0.6f});
  });
}

using Clearcoat = MaterialBall;
TEST_F(Clearcoat, Pathtracer)
{
  expectReference([&](ANARIMaterial m) {
    setVec3(m, "baseColor", {0.6f, 0.05f, 0.05f});
    setFloat(m, "metallic", 0.f);
    setFloat(m, "roughness", 0.7f);
    setFloat(m, "clearcoat", 1.f);
    setFloat(m, "clearcoatRoughness", 0.05f);
  });
}

using NormalMap = MaterialBall; // the base's normal rippled, a smooth coat
TEST_F(NormalMap, Pathtracer)
{
  ANARISampler ripples = rippleNormals();
  expectReference([&](ANARIMaterial m) {
    setVec3(m, "baseColor", {0.7f, 0.5f, 0.2f});
    setFloat(m, "metallic", 1.f);
    setFloat(m, "roughness", 0.25f);
    setObject(m, "normal", ANARI_SAMPLER, ripples);
  });
}

using ClearcoatNormal = MaterialBall; // a rippled coat on a smooth base
TEST_F(ClearcoatNormal, Pathtracer)
{
  ANARISampler ripples = rippleNormals();
  expectReference([&](ANARIMaterial m) {
    setVec3(m, "baseColor", {0.1f, 0.2f, 0.6f});
    setFloat(m, "metallic", 0.f);
    setFloat(m, "roughness", 0.6f);
    setFloat(m, "clearcoat", 1.f);
    setFloat(m, "clearcoatRoughness", 0.f);
    setObject(m, "clearcoatNormal", ANARI_SAMPLER, ripples);
  });
}

using Sheen = MaterialBall;
TEST_F(Sheen, Pathtracer)
{
  expectReference([&](ANARIMaterial m) {
    setVec3(m, "baseColor", {0.05f, 0.05f, 0.2f});
    setFloat(m, "metallic", 0.f);
    setFloat(m, "roughness", 0.9f);
    setVec3(m, "sheenColor", {1.f, 0.6f, 0.8f});
    setFloat(m, "sheenRoughness", 0.3f);
  });
}

using ThinTransmission = MaterialBall; // thickness 0: a soap-bubble sheet
TEST_F(ThinTransmission, Pathtracer)
{
  expectReference([&](ANARIMaterial m) {
    setVec3(m, "baseColor", {0.9f, 0.95f, 1.f});
    setFloat(m, "metallic", 0.f);
    setFloat(m, "roughness", 0.f);
    setFloat(m, "transmission", 1.f);
    setFloat(m, "thickness", 0.f);
  });
}

using RefractingGlass = MaterialBall; // thickness > 0, tinted by absorption
TEST_F(RefractingGlass, Pathtracer)
{
  expectReference([&](ANARIMaterial m) {
    setVec3(m, "baseColor", {1.f, 1.f, 1.f});
    setFloat(m, "metallic", 0.f);
    setFloat(m, "roughness", 0.f);
    setFloat(m, "transmission", 1.f);
    setFloat(m, "ior", 1.5f);
    setFloat(m, "thickness", 1.f);
    setVec3(m, "attenuationColor", {0.3f, 0.8f, 0.4f});
    setFloat(m, "attenuationDistance", 0.8f);
  });
}

using Iridescence = MaterialBall;
TEST_F(Iridescence, Pathtracer)
{
  expectReference([&](ANARIMaterial m) {
    setVec3(m, "baseColor", {0.05f, 0.05f, 0.05f});
    setFloat(m, "metallic", 0.f);
    setFloat(m, "roughness", 0.15f);
    setFloat(m, "iridescence", 1.f);
    setFloat(m, "iridescenceIor", 1.3f);
    setFloat(m, "iridescenceThickness", 400.f);
  });
}

using Emissive = MaterialBall; // the ball lights the floor and the wall
TEST_F(Emissive, Pathtracer)
{
  expectReference([&](ANARIMaterial m) {
    setVec3(m, "baseColor", {0.2f, 0.2f, 0.2f});
    setVec3(m, "emissive", {2.f, 1.2f, 0.4f});
  });
}

// A material whose inputs read no attributes keeps its shading and BSDF
// from commit to commit: a color committed between frames must reach the
// image exactly as a material created with it.
using RecommittedMaterial = MaterialBall;
TEST_F(RecommittedMaterial, Pathtracer)
{
  ANARIRenderer renderer = keep(anariNewRenderer(device(), "pathtracer"));
  anariCommitParameters(device(), renderer);
  const ANARICamera view = camera();
  auto ball = [&](const Vec3 &color) {
    return pbr([&](ANARIMaterial m) { setVec3(m, "baseColor", color); });
  };
  const Vec3 red{0.9f, 0.1f, 0.1f}, green{0.1f, 0.9f, 0.1f};
  ANARIMaterial edited = ball(red);
  const ANARIWorld world = scene(edited);
  const auto before = render(world, view, renderer, kWidth, kHeight, 4);
  setVec3(edited, "baseColor", green);
  anariCommitParameters(device(), edited);
  const auto after = render(world, view, renderer, kWidth, kHeight, 4);
  const auto fresh =
      render(scene(ball(green)), view, renderer, kWidth, kHeight, 4);
  ASSERT_FALSE(before.empty() || after.empty() || fresh.empty());
  // The ball fills the middle of the image.
  const auto &redPixel = before.at(kWidth / 2, kHeight / 2);
  const auto &greenPixel = after.at(kWidth / 2, kHeight / 2);
  EXPECT_GT(redPixel.r, 2.f * redPixel.g);
  EXPECT_GT(greenPixel.g, 2.f * greenPixel.r);
  expectSameImage(after, fresh, "recommitted and created green");
}

using PathTracedDepthOfField = MaterialBall; // focused on the ball
TEST_F(PathTracedDepthOfField, Pathtracer)
{
  ANARICamera lens = camera();
  setFloat(lens, "apertureRadius", 0.15f);
  setFloat(lens, "focusDistance", 4.6f);
  anariCommitParameters(device(), lens);
  expectReference(scene(pbr([&](ANARIMaterial m) {
    setVec3(m, "baseColor", {0.8f, 0.3f, 0.2f});
    setFloat(m, "roughness", 0.4f);
  })),
      lens);
}

} // namespace
