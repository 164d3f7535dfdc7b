// The one frame construction: orthonormal and right-handed for every unit
// axis (near -z too), a round trip through it is the identity, and a hint
// sets the x axis unless it is parallel to z.
#include "math/LocalFrame.h"

#include "math/SphereSampling.h"

#include "../shading/ShadingTestUtil.h"

#include <gtest/gtest.h>

#include <vector>

using namespace prism;

namespace {

std::vector<float3> unitAxes()
{
  std::vector<float3> axes = {{0, 0, 1},
      {0, 0, -1},
      {1, 0, 0},
      {0, -1, 0},
      normalize(float3{1e-8f, 0, -1})};
  for (uint32_t i = 0; i < 2000; i++)
    axes.push_back(sampleUniformSphere(RandomSequence({i, 0}, 0, 0).get2D(0)));
  return axes;
}

void expectOrthonormalRightHanded(const LocalFrame &frame)
{
  ASSERT_NEAR(length(frame.x), 1.f, 1e-5f);
  ASSERT_NEAR(length(frame.y), 1.f, 1e-5f);
  ASSERT_NEAR(dot(frame.x, frame.z), 0.f, 1e-5f);
  ASSERT_NEAR(dot(frame.y, frame.z), 0.f, 1e-5f);
  ASSERT_NEAR(dot(frame.x, frame.y), 0.f, 1e-5f);
  // Right-handed: x cross y = z.
  ASSERT_NEAR(length(cross(frame.x, frame.y) - frame.z), 0.f, 1e-5f);
}

} // namespace

TEST(LocalFrame, AroundAnAxisIsOrthonormalAndRightHanded)
{
  for (const float3 n : unitAxes()) {
    float3 b1, b2;
    orthonormalBasis(n, b1, b2);
    const LocalFrame frame = LocalFrame::around(n);
    EXPECT_EQ(frame.x, b1);
    EXPECT_EQ(frame.y, b2);
    EXPECT_EQ(frame.z, n);
    expectOrthonormalRightHanded(frame);
    const float3 v = normalize(float3{0.3f, -0.5f, 0.8f});
    ASSERT_NEAR(length(frame.toWorld(frame.toLocal(v)) - v), 0.f, 1e-5f);
    ASSERT_NEAR(frame.toLocal(n).z, 1.f, 1e-5f);
    ASSERT_NEAR(length(frame.toWorld({0.f, 0.f, 1.f}) - n), 0.f, 1e-6f);
  }
}

TEST(LocalFrame, AHintSetsTheXAxis)
{
  const LocalFrame frame = LocalFrame::around({0, 0, 1}, {2, 0, 0.5f});
  EXPECT_NEAR(length(frame.x - float3{1, 0, 0}), 0.f, 1e-6f);
  EXPECT_NEAR(length(frame.y - float3{0, 1, 0}), 0.f, 1e-6f);
  for (const float3 n : unitAxes()) {
    const float3 hint{0.6f, -0.64f, 0.48f};
    const LocalFrame hinted = LocalFrame::around(n, hint);
    expectOrthonormalRightHanded(hinted);
    // x is the hint's part orthogonal to z, unless that part vanishes.
    const float3 orthogonal = hint - n * dot(hint, n);
    if (length(orthogonal) > 1e-3f) {
      ASSERT_NEAR(length(hinted.x - normalize(orthogonal)), 0.f, 1e-4f);
    }
  }
}

TEST(LocalFrame, AHintAlongTheAxisFallsBackToAnyFrame)
{
  for (const float3 hint :
      {float3{0, 0, 3}, float3{0, 0, -1e-20f}, float3{0, 0, 0}}) {
    const LocalFrame frame = LocalFrame::around({0, 0, 1}, hint);
    const LocalFrame any = LocalFrame::around({0, 0, 1});
    EXPECT_EQ(frame.x, any.x);
    EXPECT_EQ(frame.y, any.y);
  }
}
