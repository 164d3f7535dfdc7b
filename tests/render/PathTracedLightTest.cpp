// Every light subtype (spec 5.7) through the path tracer: a sphere on a
// floor in front of a wall, lit by one light, 64 samples per pixel. The
// references show each light's shape: hard and soft shadows, the spot's
// smoothstep edge, the quad's and ring's soft penumbrae, the HDRI's sun,
// and ambient light alone.
#include "RenderTest.h"

namespace {

constexpr uint32_t kWidth = 96, kHeight = 72, kSamples = 64;

class LitScene : public RenderTest
{
 protected:
  // The floor (z = 0), a wall behind (y = 2), a sphere on the floor, and
  // `lights` (committed).
  ANARIWorld scene(const std::vector<ANARILight> &lights)
  {
    ANARIGeometry floor = newGeometry("quad");
    setArray(floor,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{-3, -3, 0}, {3, -3, 0}, {3, 2, 0}, {-3, 2, 0}});
    ANARIGeometry wall = newGeometry("quad");
    setArray(wall,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{-3, 2, 0}, {3, 2, 0}, {3, 2, 4}, {-3, 2, 4}});
    ANARIGeometry sphere = newGeometry("sphere");
    setArray(sphere,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::vector<Vec3>{{0, 0, 0.7f}});
    setFloat(sphere, "radius", 0.7f);
    ANARIWorld world =
        newWorld({newSurface(floor, newMatte({0.8f, 0.8f, 0.8f})),
            newSurface(wall, newMatte({0.6f, 0.7f, 0.8f})),
            newSurface(sphere, newMatte({0.8f, 0.3f, 0.2f}))});
    if (!lights.empty()) {
      setObject(world,
          "light",
          ANARI_ARRAY1D,
          newArray1D(ANARI_LIGHT, lights.data(), lights.size()));
      anariCommitParameters(device(), world);
    }
    return world;
  }
  ANARILight newLight(const char *subtype)
  {
    return keep(anariNewLight(device(), subtype));
  }
  ANARILight committed(ANARILight light)
  {
    anariCommitParameters(device(), light);
    return light;
  }
  // Renders `world` with the path tracer (`ambientRadiance` of white
  // ambient light) and compares it with the test's reference.
  void expectReference(ANARIWorld world, float ambientRadiance = 0.f)
  {
    ANARIRenderer renderer = keep(anariNewRenderer(device(), "pathtracer"));
    setVec4(renderer, "background", {0.f, 0.f, 0.f, 1.f});
    setFloat(renderer, "ambientRadiance", ambientRadiance);
    anariCommitParameters(device(), renderer);
    ANARICamera camera = newPerspectiveCamera({0.f, -5.f, 2.2f},
        {0.f, 5.f, -1.6f},
        {0.f, 0.f, 1.f},
        float(kWidth) / float(kHeight),
        0.9f);
    renderAndCompare(world, camera, renderer, kWidth, kHeight, {}, kSamples);
  }
};

using DirectionalLight = LitScene;
TEST_F(DirectionalLight, Pathtracer)
{
  ANARILight light = newLight("directional");
  setVec3(light, "direction", {-0.6f, 0.5f, -1.f});
  setFloat(light, "irradiance", 2.5f);
  expectReference(scene({committed(light)}));
}

using SunDisk = LitScene; // a directional light with an angular diameter
TEST_F(SunDisk, Pathtracer)
{
  ANARILight light = newLight("directional");
  setVec3(light, "direction", {-0.6f, 0.5f, -1.f});
  setFloat(light, "irradiance", 2.5f);
  setFloat(light, "angularDiameter", 0.2f);
  expectReference(scene({committed(light)}));
}

using PointLight = LitScene;
TEST_F(PointLight, Pathtracer)
{
  ANARILight light = newLight("point");
  setVec3(light, "position", {1.2f, -1.f, 2.5f});
  setFloat(light, "intensity", 12.f);
  setVec3(light, "color", {1.f, 0.9f, 0.7f});
  expectReference(scene({committed(light)}));
}

using SphereLight = LitScene; // a point light with a radius, seen
TEST_F(SphereLight, Pathtracer)
{
  ANARILight light = newLight("point");
  setVec3(light, "position", {1.2f, -1.f, 2.5f});
  setFloat(light, "power", 150.f);
  setFloat(light, "radius", 0.4f);
  expectReference(scene({committed(light)}));
}

using SpotLight = LitScene;
TEST_F(SpotLight, Pathtracer)
{
  ANARILight light = newLight("spot");
  setVec3(light, "position", {0.f, -0.5f, 3.5f});
  setVec3(light, "direction", {0.f, 0.3f, -1.f});
  setFloat(light, "openingAngle", 0.9f);
  setFloat(light, "falloffAngle", 0.25f);
  setFloat(light, "intensity", 25.f);
  expectReference(scene({committed(light)}));
}

using QuadLight = LitScene;
TEST_F(QuadLight, Pathtracer)
{
  ANARILight light = newLight("quad");
  // The front side (spec: edge2 x edge1) faces down onto the scene.
  setVec3(light, "position", {-1.f, -1.5f, 3.f});
  setVec3(light, "edge1", {2.f, 0.f, 0.f});
  setVec3(light, "edge2", {0.f, 1.5f, 0.f});
  setFloat(light, "radiance", 4.f);
  expectReference(scene({committed(light)}));
}

using QuadLightBackSide = LitScene; // faces away: only the wall is lit
TEST_F(QuadLightBackSide, Pathtracer)
{
  ANARILight light = newLight("quad");
  setVec3(light, "position", {-1.f, -1.5f, 3.f});
  setVec3(light, "edge1", {2.f, 0.f, 0.f});
  setVec3(light, "edge2", {0.f, 1.5f, 0.f});
  setFloat(light, "radiance", 4.f);
  setString(light, "side", "back");
  expectReference(scene({committed(light)}));
}

using RingLight = LitScene;
TEST_F(RingLight, Pathtracer)
{
  ANARILight light = newLight("ring");
  setVec3(light, "position", {0.f, -0.5f, 3.f});
  setVec3(light, "direction", {0.f, 0.2f, -1.f});
  setFloat(light, "radius", 0.8f);
  setFloat(light, "innerRadius", 0.5f);
  setFloat(light, "openingAngle", 1.6f);
  setFloat(light, "falloffAngle", 0.3f);
  setFloat(light, "intensity", 20.f);
  expectReference(scene({committed(light)}));
}

using HdriLight = LitScene; // a sky gradient with a small bright sun
TEST_F(HdriLight, Pathtracer)
{
  constexpr uint32_t width = 32, height = 16;
  std::vector<Vec3> texels(width * height);
  for (uint32_t y = 0; y < height; y++) {
    for (uint32_t x = 0; x < width; x++) {
      // Row 0 is towards `up` (+z): bright blue above, dark ground below.
      const float sky = y < height / 2 ? 1.f - float(y) / height : 0.1f;
      texels[y * width + x] = {0.3f * sky, 0.45f * sky, 0.8f * sky};
    }
  }
  texels[3 * width + 10] = {60.f, 55.f, 45.f};
  ANARILight light = newLight("hdri");
  setObject(light,
      "radiance",
      ANARI_ARRAY2D,
      newArray2D(ANARI_FLOAT32_VEC3, texels.data(), width, height));
  setVec3(light, "up", {0.f, 0.f, 1.f});
  setVec3(light, "direction", {0.f, 1.f, 0.f});
  expectReference(scene({committed(light)}));
}

using AmbientLight = LitScene; // the renderer's ambient light alone
TEST_F(AmbientLight, Pathtracer)
{
  expectReference(scene({}), 0.8f);
}

using TwoLights = LitScene; // a bright and a dim light, chosen by power
TEST_F(TwoLights, Pathtracer)
{
  ANARILight sun = newLight("directional");
  setVec3(sun, "direction", {-0.6f, 0.5f, -1.f});
  setFloat(sun, "irradiance", 2.f);
  ANARILight fill = newLight("point");
  setVec3(fill, "position", {-1.5f, -1.5f, 1.5f});
  setFloat(fill, "intensity", 1.f);
  setVec3(fill, "color", {0.4f, 0.6f, 1.f});
  expectReference(scene({committed(sun), committed(fill)}));
}

} // namespace
