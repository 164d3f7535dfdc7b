// Every renderer subtype declares its parameters to introspection, with
// types and defaults, and the defaults are what the renderer uses: setting
// each to its declared default leaves the image exactly as it was.
#include "DeviceTestSupport.h"

#include <cstring>

namespace {

using RendererParameters = PrismDeviceTest;

TEST_F(RendererParameters, DeclaredDefaultsAreTheDefaults)
{
  // A lit sphere in front of a perspective camera.
  ANARIGeometry sphere = anariNewGeometry(m_device, "sphere");
  const float center[3] = {0, 0, 0}, radius = 1.f;
  ANARIArray1D positions = anariNewArray1D(
      m_device, center, nullptr, nullptr, ANARI_FLOAT32_VEC3, 1);
  anariSetParameter(
      m_device, sphere, "vertex.position", ANARI_ARRAY1D, &positions);
  anariSetParameter(m_device, sphere, "radius", ANARI_FLOAT32, &radius);
  anariCommitParameters(m_device, sphere);
  ANARIMaterial material = anariNewMaterial(m_device, "physicallyBased");
  anariCommitParameters(m_device, material);
  ANARISurface surface = anariNewSurface(m_device);
  anariSetParameter(m_device, surface, "geometry", ANARI_GEOMETRY, &sphere);
  anariSetParameter(m_device, surface, "material", ANARI_MATERIAL, &material);
  anariCommitParameters(m_device, surface);
  ANARILight light = anariNewLight(m_device, "directional");
  const float direction[3] = {-1, -1, -1};
  anariSetParameter(
      m_device, light, "direction", ANARI_FLOAT32_VEC3, direction);
  anariCommitParameters(m_device, light);
  ANARIWorld world = anariNewWorld(m_device);
  ANARIArray1D surfaces =
      anariNewArray1D(m_device, &surface, nullptr, nullptr, ANARI_SURFACE, 1);
  ANARIArray1D lights =
      anariNewArray1D(m_device, &light, nullptr, nullptr, ANARI_LIGHT, 1);
  anariSetParameter(m_device, world, "surface", ANARI_ARRAY1D, &surfaces);
  anariSetParameter(m_device, world, "light", ANARI_ARRAY1D, &lights);
  anariCommitParameters(m_device, world);
  ANARICamera camera = anariNewCamera(m_device, "perspective");
  const float eye[3] = {0, 0, 4}, dir[3] = {0, 0, -1};
  anariSetParameter(m_device, camera, "position", ANARI_FLOAT32_VEC3, eye);
  anariSetParameter(m_device, camera, "direction", ANARI_FLOAT32_VEC3, dir);
  anariCommitParameters(m_device, camera);

  auto render = [&](ANARIRenderer renderer) {
    ANARIFrame frame = newFrameOf(world, camera, renderer, 16, 16);
    anariRenderFrame(m_device, frame);
    std::vector<float> image = colorPixels(frame);
    anariRelease(m_device, frame);
    return image;
  };

  int renderers = 0, defaults = 0;
  auto **subtypes = anariGetObjectSubtypes(m_device, ANARI_RENDERER);
  ASSERT_NE(subtypes, nullptr);
  for (auto **s = subtypes; *s; s++, renderers++) {
    SCOPED_TRACE(*s);
    ANARIRenderer plain = anariNewRenderer(m_device, *s);
    anariCommitParameters(m_device, plain);
    ANARIRenderer explicitDefaults = anariNewRenderer(m_device, *s);
    auto *params = (const ANARIParameter *)anariGetObjectInfo(
        m_device, ANARI_RENDERER, *s, "parameter", ANARI_PARAMETER_LIST);
    ASSERT_NE(params, nullptr);
    for (; params->name; params++) {
      const void *value = anariGetParameterInfo(m_device,
          ANARI_RENDERER,
          *s,
          params->name,
          params->type,
          "default",
          params->type);
      if (!value)
        continue;
      anariSetParameter(
          m_device, explicitDefaults, params->name, params->type, value);
      defaults++;
    }
    anariCommitParameters(m_device, explicitDefaults);
    const std::vector<float> a = render(plain), b = render(explicitDefaults);
    ASSERT_EQ(a.size(), 16u * 16u * 4u);
    EXPECT_EQ(a, b);
    anariRelease(m_device, plain);
    anariRelease(m_device, explicitDefaults);
  }
  EXPECT_GE(renderers, 5);
  EXPECT_GE(defaults, 5 * 4); // each: its own and the inherited ones
  for (ANARIObject o : {(ANARIObject)world,
           (ANARIObject)camera,
           (ANARIObject)surfaces,
           (ANARIObject)lights,
           (ANARIObject)positions,
           (ANARIObject)surface,
           (ANARIObject)light,
           (ANARIObject)material,
           (ANARIObject)sphere})
    anariRelease(m_device, o);
  EXPECT_TRUE(problems().empty());
}

// hdAnari finds its convergence control by introspection: every renderer
// (default included) lists sampleLimit (INT32, default 0); the frame's
// numSamples property is checked in unit::introspection.
TEST_F(RendererParameters, ConvergenceControlsAreDeclared)
{
  auto **subtypes = anariGetObjectSubtypes(m_device, ANARI_RENDERER);
  ASSERT_NE(subtypes, nullptr);
  int renderers = 0;
  for (auto **s = subtypes; *s; s++, renderers++) {
    SCOPED_TRACE(*s);
    bool listed = false;
    auto *parameters = (const ANARIParameter *)anariGetObjectInfo(
        m_device, ANARI_RENDERER, *s, "parameter", ANARI_PARAMETER_LIST);
    for (auto *p = parameters; p && p->name; p++)
      listed = listed || std::strcmp(p->name, "sampleLimit") == 0;
    EXPECT_TRUE(listed);
    auto *fallback = (const int32_t *)anariGetParameterInfo(m_device,
        ANARI_RENDERER,
        *s,
        "sampleLimit",
        ANARI_INT32,
        "default",
        ANARI_INT32);
    ASSERT_NE(fallback, nullptr);
    EXPECT_EQ(*fallback, 0);
  }
  EXPECT_GE(renderers, 5);
  EXPECT_TRUE(problems().empty());
}

} // namespace
