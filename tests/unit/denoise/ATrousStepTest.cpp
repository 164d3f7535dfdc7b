// One à-trous step against what a weighted average must do: keep a
// constant image, shrink a uniform variance by the B3 kernel's sum of
// squared weights, and never blend pixels of different kinds.
#include "denoise/ATrousStep.h"

#include "DenoisePassesTestUtil.h"

#include <gtest/gtest.h>

#include <vector>

namespace prism::denoising {
namespace {

TEST(ATrousStep, KeepsAConstantImageForEveryStep)
{
  const PixelGrid grid{23, 17};
  const std::vector<Guide> guides(grid.pixels(), flatGuide());
  const auto weights = flatNeighbourWeights(grid);
  const float4 pixel{0.3f, 0.6f, 0.9f, 0.01f};
  const std::vector<float4> source(grid.pixels(), pixel);
  std::vector<float4> target(grid.pixels());
  for (int step : {1, 2, 4, 8, 16}) {
    aTrousStep(grid,
        guides.data(),
        weights.data(),
        source.data(),
        step,
        target.data());
    for (const float4 &v : target) {
      EXPECT_NEAR(v.x, pixel.x, 1e-6f);
      EXPECT_NEAR(v.y, pixel.y, 1e-6f);
      EXPECT_NEAR(v.z, pixel.z, 1e-6f);
    }
  }
}

TEST(ATrousStep, ShrinksUniformVarianceByTheKernelsSquaredWeights)
{
  // Away from the border all 25 taps count with their B3 weights, which sum
  // to 1: the variance of the mean is var * (sum of b^2 along one axis)^2.
  const PixelGrid grid{21, 21};
  const std::vector<Guide> guides(grid.pixels(), flatGuide());
  const auto weights = flatNeighbourWeights(grid);
  const float variance = 0.04f;
  const std::vector<float4> source(grid.pixels(), {0.5f, 0.5f, 0.5f, variance});
  std::vector<float4> target(grid.pixels());
  const int step = 2;
  aTrousStep(
      grid, guides.data(), weights.data(), source.data(), step, target.data());
  const float b3SquaredSum = 2.f * (1.f / 16.f) * (1.f / 16.f)
                             + 2.f * (1.f / 4.f) * (1.f / 4.f)
                             + (3.f / 8.f) * (3.f / 8.f);
  for (int y = 2 * step; y < grid.height - 2 * step; y++)
    for (int x = 2 * step; x < grid.width - 2 * step; x++)
      EXPECT_NEAR(target[grid.index(x, y)].w,
          variance * b3SquaredSum * b3SquaredSum,
          1e-8f);
}

TEST(ATrousStep, NeverBlendsBackgroundIntoSurfaces)
{
  // Left half a surface of color 1, right half background of color 0.
  const PixelGrid grid{16, 8};
  std::vector<Guide> guides(grid.pixels(), flatGuide());
  std::vector<float4> source(grid.pixels(), {1.f, 1.f, 1.f, 1.f});
  for (int y = 0; y < grid.height; y++) {
    for (int x = grid.width / 2; x < grid.width; x++) {
      guides[grid.index(x, y)].kind = 0;
      guides[grid.index(x, y)].depth = std::numeric_limits<float>::infinity();
      source[grid.index(x, y)] = {0.f, 0.f, 0.f, 1.f};
    }
  }
  const auto weights = flatNeighbourWeights(grid);
  std::vector<float4> target(grid.pixels());
  aTrousStep(
      grid, guides.data(), weights.data(), source.data(), 1, target.data());
  for (int y = 0; y < grid.height; y++) {
    for (int x = 0; x < grid.width; x++) {
      const float expected = x < grid.width / 2 ? 1.f : 0.f;
      EXPECT_FLOAT_EQ(target[grid.index(x, y)].x, expected) << x << ", " << y;
    }
  }
}

TEST(ATrousStep, KeepsLuminanceEdgesTheNoiseCannotExplain)
{
  // Two flat halves 1 apart with a tiny variance: a difference of
  // thousands of deviations gets no weight.
  const PixelGrid grid{12, 6};
  const std::vector<Guide> guides(grid.pixels(), flatGuide());
  std::vector<float4> source(grid.pixels());
  for (int y = 0; y < grid.height; y++)
    for (int x = 0; x < grid.width; x++)
      source[grid.index(x, y)] = x < grid.width / 2
                                     ? float4{0.2f, 0.2f, 0.2f, 1e-8f}
                                     : float4{1.2f, 1.2f, 1.2f, 1e-8f};
  const auto weights = flatNeighbourWeights(grid);
  std::vector<float4> target(grid.pixels());
  aTrousStep(
      grid, guides.data(), weights.data(), source.data(), 1, target.data());
  for (int y = 0; y < grid.height; y++)
    for (int x = 0; x < grid.width; x++)
      EXPECT_NEAR(
          target[grid.index(x, y)].x, source[grid.index(x, y)].x, 1e-6f);
}

} // namespace
} // namespace prism::denoising
