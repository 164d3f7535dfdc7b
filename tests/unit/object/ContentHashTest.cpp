// Object::contentHash and World::declaredLightsHash: equal for worlds built
// alike, different when anything that shows in the image differs, and
// current after every kind of change (a commit, an unmapped array, a
// recommitted child).
#include "../ObjectTestFixture.h"
#include "world/World.h"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

namespace prism {
namespace {

class ContentHashTest : public testing::ObjectTestFixture
{
 protected:
  // One sphere of a matte material and one directional light.
  struct Scene
  {
    ANARIWorld world;
    ANARIMaterial material;
    ANARIArray1D positions;
    ANARILight light;
  };

  Scene scene(float3 color, float3 direction = {0.f, -1.f, 0.f})
  {
    Scene s;
    const float3 center{1.f, 2.f, 3.f};
    s.positions = managedArray(ANARI_FLOAT32_VEC3, &center, 1);
    ANARIGeometry sphere = keep(m_device.newGeometry("sphere"));
    m_device.setParameter(
        sphere, "vertex.position", ANARI_ARRAY1D, &s.positions);
    m_device.commitParameters(sphere);
    s.material = keep(m_device.newMaterial("matte"));
    m_device.setParameter(s.material, "color", ANARI_FLOAT32_VEC3, &color);
    m_device.commitParameters(s.material);
    ANARISurface surface = keep(m_device.newSurface());
    m_device.setParameter(surface, "geometry", ANARI_GEOMETRY, &sphere);
    m_device.setParameter(surface, "material", ANARI_MATERIAL, &s.material);
    m_device.commitParameters(surface);
    s.light = keep(m_device.newLight("directional"));
    m_device.setParameter(s.light, "direction", ANARI_FLOAT32_VEC3, &direction);
    m_device.commitParameters(s.light);
    s.world = keep(m_device.newWorld());
    ANARIArray1D surfaces = managedArray(ANARI_SURFACE, &surface, 1);
    ANARIArray1D lights = managedArray(ANARI_LIGHT, &s.light, 1);
    m_device.setParameter(s.world, "surface", ANARI_ARRAY1D, &surfaces);
    m_device.setParameter(s.world, "light", ANARI_ARRAY1D, &lights);
    m_device.commitParameters(s.world);
    return s;
  }
  World &committed(ANARIWorld handle)
  {
    auto &world = *(World *)m_device.lookup(handle);
    m_device.flushCommitsAndRefresh(world);
    return world;
  }
  uint64_t contentHash(ANARIWorld world)
  {
    return committed(world).contentHash();
  }
  uint64_t lightsHash(ANARIWorld world)
  {
    return committed(world).declaredLightsHash();
  }
};

TEST_F(ContentHashTest, WorldsBuiltAlikeHashAlike)
{
  const Scene a = scene({0.8f, 0.2f, 0.1f});
  const Scene b = scene({0.8f, 0.2f, 0.1f});
  // Names and pointers differ by process; neither shows in the image.
  m_device.setParameter(b.world, "name", ANARI_STRING, "another name");
  int here = 0, there = 0;
  m_device.setParameter(a.world, "mpiCommunicator", ANARI_VOID_POINTER, &here);
  m_device.setParameter(b.world, "mpiCommunicator", ANARI_VOID_POINTER, &there);
  m_device.commitParameters(a.world);
  m_device.commitParameters(b.world);
  EXPECT_EQ(contentHash(a.world), contentHash(b.world));
  EXPECT_EQ(lightsHash(a.world), lightsHash(b.world));
}

TEST_F(ContentHashTest, AnotherMaterialColorOrLightHashesOtherwise)
{
  const Scene a = scene({0.8f, 0.2f, 0.1f});
  const Scene redder = scene({0.9f, 0.2f, 0.1f});
  const Scene tilted = scene({0.8f, 0.2f, 0.1f}, {0.f, -1.f, 0.1f});
  EXPECT_NE(contentHash(a.world), contentHash(redder.world));
  EXPECT_NE(contentHash(a.world), contentHash(tilted.world));
  // The lights alone: the same light, another material, hashes alike.
  EXPECT_EQ(lightsHash(a.world), lightsHash(redder.world));
  EXPECT_NE(lightsHash(a.world), lightsHash(tilted.world));
}

TEST_F(ContentHashTest, FollowsCommitsOfChildrenAndUnmappedArrays)
{
  const Scene s = scene({0.8f, 0.2f, 0.1f});
  const uint64_t original = contentHash(s.world);
  const uint64_t originalLights = lightsHash(s.world);

  const float3 blue{0.1f, 0.2f, 0.8f};
  m_device.setParameter(s.material, "color", ANARI_FLOAT32_VEC3, &blue);
  m_device.commitParameters(s.material);
  const uint64_t recolored = contentHash(s.world);
  EXPECT_NE(recolored, original);
  EXPECT_EQ(lightsHash(s.world), originalLights);

  // One vertex moved, in place: the array's bytes are hashed again.
  auto *center = (float3 *)m_device.mapArray(s.positions);
  center->x += 0.25f;
  m_device.unmapArray(s.positions);
  const uint64_t moved = contentHash(s.world);
  EXPECT_NE(moved, recolored);

  const float3 direction{1.f, -1.f, 0.f};
  m_device.setParameter(s.light, "direction", ANARI_FLOAT32_VEC3, &direction);
  m_device.commitParameters(s.light);
  EXPECT_NE(lightsHash(s.world), originalLights);
  EXPECT_NE(contentHash(s.world), moved);

  // Back as it was: the hash is a function of the contents alone.
  const float3 red{0.8f, 0.2f, 0.1f};
  const float3 down{0.f, -1.f, 0.f};
  m_device.setParameter(s.material, "color", ANARI_FLOAT32_VEC3, &red);
  m_device.commitParameters(s.material);
  m_device.setParameter(s.light, "direction", ANARI_FLOAT32_VEC3, &down);
  m_device.commitParameters(s.light);
  center = (float3 *)m_device.mapArray(s.positions);
  center->x -= 0.25f;
  m_device.unmapArray(s.positions);
  EXPECT_EQ(contentHash(s.world), original);
  EXPECT_EQ(lightsHash(s.world), originalLights);
}

// A camera's or renderer's hash (the data-parallel device compares them)
// depends on the committed values, not on the order they were set in, nor
// on values set and overwritten before the commit.
TEST_F(ContentHashTest, CameraAndRendererHashTheirValuesInAnyOrder)
{
  const float3 position{1.f, 2.f, 3.f}, elsewhere{1.f, 2.f, 4.f};
  const float3 up{0.f, 1.f, 0.f};
  const float fovy = 0.7f, radiance = 0.5f, otherRadiance = 2.f;
  const float4 background{0.1f, 0.2f, 0.3f, 1.f};
  ANARICamera a = keep(m_device.newCamera("perspective"));
  m_device.setParameter(a, "position", ANARI_FLOAT32_VEC3, &position);
  m_device.setParameter(a, "up", ANARI_FLOAT32_VEC3, &up);
  m_device.setParameter(a, "fovy", ANARI_FLOAT32, &fovy);
  m_device.commitParameters(a);
  ANARICamera b = keep(m_device.newCamera("perspective"));
  m_device.setParameter(b, "fovy", ANARI_FLOAT32, &fovy);
  m_device.setParameter(b, "position", ANARI_FLOAT32_VEC3, &elsewhere);
  m_device.setParameter(b, "up", ANARI_FLOAT32_VEC3, &up);
  m_device.setParameter(b, "position", ANARI_FLOAT32_VEC3, &position);
  m_device.commitParameters(b);
  ANARIRenderer r = keep(m_device.newRenderer("pathtracer"));
  m_device.setParameter(r, "background", ANARI_FLOAT32_VEC4, &background);
  m_device.setParameter(r, "ambientRadiance", ANARI_FLOAT32, &radiance);
  m_device.commitParameters(r);
  ANARIRenderer s = keep(m_device.newRenderer("pathtracer"));
  m_device.setParameter(s, "ambientRadiance", ANARI_FLOAT32, &otherRadiance);
  m_device.setParameter(s, "ambientRadiance", ANARI_FLOAT32, &radiance);
  m_device.setParameter(s, "background", ANARI_FLOAT32_VEC4, &background);
  m_device.commitParameters(s);
  auto hash = [&](ANARIObject handle) {
    Object &object = *m_device.lookup(handle);
    m_device.flushCommitsAndRefresh(object);
    return object.contentHash();
  };
  EXPECT_EQ(hash(a), hash(b));
  EXPECT_EQ(hash(r), hash(s));
  EXPECT_NE(hash(a), hash(r));

  // Another value hashes otherwise, and back again hashes as before.
  const uint64_t original = hash(b);
  m_device.setParameter(b, "position", ANARI_FLOAT32_VEC3, &elsewhere);
  m_device.commitParameters(b);
  EXPECT_NE(hash(b), original);
  m_device.setParameter(b, "position", ANARI_FLOAT32_VEC3, &position);
  m_device.commitParameters(b);
  EXPECT_EQ(hash(b), original);
  m_device.setParameter(s, "ambientRadiance", ANARI_FLOAT32, &otherRadiance);
  m_device.commitParameters(s);
  EXPECT_NE(hash(r), hash(s));
}

} // namespace
} // namespace prism
