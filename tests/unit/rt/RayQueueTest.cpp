// Ray queues traced through Embree's stream API: closest hits and
// occlusion per ray, tags returned unchanged, and rays Embree must never
// see (non-finite, huge, empty intervals) finding nothing.
#include "rt/Context.h"
#include "rt/RayQueue.h"
#include "rt/Scene.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

namespace prism::rt {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

class RayQueueTest : public ::testing::Test
{
 protected:
  RayQueueTest()
      : m_context([this](const std::string &m) { m_errors.push_back(m); }),
        m_scene(m_context)
  {
    // A unit triangle in the plane z = 0 (geometry 0) and a sphere of
    // radius 1 around (5, 0, 0) (geometry 1).
    m_vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}}; // + padding
    m_indices = {0, 1, 2};
    m_spheres = {{5, 0, 0, 1}};
    m_scene.addTriangles(0, m_vertices.data(), 3, m_indices.data(), 1);
    m_scene.addSpheres(1, m_spheres.data(), 1);
    m_scene.commit();
  }

  std::vector<std::string> m_errors;
  Context m_context;
  Scene m_scene;
  std::vector<float3> m_vertices;
  std::vector<uint32_t> m_indices;
  std::vector<float4> m_spheres;
};

TEST_F(RayQueueTest, ClosestHitsPerRayWithTagsKept)
{
  RayQueue queue;
  queue.push({0.2f, 0.2f, 1}, {0, 0, -1}, 0.f, kInf, 0.5f, 70); // triangle
  queue.push({5, 0, 3}, {0, 0, -1}, 0.f, kInf, 0.5f, 71);       // sphere
  queue.push({-3, 0, 1}, {0, 0, -1}, 0.f, kInf, 0.5f, 72);      // nothing
  queue.push({0.2f, 0.2f, 1}, {0, 0, -1}, 0.f, 0.5f, 0.5f, 73); // too short
  m_scene.intersect(queue);
  ASSERT_EQ(queue.size(), 4u);
  const Hit triangle = queue.hit(0);
  ASSERT_TRUE(triangle.found());
  EXPECT_EQ(triangle.geometryId, 0u);
  EXPECT_FLOAT_EQ(triangle.t, 1.f);
  const Hit sphere = queue.hit(1);
  ASSERT_TRUE(sphere.found());
  EXPECT_EQ(sphere.geometryId, 1u);
  EXPECT_NEAR(sphere.t, 2.f, 1e-5f);
  EXPECT_FALSE(queue.hit(2).found());
  EXPECT_FALSE(queue.hit(3).found());
  for (size_t i = 0; i < 4; i++) {
    EXPECT_EQ(queue.tag(i), 70 + i);
    EXPECT_FALSE(queue.untraceable(i));
  }
  EXPECT_TRUE(m_errors.empty());
}

TEST_F(RayQueueTest, OcclusionPerRay)
{
  RayQueue queue;
  queue.push({0.2f, 0.2f, 1}, {0, 0, -1}, 0.f, kInf, 0.5f, 0);
  queue.push({0.2f, 0.2f, 1}, {0, 0, -1}, 0.f, 0.9f, 0.5f, 1); // stops short
  queue.push({5, 0, 3}, {0, 0, -1}, 0.f, kInf, 0.5f, 2);
  queue.push({5, 0, 3}, {0, 0, 1}, 0.f, kInf, 0.5f, 3); // away from it
  m_scene.occluded(queue);
  EXPECT_TRUE(queue.occluded(0));
  EXPECT_FALSE(queue.occluded(1));
  EXPECT_TRUE(queue.occluded(2));
  EXPECT_FALSE(queue.occluded(3));
  // Transmittance: nothing through opaque blockers, everything otherwise,
  // then what attenuation along the ray lets through.
  const float3 none{0, 0, 0}, all{1, 1, 1};
  EXPECT_EQ(queue.transmittance(0), none);
  EXPECT_EQ(queue.transmittance(1), all);
  EXPECT_EQ(queue.transmittance(2), none);
  EXPECT_EQ(queue.transmittance(3), all);
  queue.attenuate(3, float3{0.5f, 0.25f, 1.f});
  EXPECT_EQ(queue.transmittance(3), (float3{0.5f, 0.25f, 1.f}));
  // Untraced rays (an empty world) reach their end.
  RayQueue untraced;
  untraced.push({0, 0, 0}, {0, 0, 1}, 0.f, kInf, 0.5f, 0);
  EXPECT_EQ(untraced.transmittance(0), all);
}

TEST_F(RayQueueTest, UntraceableRaysFindNothing)
{
  RayQueue queue;
  queue.push({kNaN, 0, 1}, {0, 0, -1}, 0.f, kInf, 0.5f, 0);
  queue.push({0.2f, 0.2f, 1}, {0, 0, kInf}, 0.f, kInf, 0.5f, 1);
  queue.push({0.2f, 0.2f, 1e30f}, {0, 0, -1}, 0.f, kInf, 0.5f, 2);
  queue.push({0.2f, 0.2f, 1}, {0, 0, -1}, 2.f, 1.f, 0.5f, 3); // tMax < tMin
  queue.push({0.2f, 0.2f, 1}, {0, 0, -1}, -1.f, kInf, 0.5f, 4);
  queue.push({0.2f, 0.2f, 1}, {0, 0, -1}, 0.f, kNaN, 0.5f, 5);
  // A time outside the shutter is traced at its midpoint, not refused.
  queue.push({0.2f, 0.2f, 1}, {0, 0, -1}, 0.f, kInf, kNaN, 6);
  m_scene.intersect(queue);
  for (size_t i = 0; i < 6; i++) {
    EXPECT_TRUE(queue.untraceable(i)) << i;
    EXPECT_FALSE(queue.hit(i).found()) << i;
  }
  EXPECT_FALSE(queue.untraceable(6));
  EXPECT_TRUE(queue.hit(6).found());
  EXPECT_FLOAT_EQ(queue.time(6), 0.5f);
  RayQueue shadows;
  shadows.push({kNaN, 0, 1}, {0, 0, -1}, 0.f, kInf, 0.5f, 0);
  m_scene.occluded(shadows);
  EXPECT_FALSE(shadows.occluded(0));
  EXPECT_TRUE(m_errors.empty());
}

TEST_F(RayQueueTest, EmptyQueueAndClear)
{
  RayQueue queue;
  m_scene.intersect(queue);
  m_scene.occluded(queue);
  queue.push({0.2f, 0.2f, 1}, {0, 0, -1}, 0.f, kInf, 0.5f, 9);
  queue.setCoherent(true);
  queue.clear();
  EXPECT_TRUE(queue.empty());
  EXPECT_FALSE(queue.coherent()); // the next rays are anyone's
}

TEST_F(RayQueueTest, CoherentQueuesFindWhatIncoherentOnesFind)
{
  // A fan of camera-like rays from one point over the triangle and the
  // sphere, some untraceable: the coherence hint changes how Embree
  // traces, never what a ray finds or whether it is blocked.
  RayQueue coherent, incoherent, coherentShadows, incoherentShadows;
  for (RayQueue *queue :
      {&coherent, &incoherent, &coherentShadows, &incoherentShadows}) {
    for (int i = 0; i < 100; i++) {
      const float3 direction =
          normalize(float3{-0.5f + 0.065f * float(i), 0.25f, -1.f});
      const float tMin = i % 17 == 5 ? kNaN : 0.f;
      queue->push({0.1f, 0.f, 1.f}, direction, tMin, kInf, 0.5f, uint32_t(i));
    }
  }
  coherent.setCoherent(true);
  coherentShadows.setCoherent(true);
  m_scene.intersect(coherent);
  m_scene.intersect(incoherent);
  m_scene.occluded(coherentShadows);
  m_scene.occluded(incoherentShadows);
  int hits = 0, blocked = 0;
  for (size_t i = 0; i < coherent.size(); i++) {
    const Hit a = coherent.hit(i), b = incoherent.hit(i);
    ASSERT_EQ(a.found(), b.found()) << i;
    hits += a.found();
    if (a.found()) {
      EXPECT_EQ(a.geometryId, b.geometryId) << i;
      EXPECT_EQ(a.primitiveId, b.primitiveId) << i;
      EXPECT_FLOAT_EQ(a.t, b.t) << i;
    }
    EXPECT_EQ(coherentShadows.occluded(i), incoherentShadows.occluded(i)) << i;
    blocked += coherentShadows.occluded(i);
  }
  EXPECT_GT(hits, 10);
  EXPECT_EQ(blocked, hits);
  EXPECT_TRUE(m_errors.empty());
}

// A single-sided triangle: closest-hit rays pass it from behind,
// occlusion rays from the front (light meets it from behind), and each
// says where; a ray that passes nothing says +inf, and so does every ray
// of a two-sided triangle.
TEST_F(RayQueueTest, RaysSayWhereTheyPassedASingleSidedSurface)
{
  for (const bool singleSided : {true, false}) {
    Scene scene(m_context);
    scene.addTriangles(0, m_vertices.data(), 3, m_indices.data(), 1);
    if (singleSided)
      scene.cullBackFaces(0);
    scene.commit();
    auto both = [](RayQueue &queue) {
      queue.push({0.2f, 0.2f, 1}, {0, 0, -1}, 0.f, kInf, 0.5f, 0);
      queue.push({0.2f, 0.2f, -1}, {0, 0, 1}, 0.f, kInf, 0.5f, 1);
      queue.push({3, 3, 1}, {0, 0, -1}, 0.f, kInf, 0.5f, 2); // misses
    };
    RayQueue closest, occlusion;
    both(closest);
    both(occlusion);
    scene.intersect(closest);
    scene.occluded(occlusion);
    EXPECT_EQ(closest.passedOneSidedAt(2), kInf);
    EXPECT_EQ(occlusion.passedOneSidedAt(2), kInf);
    if (!singleSided) {
      for (size_t i = 0; i < 2; i++) {
        EXPECT_TRUE(closest.hit(i).found());
        EXPECT_TRUE(occlusion.occluded(i));
        EXPECT_EQ(closest.passedOneSidedAt(i), kInf);
        EXPECT_EQ(occlusion.passedOneSidedAt(i), kInf);
      }
      continue;
    }
    // One side is the front: the ray from there hits it and is blocked...
    const size_t front = closest.hit(0).found() ? 0 : 1, back = 1 - front;
    ASSERT_TRUE(closest.hit(front).found());
    EXPECT_FALSE(closest.hit(back).found());
    EXPECT_EQ(closest.passedOneSidedAt(front), kInf);
    EXPECT_NEAR(closest.passedOneSidedAt(back), 1.f, 1e-5f);
    // ... except for light, which meets that face from behind.
    EXPECT_FALSE(occlusion.occluded(front));
    EXPECT_NEAR(occlusion.passedOneSidedAt(front), 1.f, 1e-5f);
    EXPECT_TRUE(occlusion.occluded(back));
  }
}

// A ray carried on past a see-through layer is given what it passed
// before: appending keeps that, and a trace only lowers it.
TEST_F(RayQueueTest, RaysCarriedOnKeepTheSingleSidedSurfacesTheyPassed)
{
  Scene scene(m_context);
  scene.addTriangles(0, m_vertices.data(), 3, m_indices.data(), 1);
  scene.cullBackFaces(0);
  scene.commit();
  // Which side of the triangle a closest-hit ray passes from behind.
  RayQueue probe;
  probe.push({0.2f, 0.2f, 1}, {0, 0, -1}, 0.f, kInf, 0.5f, 0);
  scene.intersect(probe);
  const float z = probe.hit(0).found() ? -1.f : 1.f;
  RayQueue given;
  given.push({0.2f, 0.2f, z}, {0, 0, -z}, 0.f, kInf, 0.5f, 0); // passes at 1
  given.push({0.2f, 0.2f, z}, {0, 0, -z}, 0.f, kInf, 0.5f, 1);
  given.push({3, 3, z}, {0, 0, -z}, 0.f, kInf, 0.5f, 2); // passes nothing
  given.setPassedOneSidedAt(0, 3.f);
  given.setPassedOneSidedAt(1, 0.25f);
  given.setPassedOneSidedAt(2, 0.5f);
  RayQueue queue;
  queue.push({0, 0, 9}, {0, 0, 1}, 0.f, kInf, 0.5f, 9);
  queue.append(given);
  ASSERT_EQ(queue.size(), 4u);
  EXPECT_EQ(queue.passedOneSidedAt(0), kInf);
  EXPECT_EQ(queue.passedOneSidedAt(1), 3.f);
  EXPECT_EQ(queue.passedOneSidedAt(2), 0.25f);
  EXPECT_EQ(queue.passedOneSidedAt(3), 0.5f);
  scene.intersect(queue);
  EXPECT_EQ(queue.passedOneSidedAt(0), kInf);
  EXPECT_NEAR(queue.passedOneSidedAt(1), 1.f, 1e-5f);
  EXPECT_EQ(queue.passedOneSidedAt(2), 0.25f);
  EXPECT_EQ(queue.passedOneSidedAt(3), 0.5f);
  for (size_t i = 0; i < 4; i++)
    EXPECT_FALSE(queue.hit(i).found()) << i;
}

} // namespace
} // namespace prism::rt
