// Renders with known answers: exact depths, coverage fractions and the
// raycast renderer's eye-light shading, for every surface geometry.
#include "AnalyticScene.h"

#include <cmath>

namespace {

const float kEyeZ5[3] = {0, 0, 5};
const float kLookDown[3] = {0, 0, -1};

class SurfaceAnalytic : public AnalyticTest
{
 protected:
  ANARISurface unitSphere(uint32_t id = ~0u)
  {
    return surface(geometry("sphere", {0, 0, 0}), matte(1, 1, 1), id);
  }
  // A square [-s, s]^2 in the plane z = 0 facing +z, as two triangles.
  ANARIGeometry square(float s)
  {
    ANARIGeometry g =
        geometry("triangle", {-s, -s, 0, s, -s, 0, s, s, 0, -s, s, 0});
    setArray(g,
        "primitive.index",
        array1D(std::vector<uint32_t>{0, 1, 2, 0, 2, 3}, ANARI_UINT32_VEC3));
    return g;
  }
  // A 20 x 20 quad tilted from the view direction (-z) so that the cosine
  // between its normal and the rays is `cosine`.
  ANARIGeometry tiltedPlane(float cosine)
  {
    const float sine = std::sqrt(1.f - cosine * cosine);
    return geometry("quad",
        {-10,
            -10 * cosine,
            -10 * sine,
            10,
            -10 * cosine,
            -10 * sine,
            10,
            10 * cosine,
            10 * sine,
            -10,
            10 * cosine,
            10 * sine});
  }
  RenderedImage renderOrthographic(ANARIWorld w, float height, uint32_t size)
  {
    ANARICamera c = orthographic(kEyeZ5, kLookDown, height);
    ANARIRenderer r = renderer("raycast");
    RenderedImage image = render(w, c, r, size, size);
    anariRelease(m_device, c);
    anariRelease(m_device, r);
    return image;
  }
};

TEST_F(SurfaceAnalytic, SphereDepthAtTheCentrePixelIsExact)
{
  ANARIWorld w = world({unitSphere()});
  ANARICamera c = perspective(kEyeZ5, kLookDown, 0.5f);
  ANARIRenderer r = renderer("raycast");
  RenderedImage image = render(w, c, r, 65, 65);
  // The centre pixel's ray runs along the axis: depth = 5 - radius.
  EXPECT_NEAR(image.depthAt(32, 32), 4.f, 1e-5f);
  // The background's depth is +infinity (not 0, not 1e30).
  EXPECT_TRUE(std::isinf(image.depthAt(0, 0)) && image.depthAt(0, 0) > 0);
  anariRelease(m_device, w);
  anariRelease(m_device, c);
  anariRelease(m_device, r);
  EXPECT_TRUE(problems().empty());
}

TEST_F(SurfaceAnalytic, SphereCoverageMatchesItsProjectedArea)
{
  ANARIWorld w = world({unitSphere()});
  RenderedImage image = renderOrthographic(w, 4.f, 256);
  size_t covered = 0;
  for (float d : image.depth)
    covered += std::isfinite(d) ? 1 : 0;
  // pi r^2 over a 4 x 4 view; the boundary pixels bound the error.
  const double expected = M_PI / 16.0;
  EXPECT_NEAR(double(covered) / double(image.depth.size()), expected, 0.002);
  // Orthographic depth over the sphere is 5 - sqrt(1 - x^2 - y^2).
  const uint32_t x = 160, y = 128; // x = 0.5 + 1/64 in world units
  const float wx = (float(x) + 0.5f) / 256.f * 4.f - 2.f;
  EXPECT_NEAR(image.depthAt(x, y), 5.f - std::sqrt(1.f - wx * wx), 1e-4f);
  anariRelease(m_device, w);
}

TEST_F(SurfaceAnalytic, OrthographicPlaneHasConstantDepth)
{
  ANARIWorld w = world({surface(square(10.f), matte(1, 1, 1))});
  RenderedImage image = renderOrthographic(w, 4.f, 32);
  for (float d : image.depth)
    ASSERT_NEAR(d, 5.f, 1e-5f);
  anariRelease(m_device, w);
}

TEST_F(SurfaceAnalytic, RaycastColorOfAFacingPlaneIsItsBaseColor)
{
  ANARIWorld w = world({surface(square(10.f), matte(0.2f, 0.4f, 0.6f))});
  RenderedImage image = renderOrthographic(w, 4.f, 16);
  // Facing the camera, cos = 1: c * (r * 1 + (1 - r)) = c for any r.
  for (uint32_t i = 0; i < 16 * 16; i++) {
    ASSERT_NEAR(image.color[4 * i + 0], 0.2f, 1e-6f);
    ASSERT_NEAR(image.color[4 * i + 1], 0.4f, 1e-6f);
    ASSERT_NEAR(image.color[4 * i + 2], 0.6f, 1e-6f);
    ASSERT_EQ(image.color[4 * i + 3], 1.f);
  }
  anariRelease(m_device, w);
}

TEST_F(SurfaceAnalytic, RaycastEyeLightFollowsTheBlendRatio)
{
  const float c60 = 0.5f;
  ANARIGeometry g = tiltedPlane(c60);
  ANARIWorld w = world({surface(g, matte(0.8f, 0.8f, 0.8f))});
  ANARICamera c = orthographic(kEyeZ5, kLookDown, 2.f);
  ANARIRenderer r = renderer("raycast");
  const float ratio = 0.25f;
  anariSetParameter(m_device, r, "eyeLightBlendRatio", ANARI_FLOAT32, &ratio);
  anariCommitParameters(m_device, r);
  RenderedImage image = render(w, c, r, 8, 8);
  const float expected = 0.8f * (ratio * c60 + (1.f - ratio));
  EXPECT_NEAR(image.pixel(4, 4)[0], expected, 1e-5f);
  anariRelease(m_device, w);
  anariRelease(m_device, c);
  anariRelease(m_device, r);
  EXPECT_TRUE(problems().empty());
}

// A renderer parameter beyond its declared range is clamped to the nearest
// bound (with a warning): eyeLightBlendRatio 5 renders as 1, -3 as 0.
TEST_F(SurfaceAnalytic, RaycastClampsAnEyeLightBlendRatioOutOfRange)
{
  const float c60 = 0.5f;
  ANARIGeometry g = tiltedPlane(c60);
  ANARIWorld w = world({surface(g, matte(0.8f, 0.8f, 0.8f))});
  ANARICamera c = orthographic(kEyeZ5, kLookDown, 2.f);
  for (const float ratio : {5.f, -3.f}) {
    ANARIRenderer r = renderer("raycast");
    anariSetParameter(m_device, r, "eyeLightBlendRatio", ANARI_FLOAT32, &ratio);
    anariCommitParameters(m_device, r);
    RenderedImage image = render(w, c, r, 8, 8);
    const float clamped = ratio > 1.f ? 1.f : 0.f;
    const float expected = 0.8f * (clamped * c60 + (1.f - clamped));
    EXPECT_NEAR(image.pixel(4, 4)[0], expected, 1e-6f) << ratio;
    anariRelease(m_device, r);
  }
  bool warned = false;
  for (const StatusMessage &problem : problems())
    warned |= problem.text.find(
                  "'eyeLightBlendRatio' (5) must be in [0, 1]; "
                  "clamped to 1")
              != std::string::npos;
  EXPECT_TRUE(warned);
  anariRelease(m_device, w);
  anariRelease(m_device, c);
}

TEST_F(SurfaceAnalytic, IdChannels)
{
  ANARIWorld w = world({surface(square(10.f), matte(1, 1, 1), 42)});
  RenderedImage image = renderOrthographic(w, 4.f, 16);
  // Triangle 0 covers the lower-right half, triangle 1 the upper-left.
  EXPECT_EQ(image.primitiveId[15], 0u);
  EXPECT_EQ(image.primitiveId[15 * 16], 1u);
  EXPECT_EQ(image.objectId[0], 42u);
  EXPECT_EQ(image.instanceId[0], ~0u); // placed in the world directly
  anariRelease(m_device, w);
}

TEST_F(SurfaceAnalytic, InstanceTransformArrayPlacesTheGroupManyTimes)
{
  ANARIGroup group = anariNewGroup(m_device);
  ANARISurface s = unitSphere();
  setArray(group,
      "surface",
      anariNewArray1D(m_device, &s, nullptr, nullptr, ANARI_SURFACE, 1));
  anariRelease(m_device, s);
  anariCommitParameters(m_device, group);
  ANARIInstance instance = anariNewInstance(m_device, "transform");
  anariSetParameter(m_device, instance, "group", ANARI_GROUP, &group);
  anariRelease(m_device, group);
  // Two placements: translated to x = -2 and x = +2; ids 5 and 6.
  std::vector<float> transforms(32, 0.f);
  for (int m = 0; m < 2; m++) {
    transforms[16 * m + 0] = transforms[16 * m + 5] = 1.f;
    transforms[16 * m + 10] = transforms[16 * m + 15] = 1.f;
    transforms[16 * m + 12] = m == 0 ? -2.f : 2.f;
  }
  setArray(instance, "transform", array1D(transforms, ANARI_FLOAT32_MAT4));
  setArray(instance, "id", array1D(std::vector<uint32_t>{5, 6}, ANARI_UINT32));
  anariCommitParameters(m_device, instance);
  ANARIWorld w = anariNewWorld(m_device);
  setArray(w,
      "instance",
      anariNewArray1D(
          m_device, &instance, nullptr, nullptr, ANARI_INSTANCE, 1));
  anariRelease(m_device, instance);
  anariCommitParameters(m_device, w);

  RenderedImage image = renderOrthographic(w, 8.f, 64); // 1/8 unit pixels
  // Pixel centres 1/16 off each sphere's centre in x and y.
  const float offset = 1.f / 16.f;
  const float expected = 5.f - std::sqrt(1.f - 2.f * offset * offset);
  EXPECT_NEAR(image.depthAt(15, 32), expected, 1e-4f);
  EXPECT_NEAR(image.depthAt(48, 32), expected, 1e-4f);
  EXPECT_EQ(image.instanceId[32 * 64 + 15], 5u);
  EXPECT_EQ(image.instanceId[32 * 64 + 48], 6u);
  EXPECT_TRUE(std::isinf(image.depthAt(32, 32))); // nothing at the centre
  float bounds[6] = {};
  EXPECT_EQ(anariGetProperty(m_device,
                w,
                "bounds",
                ANARI_FLOAT32_BOX3,
                bounds,
                sizeof(bounds),
                ANARI_WAIT),
      1);
  EXPECT_NEAR(bounds[0], -3.f, 1e-5f);
  EXPECT_NEAR(bounds[3], 3.f, 1e-5f);
  anariRelease(m_device, w);
  EXPECT_TRUE(problems().empty());
}

TEST_F(SurfaceAnalytic, CylinderCapsCloseTheEnds)
{
  for (const char *caps : {"none", "both"}) {
    // A cylinder along z from z = -1 to z = 1, seen end-on.
    ANARIGeometry g = geometry("cylinder", {0, 0, -1, 0, 0, 1});
    const float radius = 0.5f;
    anariSetParameter(m_device, g, "radius", ANARI_FLOAT32, &radius);
    anariSetParameter(m_device, g, "caps", ANARI_STRING, caps);
    ANARIWorld w = world({surface(g, matte(1, 1, 1))});
    RenderedImage image = renderOrthographic(w, 2.f, 33);
    const float centre = image.depthAt(16, 16);
    if (std::string(caps) == "both")
      EXPECT_NEAR(centre, 4.f, 1e-5f); // the near cap at z = 1
    else
      EXPECT_TRUE(std::isinf(centre)); // straight through the open tube
    anariRelease(m_device, w);
  }
  EXPECT_TRUE(problems().empty());
}

TEST_F(SurfaceAnalytic, ConeSideFromTheSide)
{
  // A cone along x from radius 1 at x = -1 to radius 0 at x = 1, seen along
  // -z: at x = 0 the radius is 0.5, so depth = 5 - 0.5.
  ANARIGeometry g = geometry("cone", {-1, 0, 0, 1, 0, 0});
  setArray(
      g, "vertex.radius", array1D(std::vector<float>{1.f, 0.f}, ANARI_FLOAT32));
  ANARIWorld w = world({surface(g, matte(1, 1, 1))});
  RenderedImage image = renderOrthographic(w, 4.f, 65);
  EXPECT_NEAR(image.depthAt(32, 32), 4.5f, 1e-4f);
  anariRelease(m_device, w);
  EXPECT_TRUE(problems().empty());
}

TEST_F(SurfaceAnalytic, CurveIsARoundTube)
{
  ANARIGeometry g = geometry("curve", {-1, 0, 0, 0, 0, 0, 1, 0, 0});
  const float radius = 0.25f;
  anariSetParameter(m_device, g, "radius", ANARI_FLOAT32, &radius);
  ANARIWorld w = world({surface(g, matte(1, 1, 1))});
  RenderedImage image = renderOrthographic(w, 4.f, 65);
  EXPECT_NEAR(image.depthAt(24, 32), 4.75f, 1e-3f);
  EXPECT_EQ(image.primitiveId[32 * 65 + 24], 0u); // first segment
  EXPECT_EQ(image.primitiveId[32 * 65 + 40], 1u); // second segment
  anariRelease(m_device, w);
  EXPECT_TRUE(problems().empty());
}

} // namespace

namespace {

// Changing an array's contents through map/unmap reaches the next frame
// without recommitting the geometry; only that geometry's group rebuilds.
TEST_F(SurfaceAnalytic, UnmappedArrayChangesReachTheNextFrame)
{
  ANARIGeometry g = anariNewGeometry(m_device, "sphere");
  ANARIArray1D positions = anariNewArray1D(
      m_device, nullptr, nullptr, nullptr, ANARI_FLOAT32_VEC3, 1);
  auto *p = (float *)anariMapArray(m_device, positions);
  p[0] = p[1] = p[2] = 0.f;
  anariUnmapArray(m_device, positions);
  anariSetParameter(m_device, g, "vertex.position", ANARI_ARRAY1D, &positions);
  ANARIWorld w = world({surface(g, matte(1, 1, 1))});
  ANARICamera c = orthographic(kEyeZ5, kLookDown, 8.f);
  ANARIRenderer r = renderer("raycast");
  RenderedImage before = render(w, c, r, 32, 32);
  // Pixel centres sit 1/8 off the sphere's centre in x and y.
  const float bulge = std::sqrt(1.f - 2.f / 64.f);
  EXPECT_NEAR(before.depthAt(16, 16), 5.f - bulge, 1e-4f);
  // Move the sphere to x = 2 (pixel 24) and 1 closer to the camera.
  p = (float *)anariMapArray(m_device, positions);
  p[0] = 2.f;
  p[2] = 1.f;
  anariUnmapArray(m_device, positions);
  RenderedImage after = render(w, c, r, 32, 32);
  EXPECT_TRUE(std::isinf(after.depthAt(16, 16)));
  EXPECT_NEAR(after.depthAt(24, 16), 4.f - bulge, 1e-4f);
  float bounds[6] = {};
  anariGetProperty(m_device,
      w,
      "bounds",
      ANARI_FLOAT32_BOX3,
      bounds,
      sizeof(bounds),
      ANARI_WAIT);
  EXPECT_NEAR(bounds[0], 1.f, 1e-5f);
  EXPECT_NEAR(bounds[3], 3.f, 1e-5f);
  anariRelease(m_device, positions);
  anariRelease(m_device, w);
  anariRelease(m_device, c);
  anariRelease(m_device, r);
  EXPECT_TRUE(problems().empty());
}

} // namespace
