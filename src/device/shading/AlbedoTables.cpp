#include "AlbedoTables.h"

#include "Fresnel.h"
#include "Microfacet.h"
#include "Sampling.h"

#include <numbers>

namespace prism {

namespace {

// 32 x 32 keeps interpolation error of E under 0.5% (the white-furnace test
// checks the end result) while generation stays well under 0.1 s.
constexpr int kSize = 32;

// Grid abscissae: cos theta and roughness both uniform on [0, 1]. Roughness,
// not alpha, spreads the entries evenly over how lobes actually change.
float gridValue(int i)
{
  return float(i) / float(kSize - 1);
}

struct Tables
{
  float ggxTotal[kSize][kSize]; // [roughness][cos theta]
  float ggxSchlick[kSize][kSize];
  float ggxAverage[kSize]; // [roughness]
  float ggxSchlickAverage[kSize];
  float sheen[kSize][kSize];

  Tables()
  {
    for (int r = 0; r < kSize; r++) {
      for (int m = 0; m < kSize; m++)
        fillGgx(r, m);
      ggxAverage[r] = cosineAverage(ggxTotal[r]);
      ggxSchlickAverage[r] = cosineAverage(ggxSchlick[r]);
    }
    for (int r = 0; r < kSize; r++) {
      fillSheenRow(r);
    }
  }

  // 2 * integral of the piecewise-linear interpolant of `row` times mu; on a
  // segment [a, a + h] with end values p, q it is h (p (a + h/3) + q (a + 2h/3)).
  static float cosineAverage(const float *row)
  {
    const double h = 1.0 / (kSize - 1);
    double sum = 0.0;
    for (int i = 0; i + 1 < kSize; i++) {
      const double a = i * h;
      sum += h * (row[i] * (a + h / 3.0) + row[i + 1] * (a + 2.0 * h / 3.0));
    }
    return float(sum);
  }

  // Stratified visible-normal sampling: the estimator G2 / G1(wo) is bounded
  // by 1, so 32 x 32 strata give ~0.1% error even for near-mirror lobes.
  void fillGgx(int r, int m)
  {
    const float roughness = gridValue(r);
    const float alpha = roughness * roughness;
    const float mu = gridValue(m);
    if (r == 0) {
      ggxTotal[r][m] = 1.f;
      ggxSchlick[r][m] = schlickWeight(mu);
      return;
    }
    // cos theta = 0 itself is degenerate; its limit is reached well before.
    const float cosO = max(mu, 1e-3f);
    const float3 wo{std::sqrt(1.f - cosO * cosO), 0.f, cosO};
    constexpr int kStrata = 32;
    double total = 0.0, schlick = 0.0;
    for (int i = 0; i < kStrata; i++) {
      for (int j = 0; j < kStrata; j++) {
        const float2 u{(i + 0.5f) / kStrata, (j + 0.5f) / kStrata};
        const float3 h = sampleGgxVisibleNormal(wo, alpha, alpha, u);
        const float3 wi = reflectDirection(wo, h);
        if (wi.z <= 0.f)
          continue;
        const float lambdaO = ggxLambda(wo, alpha);
        const float weight =
            (1.f + lambdaO) / (1.f + lambdaO + ggxLambda(wi, alpha));
        total += weight;
        schlick += weight * schlickWeight(dot(wo, h));
      }
    }
    ggxTotal[r][m] = float(total / (kStrata * kStrata));
    ggxSchlick[r][m] = float(schlick / (kStrata * kStrata));
  }

  // Quadrature over the hemisphere of wi: mu_i = t^2 crowds nodes near the
  // horizon, where low-roughness sheen concentrates; phi over [0, pi] twice
  // by symmetry. Lambda(mu_i) depends on the row only, so it is hoisted.
  void fillSheenRow(int r)
  {
    const float alpha = charlieAlpha(gridValue(r));
    constexpr int kNodesT = 64, kNodesPhi = 32;
    float muI[kNodesT], lambdaI[kNodesT], weightI[kNodesT];
    for (int k = 0; k < kNodesT; k++) {
      const float t = (k + 0.5f) / kNodesT;
      muI[k] = t * t;
      lambdaI[k] = charlieLambda(muI[k], alpha);
      weightI[k] = 2.f * t / kNodesT; // d mu = 2 t dt
    }
    const float dPhi = std::numbers::pi_v<float> / kNodesPhi;
    for (int m = 0; m < kSize; m++) {
      const float cosO = max(gridValue(m), 1e-3f);
      const float3 wo{std::sqrt(1.f - cosO * cosO), 0.f, cosO};
      const float lambdaO = charlieLambda(cosO, alpha);
      double sum = 0.0;
      for (int k = 0; k < kNodesT; k++) {
        const float sinI = std::sqrt(1.f - muI[k] * muI[k]);
        // f cos_i = D G2 / (4 cos_o): the cos_i of f cancels.
        const float common =
            weightI[k] * dPhi / (4.f * cosO * (1.f + lambdaO + lambdaI[k]));
        for (int p = 0; p < kNodesPhi; p++) {
          const float phi = (p + 0.5f) * dPhi;
          const float3 wi{sinI * std::cos(phi), sinI * std::sin(phi), muI[k]};
          sum += common * charlieD(normalize(wo + wi), alpha);
        }
      }
      sheen[r][m] = float(min(2.0 * sum, 1.0));
    }
  }
};

// NOTE: built by the first caller on any thread; C++ guarantees the other
// threads wait for it.
const Tables &tables()
{
  static const Tables instance;
  return instance;
}

struct Bilinear
{
  int r0, m0;
  float fr, fm;
};

Bilinear locate(float cosTheta, float roughness)
{
  const float x = clamp(cosTheta, 0.f, 1.f) * float(kSize - 1);
  const float y = clamp(roughness, 0.f, 1.f) * float(kSize - 1);
  const int m0 = min(int(x), kSize - 2);
  const int r0 = min(int(y), kSize - 2);
  return {r0, m0, y - float(r0), x - float(m0)};
}

float interpolate(const float (&table)[kSize][kSize], const Bilinear &b)
{
  const float low = lerp(table[b.r0][b.m0], table[b.r0][b.m0 + 1], b.fm);
  const float high =
      lerp(table[b.r0 + 1][b.m0], table[b.r0 + 1][b.m0 + 1], b.fm);
  return lerp(low, high, b.fr);
}

} // namespace

GgxAlbedo ggxAlbedo(float cosTheta, float roughness)
{
  const Tables &t = tables();
  const Bilinear b = locate(cosTheta, roughness);
  return {interpolate(t.ggxTotal, b),
      interpolate(t.ggxSchlick, b),
      lerp(t.ggxAverage[b.r0], t.ggxAverage[b.r0 + 1], b.fr),
      lerp(t.ggxSchlickAverage[b.r0], t.ggxSchlickAverage[b.r0 + 1], b.fr)};
}

GgxAlbedo mirrorAlbedo(float cosTheta)
{
  // 2 * integral of (1 - mu)^5 mu dmu = 2 B(2, 6) = 1/21.
  return {1.f, schlickWeight(cosTheta), 1.f, 1.f / 21.f};
}

float sheenAlbedo(float cosTheta, float sheenRoughness)
{
  // The table's roughness axis is the clamped one charlieAlpha uses.
  return interpolate(tables().sheen,
      locate(cosTheta, clamp(sheenRoughness, 0.05f, 1.f)));
}

} // namespace prism
