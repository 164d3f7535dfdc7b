// Warps, MIS heuristics, the orthonormal basis and GGX visible normals:
// each warp lands where it should with the density it claims (chi-square at
// significance 0.001, quadrature to 0.5%).
#include "shading/Microfacet.h"
#include "shading/Sampling.h"

#include "ShadingTestUtil.h"

#include <gtest/gtest.h>

#include <numbers>
#include <vector>

using namespace prism;

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

float2 uniform2(uint32_t i)
{
  return RandomSequence({i, 0}, 0, 0).get2D(0);
}

} // namespace

TEST(Sampling, ConcentricDiskIsUniformOnTheDisk)
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

TEST(Sampling, CosineHemisphere)
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

TEST(Sampling, UniformSphereHemisphereAndCone)
{
  constexpr int kCount = 50000;
  double sphereZ = 0.0, hemisphereZ = 0.0, coneZ = 0.0, tinyConeZ = 0.0;
  const float cosMax = 0.8f, tinyCosMax = 0.99999f;
  for (int i = 0; i < kCount; i++) {
    const float2 u = uniform2(i);
    const float3 s = sampleUniformSphere(u);
    const float3 h = sampleUniformHemisphere(u);
    const float3 c = sampleUniformCone(u, cosMax);
    const float3 t = sampleUniformCone(u, tinyCosMax);
    ASSERT_NEAR(length(s), 1.f, 1e-5f);
    ASSERT_NEAR(length(c), 1.f, 1e-5f);
    ASSERT_NEAR(length(t), 1.f, 1e-5f);
    ASSERT_GE(h.z, 0.f);
    ASSERT_GE(c.z, cosMax - 1e-6f);
    ASSERT_GE(t.z, tinyCosMax - 1e-6f);
    sphereZ += s.z;
    hemisphereZ += h.z;
    coneZ += c.z;
    tinyConeZ += std::sqrt(t.x * t.x + t.y * t.y);
  }
  // z is uniform on each domain; in the tiny cone sin(theta) ~ sqrt(u) * max.
  EXPECT_NEAR(sphereZ / kCount, 0.0, 1e-2);
  EXPECT_NEAR(hemisphereZ / kCount, 0.5, 5e-3);
  EXPECT_NEAR(coneZ / kCount, 0.5 * (1.0 + cosMax), 1e-3);
  const double sinMax = std::sqrt(1.0 - double(tinyCosMax) * tinyCosMax);
  EXPECT_NEAR(tinyConeZ / kCount / sinMax, 2.0 / 3.0, 1e-2);
  EXPECT_FLOAT_EQ(uniformSpherePdf(), 0.25f / kPi);
  EXPECT_FLOAT_EQ(uniformHemispherePdf(), 0.5f / kPi);
  EXPECT_FLOAT_EQ(uniformConePdf(cosMax), 1.f / (2.f * kPi * 0.2f));
}

TEST(Sampling, MisHeuristics)
{
  EXPECT_FLOAT_EQ(balanceHeuristic(1, 3.f, 1, 1.f), 0.75f);
  EXPECT_FLOAT_EQ(powerHeuristic(1, 3.f, 1, 1.f), 0.9f);
  EXPECT_FLOAT_EQ(powerHeuristic(2, 1.f, 1, 2.f), 0.5f);
  EXPECT_FLOAT_EQ(
      powerHeuristic(1, 1.f, 1, 3.f) + powerHeuristic(1, 3.f, 1, 1.f), 1.f);
  const float inf = std::numeric_limits<float>::infinity();
  EXPECT_EQ(powerHeuristic(1, inf, 1, 5.f), 1.f);
  EXPECT_EQ(balanceHeuristic(1, inf, 1, 5.f), 1.f);
  EXPECT_EQ(powerHeuristic(1, 0.f, 1, 0.f), 0.f);
  EXPECT_EQ(balanceHeuristic(1, 0.f, 1, 0.f), 0.f);
  // Huge pdfs must not overflow when squared.
  EXPECT_FLOAT_EQ(powerHeuristic(1, 1e30f, 1, 1e30f), 0.5f);
}

TEST(Sampling, OrthonormalBasis)
{
  std::vector<float3> normals = {{0, 0, 1},
      {0, 0, -1},
      {1, 0, 0},
      {0, -1, 0},
      normalize(float3{1e-8f, 0, -1})};
  for (int i = 0; i < 2000; i++)
    normals.push_back(sampleUniformSphere(uniform2(i)));
  for (const float3 n : normals) {
    float3 b1, b2;
    orthonormalBasis(n, b1, b2);
    ASSERT_NEAR(length(b1), 1.f, 1e-5f);
    ASSERT_NEAR(length(b2), 1.f, 1e-5f);
    ASSERT_NEAR(dot(b1, n), 0.f, 1e-5f);
    ASSERT_NEAR(dot(b2, n), 0.f, 1e-5f);
    ASSERT_NEAR(dot(b1, b2), 0.f, 1e-5f);
    // Right-handed: b1 x b2 = n.
    ASSERT_NEAR(length(cross(b1, b2) - n), 0.f, 1e-5f);

    const ShadingFrame frame = ShadingFrame::fromNormal(n);
    const float3 v = normalize(float3{0.3f, -0.5f, 0.8f});
    ASSERT_NEAR(length(frame.toWorld(frame.toLocal(v)) - v), 0.f, 1e-5f);
    ASSERT_NEAR(frame.toLocal(n).z, 1.f, 1e-5f);
  }
  const ShadingFrame frame =
      ShadingFrame::fromNormalTangent({0, 0, 1}, {2, 0, 0.5f});
  EXPECT_NEAR(length(frame.tangent - float3{1, 0, 0}), 0.f, 1e-6f);
  EXPECT_NEAR(length(frame.bitangent - float3{0, 1, 0}), 0.f, 1e-6f);
  // A tangent along the normal falls back to any basis.
  const ShadingFrame fallback =
      ShadingFrame::fromNormalTangent({0, 0, 1}, {0, 0, 3});
  EXPECT_NEAR(dot(fallback.tangent, fallback.normal), 0.f, 1e-6f);
}

namespace {

// The integral of the visible-normal pdf over [theta0, theta1] x [phi0,
// phi1], by an n x n midpoint rule in (theta, phi).
double integrateVisibleNormalPdf(float3 wo,
    float alpha,
    double theta0,
    double theta1,
    double phi0,
    double phi1,
    int n)
{
  const double dTheta = (theta1 - theta0) / n, dPhi = (phi1 - phi0) / n;
  double sum = 0.0;
  for (int i = 0; i < n; i++) {
    const double theta = theta0 + (i + 0.5) * dTheta;
    const double s = std::sin(theta);
    for (int j = 0; j < n; j++) {
      const double phi = phi0 + (j + 0.5) * dPhi;
      const float3 h{float(s * std::cos(phi)),
          float(s * std::sin(phi)),
          float(std::cos(theta))};
      sum += ggxVisibleNormalPdf(wo, h, alpha) * s;
    }
  }
  return sum * dTheta * dPhi;
}

} // namespace

TEST(Sampling, GgxVisibleNormalPdfIsNormalised)
{
  for (float alpha : {0.1f, 0.5f, 1.f}) {
    for (float mu : {1.f, 0.5f, 0.1f}) {
      const float3 wo{std::sqrt(1.f - mu * mu), 0.f, mu};
      EXPECT_NEAR(
          integrateVisibleNormalPdf(wo, alpha, 0.0, kPi / 2, 0.0, 2 * kPi, 400),
          1.0,
          5e-3)
          << "alpha " << alpha << " mu " << mu;
    }
  }
}

TEST(Sampling, GgxVisibleNormalSamplesFollowTheirPdf)
{
  constexpr int kBinsTheta = 12, kBinsPhi = 16, kCount = 60000;
  for (float alpha : {0.3f, 0.8f}) {
    // Off the x axis, to exercise the tangent frame.
    const float3 wo = normalize(float3{0.5f, 0.4f, 0.6f});
    std::vector<double> observed(kBinsTheta * kBinsPhi, 0.0);
    for (int i = 0; i < kCount; i++) {
      const float3 h = sampleGgxVisibleNormal(wo, alpha, alpha, uniform2(i));
      ASSERT_NEAR(length(h), 1.f, 1e-5f);
      ASSERT_GE(h.z, 0.f);
      const float theta = std::acos(clamp(h.z, 0.f, 1.f));
      const float phi = std::atan2(h.y, h.x) + kPi;
      const int a = min(int(theta / (kPi / 2) * kBinsTheta), kBinsTheta - 1);
      const int b = min(int(phi / (2 * kPi) * kBinsPhi), kBinsPhi - 1);
      observed[a * kBinsPhi + b] += 1.0;
    }
    std::vector<double> expected(observed.size());
    for (int a = 0; a < kBinsTheta; a++) {
      for (int b = 0; b < kBinsPhi; b++) {
        const double t0 = a * (kPi / 2) / kBinsTheta;
        const double p0 = b * (2 * kPi) / kBinsPhi - kPi;
        expected[a * kBinsPhi + b] = kCount
                                     * integrateVisibleNormalPdf(wo,
                                         alpha,
                                         t0,
                                         t0 + (kPi / 2) / kBinsTheta,
                                         p0,
                                         p0 + (2 * kPi) / kBinsPhi,
                                         12);
      }
    }
    EXPECT_TRUE(test::passesChiSquare(observed, expected)) << "alpha " << alpha;
  }
}
