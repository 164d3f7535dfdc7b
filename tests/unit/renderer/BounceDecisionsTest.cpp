// A wavefront's decisions drawn in batches are exactly the numbers each
// path would draw alone, whatever the queue's order and length.
#include "renderer/SampleSequence.h"
#include "renderer/wavefront/BounceDecisions.h"

#include <gtest/gtest.h>

namespace prism {
namespace {

float2 alone(const PathState &path, uint32_t decision)
{
  return sobolSample2D(path.sampleIndex,
      streamSeed(path, path.bounce * kStreamsPerBounce + decision));
}

TEST(BounceDecisions, BatchesEqualEachPathDrawingAlone)
{
  // 37 rays: not a multiple of any vector width; tags out of order.
  std::vector<PathState> paths(37);
  rt::RayQueue rays;
  for (size_t i = 0; i < paths.size(); i++) {
    PathState &path = paths[i];
    path.seed = sequenceSeed(uint32_t(i), uint32_t(3 * i), 0, 0);
    path.sampleIndex = uint32_t(i * i);
    path.bounce = uint16_t(i % 9);
  }
  for (size_t i = 0; i < paths.size(); i++) {
    const uint32_t tag = uint32_t((i * 11) % paths.size());
    rays.push({0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}, 0.f, 1.f, 0.5f, tag);
  }
  BounceDecisions decisions;
  decisions.draw(paths, rays);
  for (size_t r = 0; r < rays.size(); r++) {
    const PathState &path = paths[rays.tag(r)];
    EXPECT_EQ(decisions.direction(r).x, alone(path, 0).x) << r;
    EXPECT_EQ(decisions.direction(r).y, alone(path, 0).y) << r;
    EXPECT_EQ(decisions.lobe(r), alone(path, 1).x) << r;
    EXPECT_EQ(decisions.lightPick(r), alone(path, 2).x) << r;
    EXPECT_EQ(decisions.lightPoint(r).x, alone(path, 3).x) << r;
    EXPECT_EQ(decisions.lightPoint(r).y, alone(path, 3).y) << r;
    EXPECT_EQ(decisions.roulette(r), alone(path, 4).y) << r;
  }
}

} // namespace
} // namespace prism
