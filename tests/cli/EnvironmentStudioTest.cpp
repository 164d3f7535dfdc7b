// The default studio environment has no bands: neighbouring texels differ
// little everywhere (the first studio stepped 0.4 at the horizon and up to
// 4 at its softboxes' edges, at 256 x 128), and its mean radiance is still
// the first studio's within 1%, so scenes keep their brightness.
#include "EnvironmentStudio.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

using namespace prism::scene_io;

// The first studio's mean (its 256 x 128 image, solid-angle weighted).
constexpr float kFirstStudioMean[3] = {0.82476f, 0.83182f, 0.85664f};

float largestStep(const prism::scenes::Vec3 &a, const prism::scenes::Vec3 &b)
{
  return std::max(
      {std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

TEST(EnvironmentStudio, NeighbouringTexelsDifferLittle)
{
  const size_t w = kStudioWidth, h = kStudioHeight;
  const auto texels = studioImage(w, h);
  ASSERT_EQ(texels.size(), w * h);
  float rows = 0, columns = 0, skyRows = 0;
  for (size_t j = 0; j < h; ++j)
    for (size_t i = 0; i < w; ++i) {
      const auto &t = texels[j * w + i];
      columns = std::max(columns, largestStep(t, texels[j * w + (i + 1) % w]));
      if (j + 1 < h)
        rows = std::max(rows, largestStep(t, texels[(j + 1) * w + i]));
    }
  // The column facing away from both softboxes (azimuth pi): the sky, the
  // horizon and the floor alone.
  for (size_t j = 0; j + 1 < h; ++j)
    skyRows =
        std::max(skyRows, largestStep(texels[j * w], texels[(j + 1) * w]));
  EXPECT_LT(rows, 0.35f); // the key softbox (radiance 7) fades over 36 rows
  EXPECT_LT(columns, 0.35f);
  EXPECT_LT(skyRows, 0.03f); // 3% of the horizon's radiance, at most
  std::printf("largest steps: rows %.4f, columns %.4f, sky rows %.4f\n",
      rows,
      columns,
      skyRows);
}

TEST(EnvironmentStudio, MeanRadianceIsTheFirstStudios)
{
  const auto mean = meanRadiance(
      studioImage(kStudioWidth, kStudioHeight), kStudioWidth, kStudioHeight);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(mean[c] / kFirstStudioMean[c], 1.f, 0.01f) << c;
  std::printf("mean radiance %.5f %.5f %.5f\n", mean[0], mean[1], mean[2]);
}

TEST(EnvironmentStudio, MeanOfAUniformImageIsItsValue)
{
  const std::vector<prism::scenes::Vec3> grey(64 * 32, {0.5f, 2.f, 1.f});
  const auto mean = meanRadiance(grey, 64, 32);
  EXPECT_NEAR(mean[0], 0.5f, 1e-5f);
  EXPECT_NEAR(mean[1], 2.f, 1e-5f);
  EXPECT_NEAR(mean[2], 1.f, 1e-5f);
}

} // namespace
