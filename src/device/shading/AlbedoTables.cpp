#include "AlbedoTables.h"

#include "Fresnel.h"
#include "Microfacet.h"
#include "Sampling.h"

#include <cmath>
#include <numbers>

namespace prism {

namespace {

// 32 x 32 entries keep interpolation error of E under 0.5% (the white
// furnace test checks the end result); generation takes ~40 ms.
constexpr int kSize = 32;

// Grid abscissae. Roughness is uniform (not alpha: lobes change evenly in
// roughness). cos theta is uniform in sqrt(cos theta), crowding entries
// towards the horizon where albedos change fastest.
float gridRoughness(int i)
{
  return float(i) / float(kSize - 1);
}
float gridCos(int i)
{
  const float t = float(i) / float(kSize - 1);
  return t * t;
}
// cos theta = 0 itself is degenerate; the curves reach their limit well
// before 1e-4.
float gridCosForIntegration(int i)
{
  return max(gridCos(i), 1e-4f);
}

struct Tables
{
  float ggxTotal[kSize][kSize]; // [roughness][cos theta]
  float ggxSchlick[kSize][kSize];
  float ggxMeanCos[kSize][kSize];
  float ggxAverage[kSize]; // [roughness]
  float ggxSchlickAverage[kSize];
  float sheen[kSize][kSize];

  Tables()
  {
    for (int r = 0; r < kSize; r++) {
      fillGgxRow(r);
      ggxAverage[r] = cosineAverage(ggxTotal[r]);
      ggxSchlickAverage[r] = cosineAverage(ggxSchlick[r]);
      fillSheenRow(r);
    }
  }

  // 2 * integral over mu of E(mu) mu for the interpolant, which is linear in
  // t = sqrt(mu): the integral of 4 t^3 E(t) dt, exact on each segment.
  static float cosineAverage(const float *row)
  {
    double sum = 0.0;
    for (int i = 0; i + 1 < kSize; i++) {
      const double a = double(i) / (kSize - 1);
      const double b = double(i + 1) / (kSize - 1);
      const double a4 = a * a * a * a, b4 = b * b * b * b;
      const double a5 = a4 * a, b5 = b4 * b;
      // Integrals of t^3 (b - t) and t^3 (t - a) over [a, b].
      const double towardsA = b * (b4 - a4) / 4.0 - (b5 - a5) / 5.0;
      const double towardsB = (b5 - a5) / 5.0 - a * (b4 - a4) / 4.0;
      sum += 4.0 / (b - a) * (row[i] * towardsA + row[i + 1] * towardsB);
    }
    return float(sum);
  }

  // Visible-normal sampling, whose estimator G2 / G1(wo) is bounded by 1.
  // Strata in u.x follow 1 - (1 - t)^3 so that GGX's long tail (normals
  // that send wi below the horizon) is resolved: 0.15% worst-case error.
  void fillGgxRow(int r)
  {
    const float roughness = gridRoughness(r);
    const float alpha = roughness * roughness;
    constexpr int kStrataX = 32, kStrataY = 8;
    float ux[kStrataX], weight[kStrataX];
    for (int i = 0; i < kStrataX; i++) {
      const float t = 1.f - (i + 0.5f) / kStrataX;
      ux[i] = 1.f - t * t * t;
      weight[i] = 3.f * t * t / (kStrataX * kStrataY);
    }
    for (int m = 0; m < kSize; m++) {
      if (r == 0) {
        ggxTotal[r][m] = 1.f;
        ggxSchlick[r][m] = schlickWeight(gridCos(m));
        ggxMeanCos[r][m] = gridCos(m);
        continue;
      }
      const float cosO = gridCosForIntegration(m);
      const float3 wo{std::sqrt(1.f - cosO * cosO), 0.f, cosO};
      const float lambdaO = ggxLambda(wo, alpha);
      double total = 0.0, schlick = 0.0, cosine = 0.0;
      for (int i = 0; i < kStrataX; i++) {
        for (int j = 0; j < kStrataY; j++) {
          const float2 u{ux[i], (j + 0.5f) / kStrataY};
          const float3 h = sampleGgxVisibleNormal(wo, alpha, alpha, u);
          const float3 wi = reflectDirection(wo, h);
          if (wi.z <= 0.f)
            continue;
          const float g =
              (1.f + lambdaO) / (1.f + lambdaO + ggxLambda(wi, alpha));
          total += weight[i] * g;
          const float cosOH = dot(wo, h);
          schlick += weight[i] * g * schlickWeight(cosOH);
          cosine += weight[i] * g * cosOH;
        }
      }
      ggxTotal[r][m] = float(total);
      ggxSchlick[r][m] = float(schlick);
      ggxMeanCos[r][m] = total > 0.0 ? float(cosine / total) : cosO;
    }
  }

  // Quadrature over the hemisphere of wi: mu_i = t^2 crowds nodes near the
  // horizon, where low-roughness sheen concentrates; phi over [0, pi] twice
  // by symmetry. Not clamped: the Lambda fit lets narrow sheen exceed 1 at
  // grazing angles, which the BSDF normalises away.
  void fillSheenRow(int r)
  {
    const float alpha = charlieAlpha(gridRoughness(r));
    constexpr int kNodesT = 32, kNodesPhi = 12;
    float muI[kNodesT], sinI[kNodesT], lambdaI[kNodesT], weightI[kNodesT];
    for (int k = 0; k < kNodesT; k++) {
      const float t = (k + 0.5f) / kNodesT;
      muI[k] = t * t;
      sinI[k] = std::sqrt(1.f - muI[k] * muI[k]);
      lambdaI[k] = charlieLambda(muI[k], alpha);
      weightI[k] = 2.f * t / kNodesT; // d mu = 2 t dt
    }
    const float dPhi = std::numbers::pi_v<float> / kNodesPhi;
    float cosPhi[kNodesPhi], sinPhi[kNodesPhi];
    for (int p = 0; p < kNodesPhi; p++) {
      cosPhi[p] = std::cos((p + 0.5f) * dPhi);
      sinPhi[p] = std::sin((p + 0.5f) * dPhi);
    }
    for (int m = 0; m < kSize; m++) {
      const float cosO = gridCosForIntegration(m);
      const float3 wo{std::sqrt(1.f - cosO * cosO), 0.f, cosO};
      const float lambdaO = charlieLambda(cosO, alpha);
      double sum = 0.0;
      for (int k = 0; k < kNodesT; k++) {
        // f cos_i = D G2 / (4 cos_o): the cos_i of f cancels.
        const float common =
            weightI[k] * dPhi / (4.f * cosO * (1.f + lambdaO + lambdaI[k]));
        for (int p = 0; p < kNodesPhi; p++) {
          const float3 wi{sinI[k] * cosPhi[p], sinI[k] * sinPhi[p], muI[k]};
          sum += common * charlieD(normalize(wo + wi), alpha);
        }
      }
      sheen[r][m] = float(2.0 * sum);
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
  const float x = std::sqrt(clamp(cosTheta, 0.f, 1.f)) * float(kSize - 1);
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
      lerp(t.ggxSchlickAverage[b.r0], t.ggxSchlickAverage[b.r0 + 1], b.fr),
      interpolate(t.ggxMeanCos, b)};
}

GgxAlbedo mirrorAlbedo(float cosTheta)
{
  // 2 * integral of (1 - mu)^5 mu dmu = 2 B(2, 6) = 1/21.
  return {1.f, schlickWeight(cosTheta), 1.f, 1.f / 21.f, cosTheta};
}

float sheenAlbedo(float cosTheta, float sheenRoughness)
{
  // The table's roughness axis is the clamped one charlieAlpha uses.
  return interpolate(
      tables().sheen, locate(cosTheta, clamp(sheenRoughness, 0.05f, 1.f)));
}

} // namespace prism
