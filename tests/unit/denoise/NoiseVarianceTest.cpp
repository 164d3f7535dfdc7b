// The noise estimate on images whose noise is known: none, a checkerboard
// of known amplitude, Gaussian noise of known deviation, and the prior
// that caps it as samples grow.
#include "denoise/NoiseVariance.h"

#include "DenoisePassesTestUtil.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <vector>

namespace prism::denoising {
namespace {

constexpr float kMedianChiSquare1 = 0.4549364f;

// Probes and variance of a gray image on flat guides.
struct Estimate
{
  std::vector<float> probes;
  std::vector<NeighbourWeights> weights;
  std::vector<float4> withVariance;
};

Estimate estimate(const PixelGrid &grid,
    const std::vector<float> &gray,
    float samples,
    const std::vector<Guide> &guides)
{
  std::vector<float4> image;
  for (float v : gray)
    image.push_back({v, v, v, 0.f});
  Estimate e{std::vector<float>(grid.pixels()),
      std::vector<NeighbourWeights>(grid.pixels()),
      std::vector<float4>(grid.pixels())};
  probeNoise(
      grid, guides.data(), image.data(), e.probes.data(), e.weights.data());
  estimateVariance(grid,
      guides.data(),
      image.data(),
      e.probes.data(),
      samples,
      e.withVariance.data());
  return e;
}
Estimate estimate(
    const PixelGrid &grid, const std::vector<float> &gray, float samples)
{
  return estimate(
      grid, gray, samples, std::vector<Guide>(grid.pixels(), flatGuide()));
}

std::vector<float> checkerboard(const PixelGrid &grid, float mean, float a)
{
  std::vector<float> gray(grid.pixels());
  for (int y = 0; y < grid.height; y++)
    for (int x = 0; x < grid.width; x++)
      gray[grid.index(x, y)] = (x + y) % 2 ? mean + a : mean - a;
  return gray;
}

// Pixels whose whole 7x7 window of 3x3 probes lies inside the image.
template <typename F>
void forEachInterior(const PixelGrid &grid, const F &f)
{
  for (int y = 4; y < grid.height - 4; y++)
    for (int x = 4; x < grid.width - 4; x++)
      f(grid.index(x, y));
}

TEST(NoiseVariance, AConstantImageHasNone)
{
  // None but the rounding of the neighbours' mean.
  const PixelGrid grid{16, 12};
  const Estimate e = estimate(grid, std::vector<float>(grid.pixels(), 0.7f), 1);
  for (size_t i = 0; i < grid.pixels(); i++) {
    EXPECT_NEAR(e.probes[i], 0.f, 1e-12f);
    EXPECT_NEAR(e.withVariance[i].w, 0.f, 1e-12f);
    EXPECT_EQ(xyz(e.withVariance[i]), (float3{0.7f, 0.7f, 0.7f}));
  }
}

TEST(NoiseVariance, ACheckerboardOfAmplitudeAHasVarianceFromItsResidual)
{
  // Inside, the 8 neighbours average to the mean: the residual is +-a, and
  // Var(residual) = var (1 + 8 / 64), so the probe is a^2 / 1.125 and
  // every probe of the window is the median.
  const PixelGrid grid{16, 14};
  const float a = 0.1f;
  const Estimate e = estimate(grid, checkerboard(grid, 1.f, a), 1);
  forEachInterior(grid, [&](size_t i) {
    EXPECT_NEAR(e.probes[i], a * a / 1.125f, 1e-6f);
    EXPECT_NEAR(e.withVariance[i].w, a * a / 1.125f / kMedianChiSquare1, 1e-5f);
  });
}

TEST(NoiseVariance, GaussianNoiseOfDeviationSigmaHasVarianceSigmaSquared)
{
  const PixelGrid grid{96, 96};
  const float sigma = 0.05f;
  std::mt19937 random(7);
  std::normal_distribution<float> noise(0.f, sigma);
  std::vector<float> gray(grid.pixels());
  for (float &v : gray)
    v = 1.f + noise(random);
  const Estimate e = estimate(grid, gray, 1);
  double sum = 0.0;
  int count = 0;
  forEachInterior(grid, [&](size_t i) {
    sum += e.withVariance[i].w;
    count++;
  });
  EXPECT_NEAR(sum / count, sigma * sigma, 0.1 * sigma * sigma);
}

TEST(NoiseVariance, ThePriorCapsItAsSamplesGrow)
{
  // A sample deviates at most ~4x its mean: with 1000 samples the variance
  // is at most 16 mean^2 / 1000, far below the checkerboard's.
  const PixelGrid grid{16, 14};
  const float samples = 1000.f;
  const Estimate e = estimate(grid, checkerboard(grid, 1.f, 0.5f), samples);
  forEachInterior(grid, [&](size_t i) {
    // The window's mean is 1 +- 0.5 / 49 (one square more of one color).
    EXPECT_NEAR(e.withVariance[i].w, 16.f / samples, 16.f / samples * 0.05f);
  });
}

TEST(NoiseVariance, AnIsolatedPixelHasNoProbe)
{
  // A hit surrounded by background: no neighbour of its kind.
  const PixelGrid grid{3, 3};
  std::vector<Guide> guides(grid.pixels(), flatGuide());
  for (Guide &g : guides) {
    g.kind = 0;
    g.depth = std::numeric_limits<float>::infinity();
  }
  guides[grid.index(1, 1)] = flatGuide();
  const Estimate e =
      estimate(grid, std::vector<float>(grid.pixels(), 0.5f), 1, guides);
  EXPECT_EQ(e.probes[grid.index(1, 1)], -1.f);
  EXPECT_EQ(e.withVariance[grid.index(1, 1)].w, 0.f);
  const NeighbourWeights &w = e.weights[grid.index(1, 1)];
  for (size_t k = 0; k < w.size(); k++)
    EXPECT_EQ(w[k], k == 4 ? 1.f : 0.f) << k;
}

TEST(NoiseVariance, KeepsTheThreeByThreeWeightsOfFlatGuides)
{
  const PixelGrid grid{5, 4};
  const Estimate e = estimate(grid, std::vector<float>(grid.pixels(), 1.f), 1);
  for (int y = 0; y < grid.height; y++)
    for (int x = 0; x < grid.width; x++)
      EXPECT_EQ(e.weights[grid.index(x, y)], flatNeighbourWeights(grid, x, y));
}

} // namespace
} // namespace prism::denoising
