// The warps BSDFs, lights and the ambient-occlusion renderer share: each
// lands where it should with the density it claims (chi-square at
// significance 0.001).
#include "math/SphereSampling.h"

#include "../shading/ShadingTestUtil.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

using namespace prism;

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

} // namespace

TEST(SphereSampling, ConcentricDiskIsUniformOnTheDisk)
{
  constexpr int kCount = 100000, kBins = 20;
  std::vector<double> radial(kBins, 0.0), angular(kBins, 0.0);
  for (int i = 0; i < kCount; i++) {
    const float2 p = sampleConcentricDisk(uniform2(i));
    const float r2 = p.x * p.x + p.y * p.y;
    ASSERT_LE(r2, 1.f + 1e-6f);
    // Uniform area: r^2 and the angle are uniform.
    radial[min(int(r2 * kBins), kBins - 1)] += 1.0;
    const float angle = std::atan2(p.y, p.x) + kPi;
    angular[min(int(angle / (2.f * kPi) * kBins), kBins - 1)] += 1.0;
  }
  const std::vector<double> expected(kBins, double(kCount) / kBins);
  EXPECT_TRUE(test::passesChiSquare(radial, expected));
  EXPECT_TRUE(test::passesChiSquare(angular, expected));
  EXPECT_EQ(sampleConcentricDisk({0.5f, 0.5f}), (float2{0.f, 0.f}));
}

TEST(SphereSampling, CosineHemisphere)
{
  constexpr int kCount = 100000, kBins = 20;
  std::vector<double> counts(kBins, 0.0);
  double meanZ = 0.0;
  for (int i = 0; i < kCount; i++) {
    const float3 w = sampleCosineHemisphere(uniform2(i));
    ASSERT_NEAR(length(w), 1.f, 1e-5f);
    ASSERT_GE(w.z, 0.f);
    meanZ += w.z;
    // Under a cosine density z^2 is uniform on [0, 1].
    counts[min(int(w.z * w.z * kBins), kBins - 1)] += 1.0;
  }
  const std::vector<double> expected(kBins, double(kCount) / kBins);
  EXPECT_TRUE(test::passesChiSquare(counts, expected));
  EXPECT_NEAR(meanZ / kCount, 2.0 / 3.0, 3e-3);
  EXPECT_FLOAT_EQ(cosineHemispherePdf(1.f), 1.f / kPi);
  EXPECT_EQ(cosineHemispherePdf(-0.5f), 0.f);
}

TEST(SphereSampling, UniformSphereHemisphereAndCap)
{
  constexpr int kCount = 50000;
  double sphereZ = 0.0, hemisphereZ = 0.0, capZ = 0.0, tinyCapZ = 0.0;
  const float cosMax = 0.8f, tinyCosMax = 0.99999f;
  for (int i = 0; i < kCount; i++) {
    const float2 u = uniform2(i);
    const float3 s = sampleUniformSphere(u);
    const float3 h = sampleUniformHemisphere(u);
    const float3 c = sampleUniformCap(u, 1.f - cosMax);
    const float3 t = sampleUniformCap(u, 1.f - tinyCosMax);
    ASSERT_NEAR(length(s), 1.f, 1e-5f);
    ASSERT_NEAR(length(c), 1.f, 1e-5f);
    ASSERT_NEAR(length(t), 1.f, 1e-5f);
    ASSERT_GE(h.z, 0.f);
    ASSERT_GE(c.z, cosMax - 1e-6f);
    ASSERT_GE(t.z, tinyCosMax - 1e-6f);
    sphereZ += s.z;
    hemisphereZ += h.z;
    capZ += c.z;
    tinyCapZ += std::sqrt(t.x * t.x + t.y * t.y);
  }
  // z is uniform on each domain; in the tiny cap sin(theta) ~ sqrt(u) * max.
  EXPECT_NEAR(sphereZ / kCount, 0.0, 1e-2);
  EXPECT_NEAR(hemisphereZ / kCount, 0.5, 5e-3);
  EXPECT_NEAR(capZ / kCount, 0.5 * (1.0 + cosMax), 1e-3);
  const double sinMax = std::sqrt(1.0 - double(tinyCosMax) * tinyCosMax);
  EXPECT_NEAR(tinyCapZ / kCount / sinMax, 2.0 / 3.0, 1e-2);
  EXPECT_FLOAT_EQ(uniformSpherePdf(), 0.25f / kPi);
  EXPECT_FLOAT_EQ(uniformHemispherePdf(), 0.5f / kPi);
  EXPECT_FLOAT_EQ(uniformCapPdf(1.f - cosMax), 1.f / (2.f * kPi * 0.2f));
}
