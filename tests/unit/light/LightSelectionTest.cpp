// How next-event estimation chooses lights (by power, a tenth uniformly)
// and samples emissive surfaces (with the pdf that weighs rays hitting
// them).
#include "light/EmissiveSurface.h"
#include "light/LightSelector.h"

#include "SquareOfCells.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

namespace prism {
namespace {

// A light of a given power and nothing else.
class FixedPowerLight : public PlacedLight
{
 public:
  FixedPowerLight(float power, bool infinite)
      : m_power(power), m_infinite(infinite)
  {}
  LightSample sample(const float3 &, const float2 &) const override
  {
    return {};
  }
  float3 radianceAlong(
      const float3 &, const float3 &, float &, float &pdf) const override
  {
    pdf = 0.f;
    return {0.f, 0.f, 0.f};
  }
  bool isInfinite() const override
  {
    return m_infinite;
  }
  float3 power() const override
  {
    return {m_power, m_power, m_power};
  }

 private:
  float m_power;
  bool m_infinite;
};

std::vector<std::unique_ptr<PlacedLight>> lights(
    const std::vector<std::pair<float, bool>> &powers)
{
  std::vector<std::unique_ptr<PlacedLight>> out;
  for (auto [power, infinite] : powers)
    out.push_back(std::make_unique<FixedPowerLight>(power, infinite));
  return out;
}

TEST(LightSelector, ChoosesInProportionToPowerWithAUniformTenth)
{
  LightSelector selector;
  selector.build(lights({{1.f, false}, {3.f, false}, {0.f, false}}), 1.f);
  // 0.9 * share + 0.1 / 3.
  EXPECT_NEAR(selector.probability(0), 0.9f * 0.25f + 0.1f / 3.f, 1e-6f);
  EXPECT_NEAR(selector.probability(1), 0.9f * 0.75f + 0.1f / 3.f, 1e-6f);
  EXPECT_NEAR(selector.probability(2), 0.1f / 3.f, 1e-6f);
  // pick() agrees with probability(): count choices over a fine grid.
  std::vector<int> counts(3, 0);
  const int n = 100000;
  for (int i = 0; i < n; i++) {
    float p = 0.f;
    const size_t index = selector.pick((float(i) + 0.5f) / float(n), p);
    ASSERT_LT(index, 3u);
    EXPECT_EQ(p, selector.probability(index));
    counts[index]++;
  }
  for (size_t i = 0; i < 3; i++)
    EXPECT_NEAR(float(counts[i]) / n, selector.probability(i), 1e-4f);
}

TEST(LightSelector, InfiniteLightsCountOverTheSceneCrossSection)
{
  // 1 W/m^2 through a scene of radius 2 is 4 pi W: against a 4 pi W lamp
  // the two split the power share evenly.
  LightSelector selector;
  selector.build(lights({{1.f, true}, {4.f * 3.14159265f, false}}), 2.f);
  EXPECT_NEAR(selector.probability(0), 0.5f, 1e-5f);
  EXPECT_NEAR(selector.probability(1), 0.5f, 1e-5f);
}

TEST(LightSelector, WithoutPowerEveryLightIsEquallyLikely)
{
  LightSelector selector;
  selector.build(lights({{0.f, false}, {0.f, false}}), 1.f);
  EXPECT_FLOAT_EQ(selector.probability(0), 0.5f);
  float p = 0.f;
  EXPECT_EQ(selector.pick(0.99999994f, p), 1u);
  LightSelector none;
  none.build({}, 1.f);
  EXPECT_TRUE(none.empty());
}

TEST(EmissiveSurface, SamplesLieOnTheSurfaceWithTheHitPdf)
{
  // A unit square at z = 1 as two triangles and as 8x8 cells of two (a
  // light tree of several levels), seen from close (sampled by solid
  // angle) and from far (by area), and a sphere of radius 0.5. Every
  // sample lies on the surface and pdfOfHit() of the ray that would find it
  // from the same receiver is the sample's pdf.
  EmitterShape square, cells;
  square.triangles = {
      {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const int side = 8;
  cells.triangles = test::squareOfCells(0.f, 0.f, 1.f, 1.f, side);
  EmitterShape sphere;
  sphere.spheres = {{3, 0, 0, 0.5f}};
  const EmissiveSurface squareLight(square, {2.f, 2.f, 2.f});
  const EmissiveSurface cellsLight(cells, {2.f, 2.f, 2.f});
  const EmissiveSurface sphereLight(sphere, {2.f, 2.f, 2.f});
  EXPECT_NEAR(squareLight.power().x, 2.f * 2.f * 3.14159265f, 1e-4f);
  EXPECT_NEAR(
      sphereLight.power().x, 2.f * 2.f * 3.14159265f * 3.14159265f, 1e-3f);
  const int n = 48;
  for (const float3 point : {float3{0.5f, 0.5f, 0.f}, float3{9.f, 4.f, -7.f}})
    for (const EmissiveSurface *light :
        {&squareLight, &cellsLight, &sphereLight})
      for (const float3 receiver :
          {float3{0, 0, 0}, float3{0, 0, 1}, float3{0.6f, 0, -0.8f}})
        for (int i = 0; i < n; i++)
          for (int j = 0; j < n; j++) {
            const float2 u{(i + 0.5f) / n, (j + 0.5f) / n};
            const LightSample s = light->sampleFacing(point, receiver, u);
            ASSERT_GT(s.pdf, 0.f);
            EXPECT_EQ(s.radiance, (float3{2.f, 2.f, 2.f}));
            const float3 p = point + s.direction * s.distance;
            float3 normal{0.f, 0.f, 1.f};
            uint32_t primitive = 0;
            if (light != &sphereLight) {
              EXPECT_NEAR(p.z, 1.f, 1e-4f);
              EXPECT_GE(p.x, -1e-4f);
              EXPECT_LE(p.x, 1.f + 1e-4f);
              EXPECT_GE(p.y, -1e-4f);
              EXPECT_LE(p.y, 1.f + 1e-4f);
              if (light == &squareLight)
                primitive = p.x >= p.y ? 0 : 1;
              else {
                // The cell's two triangles: lower right first.
                const int cx = std::min(int(p.x * side), side - 1);
                const int cy = std::min(int(p.y * side), side - 1);
                const float fx = p.x * side - float(cx),
                            fy = p.y * side - float(cy);
                primitive = uint32_t(2 * (cy * side + cx) + (fx >= fy ? 0 : 1));
              }
            } else {
              const float3 fromCenter = p - float3{3.f, 0.f, 0.f};
              EXPECT_NEAR(length(fromCenter), 0.5f, 1e-4f);
              normal = normalize(fromCenter);
            }
            const float cosine = std::abs(dot(normal, s.direction));
            if (cosine < 0.05f)
              continue; // grazing: p's rounding dominates the check's cosine
            EXPECT_NEAR(light->pdfOfHit(point,
                            receiver,
                            s.direction,
                            primitive,
                            s.distance,
                            cosine),
                s.pdf,
                2e-3f * s.pdf);
          }
}

TEST(EmissiveSurface, WithoutAreaItIsEmptyAndSamplesNothing)
{
  EmitterShape degenerate;
  degenerate.triangles = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  const EmissiveSurface light(degenerate, {1.f, 1.f, 1.f});
  EXPECT_TRUE(light.isEmpty());
  EXPECT_EQ(light.sample({0, 0, 1}, {0.5f, 0.5f}).pdf, 0.f);
  EXPECT_EQ(light.pdfOfHit({0, 0, 1}, {0, 0, 0}, {0, 0, -1}, 0, 1.f, 1.f), 0.f);
}

} // namespace
} // namespace prism
