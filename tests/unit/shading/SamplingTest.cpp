// MIS heuristics and GGX visible normals: the warp lands where it should
// with the density it claims (quadrature to 0.5%); the warps and frames
// shading shares with lights are tested in tests/unit/math.
#include "shading/Microfacet.h"
#include "shading/Sampling.h"

#include "ShadingTestUtil.h"

#include <gtest/gtest.h>

#include <numbers>
#include <vector>

using namespace prism;

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

} // namespace

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
