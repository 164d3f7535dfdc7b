// The guides and their weights: a tilted plane's depth slope is exact, so
// its pixels weigh each other fully; normals, kinds and depth edges cut.
#include "denoise/Guides.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace prism::denoising {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

struct GuideImage
{
  PixelGrid grid;
  std::vector<float3> normal;
  std::vector<float> depth;
  std::vector<Guide> guides;

  void build()
  {
    guides.resize(grid.pixels());
    const DenoiseInputs in{uint32_t(grid.width),
        uint32_t(grid.height),
        nullptr,
        nullptr,
        normal.empty() ? nullptr : normal.data(),
        depth.empty() ? nullptr : depth.data(),
        1};
    buildGuides(in, guides.data());
  }
  const Guide &at(int x, int y) const
  {
    return guides[grid.index(x, y)];
  }
};

// Depth 10 + 0.5 x + 0.25 y, normals (0, 0, 2) (normalised by the guides).
GuideImage tiltedPlane()
{
  GuideImage image{{9, 7}, {}, {}, {}};
  for (int y = 0; y < image.grid.height; y++) {
    for (int x = 0; x < image.grid.width; x++) {
      image.normal.push_back({0.f, 0.f, 2.f});
      image.depth.push_back(10.f + 0.5f * float(x) + 0.25f * float(y));
    }
  }
  image.build();
  return image;
}

TEST(Guides, ATiltedPlaneHasExactSlopesAndFullWeights)
{
  const GuideImage image = tiltedPlane();
  for (int y = 0; y < image.grid.height; y++) {
    for (int x = 0; x < image.grid.width; x++) {
      const Guide &p = image.at(x, y);
      EXPECT_EQ(p.kind, Guide::kHasNormal | Guide::kHit);
      EXPECT_EQ(p.normal, (float3{0.f, 0.f, 1.f}));
      EXPECT_FLOAT_EQ(p.depthSlope.x, 0.5f);
      EXPECT_FLOAT_EQ(p.depthSlope.y, 0.25f);
    }
  }
  const Guide &p = image.at(4, 3);
  for (int dy = -3; dy <= 3; dy++)
    for (int dx = -4; dx <= 4; dx++)
      EXPECT_NEAR(
          geometryWeight(p, image.at(4 + dx, 3 + dy), dx, dy), 1.f, 1e-5f);
}

TEST(Guides, ADepthStepOffThePlaneGetsNoWeight)
{
  GuideImage image = tiltedPlane();
  Guide q = image.at(5, 3);
  q.depth += 5.f; // far off p's plane and beyond its tolerance
  EXPECT_LT(geometryWeight(image.at(4, 3), q, 1, 0), 1e-6f);
}

TEST(Guides, NormalWeightIsTheCosineToThe128th)
{
  Guide p{{0.f, 0.f, 1.f}, 0.f, {0.f, 0.f}, Guide::kHasNormal | Guide::kHit};
  Guide q = p;
  EXPECT_EQ(normalWeight(p, q), 1.f);
  const float angle = 0.1f;
  q.normal = {std::sin(angle), 0.f, std::cos(angle)};
  EXPECT_NEAR(normalWeight(p, q), std::pow(std::cos(angle), 128.f), 1e-5f);
  q.normal = {1.f, 0.f, 0.f};
  EXPECT_EQ(normalWeight(p, q), 0.f);
  q.normal = {0.f, 0.f, -1.f};
  EXPECT_EQ(normalWeight(p, q), 0.f);
}

TEST(Guides, KindsNeverMeet)
{
  GuideImage image{{3, 1}, {}, {1.f, kInfinity, 1.f}, {}};
  image.build();
  EXPECT_EQ(image.at(0, 0).kind, Guide::kHit);
  EXPECT_EQ(image.at(1, 0).kind, 0u);
  EXPECT_EQ(geometryWeight(image.at(0, 0), image.at(1, 0), 1, 0), 0.f);
  EXPECT_EQ(geometryWeight(image.at(1, 0), image.at(0, 0), -1, 0), 0.f);
  // Background pixels blend with each other whatever their depth reads.
  EXPECT_EQ(geometryWeight(image.at(1, 0), image.at(1, 0), 0, 0), 1.f);
}

TEST(Guides, WithoutBuffersEveryPixelIsOneSurface)
{
  GuideImage image{{4, 3}, {}, {}, {}};
  image.build();
  for (const Guide &g : image.guides) {
    EXPECT_EQ(g.kind, Guide::kHit);
    EXPECT_EQ(g.depth, 0.f);
    EXPECT_EQ(geometryWeight(g, image.guides[0], 2, 1), 1.f);
  }
}

TEST(Guides, TheSlopeTakesTheSmallerSideAtADepthEdge)
{
  // Depths 1, 2, 10: the middle pixel's slope is the step to its own side.
  GuideImage image{{3, 1}, {}, {1.f, 2.f, 10.f}, {}};
  image.build();
  EXPECT_EQ(image.at(1, 0).depthSlope.x, 1.f);
  EXPECT_EQ(image.at(2, 0).depthSlope.x, 8.f); // one-sided at the border
}

TEST(ExpNegative, MatchesExp)
{
  for (float x = 0.f; x < 80.f; x += 0.37f) {
    EXPECT_NEAR(expNegative(x), std::exp(-x), 3e-6f) << x;
    EXPECT_NEAR(expNegative(x), std::exp(-x), 1e-5f * std::exp(-x)) << x;
  }
  EXPECT_EQ(expNegative(kInfinity), 0.f);
  EXPECT_EQ(expNegative(std::numeric_limits<float>::quiet_NaN()), 0.f);
}

} // namespace
} // namespace prism::denoising
