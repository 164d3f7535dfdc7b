// World::shareEmitters, shareLights and keepOwnEmitters, what the
// data-parallel device's pathtracer mode uses so that every process samples
// every process's emissive surfaces and declared lights: the shared
// emitters follow the declared lights, the world's own surfaces name their
// place among them, light selection is rebuilt, and the world goes back to
// its own lights on request or when it places its lights anew.
#include "../ObjectTestFixture.h"
#include "light/EmissiveSurface.h"
#include "world/World.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <vector>

namespace prism {
namespace {

class SharedEmittersTest : public testing::ObjectTestFixture
{
 protected:
  // A glowing triangle placed in the world directly and a directional
  // light.
  ANARIWorld glowingWorld()
  {
    const float3 corners[3] = {
        {0.f, 0.f, 0.f}, {2.f, 0.f, 0.f}, {0.f, 0.f, 2.f}};
    ANARIGeometry triangle = keep(m_device.newGeometry("triangle"));
    ANARIArray1D positions = managedArray(ANARI_FLOAT32_VEC3, corners, 3);
    m_device.setParameter(
        triangle, "vertex.position", ANARI_ARRAY1D, &positions);
    m_device.commitParameters(triangle);
    ANARIMaterial material = keep(m_device.newMaterial("physicallyBased"));
    const float3 glow{4.f, 3.f, 2.f};
    m_device.setParameter(material, "emissive", ANARI_FLOAT32_VEC3, &glow);
    m_device.commitParameters(material);
    ANARISurface surface = keep(m_device.newSurface());
    m_device.setParameter(surface, "geometry", ANARI_GEOMETRY, &triangle);
    m_device.setParameter(surface, "material", ANARI_MATERIAL, &material);
    m_device.commitParameters(surface);
    ANARILight sun = keep(m_device.newLight("directional"));
    m_device.commitParameters(sun);
    ANARIWorld world = keep(m_device.newWorld());
    ANARIArray1D surfaces = managedArray(ANARI_SURFACE, &surface, 1);
    ANARIArray1D lights = managedArray(ANARI_LIGHT, &sun, 1);
    m_device.setParameter(world, "surface", ANARI_ARRAY1D, &surfaces);
    m_device.setParameter(world, "light", ANARI_ARRAY1D, &lights);
    m_device.commitParameters(world);
    return world;
  }
  World &committed(ANARIWorld handle)
  {
    auto &world = *(World *)m_device.lookup(handle);
    m_device.flushCommitsAndRefresh(world);
    return world;
  }
  // Another process's emitter: a triangle far from this world's.
  static std::unique_ptr<PlacedLight> remoteEmitter()
  {
    EmitterShape shape;
    shape.triangles = {{5.f, 0.f, 0.f}, {6.f, 0.f, 0.f}, {5.f, 1.f, 0.f}};
    return std::make_unique<EmissiveSurface>(shape, float3{1.f, 1.f, 1.f});
  }
};

TEST_F(SharedEmittersTest, SharedEmittersFollowTheDeclaredLights)
{
  World &world = committed(glowingWorld());
  ASSERT_EQ(world.declaredLightCount(), 1u);
  ASSERT_EQ(world.ownEmitterCount(), 1u);
  ASSERT_EQ(world.lights().size(), 2u);
  EXPECT_EQ(world.emitterLight(0, 0), 1);
  EXPECT_FALSE(world.sharesEmitters());
  const float sunAlone = world.lightSelector().probability(0);

  // Rank 0's emitter first, then this world's own (a copy, as sent).
  std::vector<std::unique_ptr<PlacedLight>> emitters;
  emitters.push_back(remoteEmitter());
  const EmissiveSurface &own = world.ownEmitter(0);
  emitters.push_back(
      std::make_unique<EmissiveSurface>(own.shape(), own.radiance()));
  world.shareEmitters(std::move(emitters), 1, 100.f);
  EXPECT_TRUE(world.sharesEmitters());
  ASSERT_EQ(world.lights().size(), 3u);
  EXPECT_EQ(world.declaredLightCount(), 1u);
  EXPECT_EQ(world.ownEmitterCount(), 1u);
  EXPECT_EQ(world.ownEmitter(0).radiance().x, 4.f);
  EXPECT_EQ(world.emitterLight(0, 0), 2);
  // A larger scene: the light at infinity carries more power through it.
  EXPECT_GT(world.lightSelector().probability(0), sunAlone);
  float total = 0.f;
  for (size_t i = 0; i < world.lights().size(); i++)
    total += world.lightSelector().probability(i);
  EXPECT_NEAR(total, 1.f, 1e-5f);

  world.keepOwnEmitters();
  EXPECT_FALSE(world.sharesEmitters());
  ASSERT_EQ(world.lights().size(), 2u);
  EXPECT_EQ(world.emitterLight(0, 0), 1);
  EXPECT_EQ(world.lightSelector().probability(0), sunAlone);
}

TEST_F(SharedEmittersTest, EmittersThatCannotHoldTheOwnOnesAreRefused)
{
  World &world = committed(glowingWorld());
  std::vector<std::unique_ptr<PlacedLight>> emitters;
  emitters.push_back(remoteEmitter());
  world.shareEmitters(std::move(emitters), 1, 10.f); // no room for its own
  EXPECT_FALSE(world.sharesEmitters());
  ASSERT_EQ(world.lights().size(), 2u);
  EXPECT_EQ(world.emitterLight(0, 0), 1);
}

TEST_F(SharedEmittersTest, PlacingTheLightsAnewEndsTheSharing)
{
  const ANARIWorld handle = glowingWorld();
  World &world = committed(handle);
  std::vector<std::unique_ptr<PlacedLight>> emitters;
  const EmissiveSurface &own = world.ownEmitter(0);
  emitters.push_back(
      std::make_unique<EmissiveSurface>(own.shape(), own.radiance()));
  emitters.push_back(remoteEmitter());
  world.shareEmitters(std::move(emitters), 0, 10.f);
  ASSERT_TRUE(world.sharesEmitters());
  EXPECT_EQ(world.emitterLight(0, 0), 1);
  m_device.commitParameters(handle);
  World &again = committed(handle);
  EXPECT_FALSE(again.sharesEmitters());
  EXPECT_EQ(again.lights().size(), 2u);
  EXPECT_EQ(again.emitterLight(0, 0), 1);
}

// World::shareLights: other processes' declared lights stand for the
// world's own (two of them here, where it declares one), its own surface
// names its place after them, rays can reach what can be reached, and
// keepOwnEmitters brings back the world's own sun.
TEST_F(SharedEmittersTest, SharedDeclaredLightsReplaceTheOwnOnes)
{
  World &world = committed(glowingWorld());
  ASSERT_EQ(world.ownDeclaredLights().size(), 1u);
  EXPECT_EQ(world.ownDeclaredLights()[0].light->subtype(), "directional");
  const PlacedLight *ownSun = world.lights()[0].get();
  std::vector<std::unique_ptr<PlacedLight>> declared;
  declared.push_back(world.ownDeclaredLights()[0].light->place(
      world.ownDeclaredLights()[0].worldFromObject));
  declared.push_back(remoteEmitter()); // found by rays as geometry only
  std::vector<std::unique_ptr<PlacedLight>> emitters;
  const EmissiveSurface &own = world.ownEmitter(0);
  emitters.push_back(remoteEmitter());
  emitters.push_back(
      std::make_unique<EmissiveSurface>(own.shape(), own.radiance()));
  world.shareLights(std::move(declared), std::move(emitters), 1, 100.f);
  EXPECT_TRUE(world.sharesEmitters());
  EXPECT_TRUE(world.sharesDeclaredLights());
  ASSERT_EQ(world.lights().size(), 4u);
  EXPECT_EQ(world.declaredLightCount(), 2u);
  EXPECT_EQ(world.ownDeclaredLights().size(), 1u);
  EXPECT_EQ(world.ownEmitterCount(), 1u);
  EXPECT_EQ(world.emitterLight(0, 0), 3);
  EXPECT_NE(world.lights()[0].get(), ownSun);
  float total = 0.f;
  for (size_t i = 0; i < world.lights().size(); i++)
    total += world.lightSelector().probability(i);
  EXPECT_NEAR(total, 1.f, 1e-5f);

  world.keepOwnEmitters();
  EXPECT_FALSE(world.sharesDeclaredLights());
  ASSERT_EQ(world.lights().size(), 2u);
  EXPECT_EQ(world.declaredLightCount(), 1u);
  EXPECT_EQ(world.lights()[0].get(), ownSun);
  EXPECT_EQ(world.emitterLight(0, 0), 1);
}

// World::shareDeclaredLights (composite mode): other declared lights, the
// world's own emitter kept after them.
TEST_F(SharedEmittersTest, SharedDeclaredLightsKeepTheOwnEmitters)
{
  World &world = committed(glowingWorld());
  const PlacedLight *ownEmitter = world.lights()[1].get();
  std::vector<std::unique_ptr<PlacedLight>> declared;
  for (int i = 0; i < 2; i++) {
    declared.push_back(world.ownDeclaredLights()[0].light->place(
        world.ownDeclaredLights()[0].worldFromObject));
  }
  world.shareDeclaredLights(std::move(declared), 50.f);
  EXPECT_FALSE(world.sharesEmitters());
  EXPECT_TRUE(world.sharesDeclaredLights());
  ASSERT_EQ(world.lights().size(), 3u);
  EXPECT_EQ(world.declaredLightCount(), 2u);
  EXPECT_EQ(world.lights()[2].get(), ownEmitter);
  EXPECT_EQ(world.emitterLight(0, 0), 2);
  EXPECT_EQ(world.ownEmitterCount(), 1u);

  world.keepOwnEmitters();
  EXPECT_FALSE(world.sharesDeclaredLights());
  ASSERT_EQ(world.lights().size(), 2u);
  EXPECT_EQ(world.lights()[1].get(), ownEmitter);
  EXPECT_EQ(world.emitterLight(0, 0), 1);
}

} // namespace
} // namespace prism
