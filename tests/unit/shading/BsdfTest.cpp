// The path tracer's BSDF. Tolerances, and why:
//  - white furnace: |albedo - 1| < 2% (the brief), from stratified Monte
//    Carlo whose noise is ~0.1%;
//  - energy: albedo <= 1.01 + 3 standard errors over a grid of inputs and
//    angles (1% for table interpolation and the layering estimates);
//  - reciprocity, sample/pdf/eval consistency: 1e-4 relative (float
//    rounding of the same expressions in another order);
//  - integral of the pdf = fraction of valid samples within 1%.
#include "shading/AlbedoTables.h"
#include "shading/Bsdf.h"
#include "shading/Fresnel.h"
#include "shading/Sampling.h"

#include "ShadingTestUtil.h"

#include <gtest/gtest.h>

#include <numbers>
#include <string>
#include <utility>
#include <vector>

using namespace prism;

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// A local direction at `cosTheta` from the normal, at azimuth `phi`.
float3 direction(float cosTheta, float phi = 0.3f)
{
  const float s = std::sqrt(max(0.f, 1.f - cosTheta * cosTheta));
  return {s * std::cos(phi), s * std::sin(phi), cosTheta};
}

struct AlbedoEstimate
{
  float3 albedo{0.f, 0.f, 0.f};
  // Standard error as if the samples were independent: an upper bound,
  // stratification only lowers it.
  float3 standardError{0.f, 0.f, 0.f};
  int valid{0}, delta{0};
};

// Integral of f |cos| over wi by sampling the BSDF: a jittered 64 x 64 grid
// for the direction, and for the lobe the same 4096 strata in an order
// shuffled independently of the grid (correlating the two would bias the
// estimate). Refracted samples are scaled back by relativeIor^2: flux, not
// radiance, is what is conserved, so energy conservation reads albedo <= 1.
AlbedoEstimate estimateAlbedo(
    const Bsdf &bsdf, float3 wo, int grid = 64, uint32_t seed = 0)
{
  const int kGrid = grid, kCount = kGrid * kGrid;
  std::vector<uint32_t> lobeStratum(kCount);
  for (int i = 0; i < kCount; i++)
    lobeStratum[i] = uint32_t(i);
  for (int i = kCount - 1; i > 0; i--) {
    const RandomSequence r({uint32_t(i), seed}, 1, 0);
    std::swap(lobeStratum[i], lobeStratum[int(r.get1D(0) * float(i + 1))]);
  }
  double sum[3] = {0.0, 0.0, 0.0}, sum2[3] = {0.0, 0.0, 0.0};
  AlbedoEstimate e;
  for (int i = 0; i < kCount; i++) {
    const RandomSequence r({uint32_t(i), seed}, 0, 0);
    const float2 jitter = r.get2D(0);
    const float2 u{
        ((i % kGrid) + jitter.x) / kGrid, ((i / kGrid) + jitter.y) / kGrid};
    const float uLobe = (float(lobeStratum[i]) + r.get1D(1)) / kCount;
    const BsdfSample s = bsdf.sample(wo, u, uLobe);
    if (!s.valid())
      continue;
    e.valid++;
    e.delta += s.isDelta();
    const float scale = s.relativeIor * s.relativeIor;
    for (int c = 0; c < 3; c++) {
      const double w = double(s.weight[c]) * scale;
      sum[c] += w;
      sum2[c] += w * w;
    }
  }
  for (int c = 0; c < 3; c++) {
    const double mean = sum[c] / kCount;
    e.albedo[c] = float(mean);
    e.standardError[c] =
        float(std::sqrt(max(0.0, sum2[c] / kCount - mean * mean) / kCount));
  }
  return e;
}

std::string describe(const BsdfInputs &in)
{
  char text[512];
  std::snprintf(text,
      sizeof(text),
      "baseColor (%g %g %g) metallic %g roughness %g specular %g "
      "specularColor (%g %g %g) ior %g clearcoat %g/%g (%g %g %g) "
      "transmission %g "
      "thickness %g sheen (%g %g %g)/%g iridescence %g ior %g %g nm "
      "anisotropy %g (%g %g)",
      in.baseColor.x,
      in.baseColor.y,
      in.baseColor.z,
      in.metallic,
      in.roughness,
      in.specular,
      in.specularColor.x,
      in.specularColor.y,
      in.specularColor.z,
      in.ior,
      in.clearcoat,
      in.clearcoatRoughness,
      in.clearcoatNormal.x,
      in.clearcoatNormal.y,
      in.clearcoatNormal.z,
      in.transmission,
      in.thickness,
      in.sheenColor.x,
      in.sheenColor.y,
      in.sheenColor.z,
      in.sheenRoughness,
      in.iridescence,
      in.iridescenceIor,
      in.iridescenceThickness,
      in.anisotropy,
      in.anisotropyDirection.x,
      in.anisotropyDirection.y);
  return text;
}

BsdfInputs whiteMetal(float roughness)
{
  BsdfInputs in;
  in.baseColor = {1.f, 1.f, 1.f};
  in.metallic = 1.f;
  in.roughness = roughness;
  return in;
}

BsdfInputs whitePlastic(float roughness)
{
  BsdfInputs in;
  in.baseColor = {1.f, 1.f, 1.f};
  in.metallic = 0.f;
  in.roughness = roughness;
  in.specular = 1.f;
  return in;
}

BsdfInputs glass(float roughness, float thickness)
{
  BsdfInputs in = whitePlastic(roughness);
  in.transmission = 1.f;
  in.thickness = thickness;
  return in;
}

// Hand-picked corners plus pseudo-random inputs over every parameter's range.
std::vector<BsdfInputs> inputGrid()
{
  std::vector<BsdfInputs> grid;
  for (float r : {0.f, 0.05f, 0.5f, 1.f})
    grid.push_back(whiteMetal(r));
  for (float r : {0.f, 0.4f, 1.f}) {
    grid.push_back(whitePlastic(r));
    grid.push_back(glass(r, 0.f));
    grid.push_back(glass(r, 1.f));
  }
  for (float r : {0.f, 0.2f, 1.f}) {
    BsdfInputs in = whitePlastic(0.5f);
    in.sheenColor = {1.f, 1.f, 1.f};
    in.sheenRoughness = r;
    grid.push_back(in);
  }
  for (float r : {0.f, 0.5f}) {
    BsdfInputs in = whiteMetal(0.3f);
    in.clearcoat = 1.f;
    in.clearcoatRoughness = r;
    grid.push_back(in);
  }
  // clearcoatNormal: a slight and a strong tilt, rough and smooth.
  for (float3 tilt : {float3{0.3f, 0.1f, 0.95f}, float3{0.7f, 0.f, 0.7f}}) {
    for (float r : {0.f, 0.3f}) {
      BsdfInputs in = whitePlastic(0.6f);
      in.clearcoat = 1.f;
      in.clearcoatRoughness = r;
      in.clearcoatNormal = tilt;
      grid.push_back(in);
    }
  }
  for (float thickness : {250.f, 500.f, 900.f}) {
    BsdfInputs in = whitePlastic(0.3f);
    in.iridescence = 1.f;
    in.iridescenceThickness = thickness;
    grid.push_back(in);
    in = whiteMetal(0.2f);
    in.iridescence = 1.f;
    in.iridescenceThickness = thickness;
    grid.push_back(in);
  }
  {
    BsdfInputs in = whitePlastic(0.f);
    in.specularColor = {3.f, 1.f, 0.2f};
    in.ior = 2.5f;
    grid.push_back(in);
  }
  // KHR_materials_anisotropy: metal, plastic and glass stretched along a
  // turned direction, from a mirror base and a rough one.
  for (float strength : {0.5f, 1.f})
    for (float r : {0.f, 0.3f})
      for (BsdfInputs in : {whiteMetal(r), whitePlastic(r), glass(r, 1.f)}) {
        in.anisotropy = strength;
        in.anisotropyDirection = {0.6f, 0.8f};
        grid.push_back(in);
      }

  const auto pick = [](const RandomSequence &r, uint32_t d, float a, float b) {
    const float u = r.get1D(d);
    return u < 0.25f ? a : (u < 0.5f ? b : lerp(a, b, r.get1D(d + 100)));
  };
  for (uint32_t i = 0; i < 48; i++) {
    const RandomSequence r({i, 77}, 0, 0);
    BsdfInputs in;
    in.baseColor = {r.get1D(0), r.get1D(1), r.get1D(2)};
    in.metallic = pick(r, 3, 0.f, 1.f);
    in.roughness = pick(r, 4, 0.f, 1.f);
    in.specular = pick(r, 5, 0.f, 1.f);
    in.specularColor = float3{r.get1D(6), r.get1D(7), r.get1D(8)} * 2.f;
    in.ior = 1.05f + 1.5f * r.get1D(9);
    in.clearcoat = pick(r, 10, 0.f, 1.f);
    in.clearcoatRoughness = pick(r, 11, 0.f, 1.f);
    in.transmission = pick(r, 12, 0.f, 1.f);
    in.thickness = r.get1D(13) < 0.5f ? 0.f : 1.f;
    const float sheen = pick(r, 14, 0.f, 1.f);
    in.sheenColor = float3{r.get1D(15), r.get1D(16), r.get1D(17)} * sheen;
    in.sheenRoughness = pick(r, 18, 0.f, 1.f);
    in.iridescence = pick(r, 19, 0.f, 1.f);
    in.iridescenceIor = 1.1f + r.get1D(20);
    in.iridescenceThickness = 1000.f * r.get1D(21);
    grid.push_back(in);
  }
  return grid;
}

// Front-side views from normal to grazing, and one from the back.
const float3 kViews[] = {direction(0.95f, 0.2f),
    direction(0.5f, 1.f),
    direction(0.15f, 2.f),
    direction(0.03f, 4.f),
    direction(-0.6f, 5.f)};

float relativeError(float3 a, float3 b)
{
  const float scale = max(maxComponent(abs(a)), maxComponent(abs(b)));
  return scale > 0.f ? maxComponent(abs(a - b)) / scale : 0.f;
}

} // namespace

TEST(Bsdf, LambertWhiteFurnace)
{
  const Bsdf bsdf(matteBsdfInputs({1.f, 1.f, 1.f}));
  for (const float3 wo : kViews) {
    // Cosine sampling makes every weight exactly f cos / pdf = 1.
    const AlbedoEstimate e = estimateAlbedo(bsdf, wo);
    EXPECT_NEAR(e.albedo.x, 1.f, 1e-5f);
    EXPECT_EQ(e.delta, 0);
    // Independently of the sampler: quadrature of eval over the sphere.
    double sum = 0.0;
    constexpr int kN = 200;
    for (int i = 0; i < kN; i++) {
      for (int j = 0; j < kN; j++) {
        const float z = 1.f - 2.f * (i + 0.5f) / kN;
        const float3 wi = direction(z, 2.f * kPi * (j + 0.5f) / kN);
        sum += bsdf.eval(wo, wi).x * std::abs(wi.z);
      }
    }
    EXPECT_NEAR(sum * 4.0 * kPi / (kN * kN), 1.0, 1e-3);
  }
  const float3 color{0.8f, 0.5f, 0.2f};
  const Bsdf matte(matteBsdfInputs(color));
  const float3 f = matte.eval(direction(0.7f), direction(0.2f, 2.f));
  EXPECT_NEAR(length(f - color / kPi), 0.f, 1e-6f);
  EXPECT_EQ(matte.eval(direction(0.7f), direction(-0.2f)), (float3{0, 0, 0}));
  // Two-sided.
  EXPECT_NEAR(
      length(matte.eval(direction(-0.7f), direction(-0.2f)) - color / kPi),
      0.f,
      1e-6f);
}

// Kulla-Conty compensation: a white rough metal loses no energy.
TEST(Bsdf, RoughMetalWhiteFurnace)
{
  for (float roughness : {0.05f, 0.25f, 0.5f, 0.75f, 1.f}) {
    const Bsdf bsdf(whiteMetal(roughness));
    for (float mu : {1.f, 0.7f, 0.4f, 0.15f}) {
      const AlbedoEstimate e = estimateAlbedo(bsdf, direction(mu));
      EXPECT_NEAR(e.albedo.x, 1.f, 0.02f)
          << "roughness " << roughness << " cos " << mu;
    }
  }
}

// The layering is energy-preserving too: white plastic and clear thin glass.
TEST(Bsdf, DielectricWhiteFurnace)
{
  for (float roughness : {0.f, 0.3f, 0.7f, 1.f}) {
    for (const BsdfInputs &in :
        {whitePlastic(roughness), glass(roughness, 0.f)}) {
      const Bsdf bsdf(in);
      for (float mu : {1.f, 0.5f, 0.15f}) {
        const AlbedoEstimate e = estimateAlbedo(bsdf, direction(mu));
        EXPECT_NEAR(e.albedo.x, 1.f, 0.02f) << describe(in) << " cos " << mu;
      }
    }
  }
  // A smooth refractive interface: R + T = 1 in flux, from both sides, with
  // total internal reflection on the dense side (inside, or outside when
  // ior < 1).
  for (float ior : {1.5f, 0.75f}) {
    BsdfInputs in = glass(0.f, 1.f);
    in.ior = ior;
    const Bsdf smooth(in);
    for (float mu : {1.f, 0.5f, 0.15f, -1.f, -0.8f, -0.3f}) {
      const AlbedoEstimate e = estimateAlbedo(smooth, direction(mu));
      EXPECT_NEAR(e.albedo.x, 1.f, 1e-4f) << "ior " << ior << " cos " << mu;
    }
  }
}

TEST(Bsdf, NoConfigurationCreatesEnergy)
{
  float highest = 0.f;
  for (const BsdfInputs &in : inputGrid()) {
    const Bsdf bsdf(in);
    for (const float3 wo : kViews) {
      const AlbedoEstimate e = estimateAlbedo(bsdf, wo, 40);
      for (int c = 0; c < 3; c++) {
        EXPECT_LE(e.albedo[c], 1.01f + 3.f * e.standardError[c])
            << describe(in) << " wo.z " << wo.z;
        highest = max(highest, e.albedo[c] - 3.f * e.standardError[c]);
      }
    }
  }
  RecordProperty("highestAlbedoMinus3Sigma", std::to_string(highest));
}

TEST(Bsdf, ReflectionIsReciprocal)
{
  for (const BsdfInputs &in : inputGrid()) {
    const Bsdf bsdf(in);
    for (uint32_t i = 0; i < 64; i++) {
      const RandomSequence r({i, 5}, 0, 0);
      float3 a = sampleCosineHemisphere(r.get2D(0));
      float3 b = sampleUniformHemisphere(r.get2D(1));
      // Two-sided surfaces are reciprocal on the back too.
      if (i % 4 == 3 && !bsdf.isVolumeBoundary()) {
        a.z = -a.z;
        b.z = -b.z;
      }
      const float3 ab = bsdf.eval(a, b), ba = bsdf.eval(b, a);
      ASSERT_LE(relativeError(ab, ba), 1e-4f) << describe(in);
    }
  }
}

TEST(Bsdf, SampleMatchesEvalAndPdf)
{
  for (const BsdfInputs &in : inputGrid()) {
    const Bsdf bsdf(in);
    for (const float3 wo : kViews) {
      for (uint32_t i = 0; i < 64; i++) {
        const RandomSequence r({i, 11}, 0, 0);
        const BsdfSample s = bsdf.sample(wo, r.get2D(0), r.get1D(1));
        if (!s.valid())
          continue;
        ASSERT_NEAR(length(s.wi), 1.f, 1e-4f);
        ASSERT_EQ(s.isTransmission(), s.wi.z * wo.z < 0.f) << describe(in);
        ASSERT_GT(s.pdf, 0.f);
        ASSERT_LE(
            relativeError(s.weight, s.f * (std::abs(s.wi.z) / s.pdf)), 1e-4f);
        if (s.isDelta())
          continue;
        const float pdf = bsdf.pdf(wo, s.wi);
        ASSERT_LE(std::abs(pdf - s.pdf), 1e-4f * s.pdf) << describe(in);
        ASSERT_LE(relativeError(bsdf.eval(wo, s.wi), s.f), 1e-4f)
            << describe(in);
      }
    }
  }
}

namespace {

// Integral of pdf(wo, .) over the sphere: midpoint rule in (theta, phi),
// fine enough for lobes with roughness >= 0.4.
double integratePdf(const Bsdf &bsdf, float3 wo)
{
  constexpr int kTheta = 400, kPhi = 200;
  double sum = 0.0;
  for (int i = 0; i < kTheta; i++) {
    const float theta = kPi * (i + 0.5f) / kTheta;
    const float s = std::sin(theta);
    for (int j = 0; j < kPhi; j++) {
      const float phi = 2.f * kPi * (j + 0.5f) / kPhi;
      const float3 wi{s * std::cos(phi), s * std::sin(phi), std::cos(theta)};
      sum += bsdf.pdf(wo, wi) * s;
    }
  }
  return sum * (kPi / kTheta) * (2.0 * kPi / kPhi);
}

std::vector<BsdfInputs> roughInputs()
{
  std::vector<BsdfInputs> inputs = {
      whiteMetal(0.5f), glass(0.5f, 0.f), glass(0.6f, 1.f)};
  BsdfInputs in = whitePlastic(0.4f);
  in.baseColor = {0.7f, 0.3f, 0.1f};
  in.sheenColor = {0.5f, 0.5f, 0.9f};
  in.sheenRoughness = 0.5f;
  in.clearcoat = 0.7f;
  in.clearcoatRoughness = 0.5f;
  in.transmission = 0.4f;
  inputs.push_back(in);
  in = whitePlastic(0.6f);
  in.metallic = 0.4f;
  in.iridescence = 0.8f;
  in.iridescenceThickness = 450.f;
  inputs.push_back(in);
  for (BsdfInputs anisotropic : {whiteMetal(0.5f), glass(0.6f, 1.f)}) {
    anisotropic.anisotropy = 0.8f;
    anisotropic.anisotropyDirection = {-0.28f, 0.96f};
    inputs.push_back(anisotropic);
  }
  return inputs;
}

} // namespace

// The density sample() draws from integrates to the probability that it
// returns a direction at all (the rest falls below the horizon).
TEST(Bsdf, PdfIntegratesToSampledFraction)
{
  for (const BsdfInputs &in : roughInputs()) {
    const Bsdf bsdf(in);
    ASSERT_TRUE(bsdf.hasNonDeltaLobes());
    for (const float3 wo :
        {direction(0.8f), direction(0.3f), direction(-0.6f)}) {
      const AlbedoEstimate e = estimateAlbedo(bsdf, wo);
      ASSERT_EQ(e.delta, 0);
      const double sampled = double(e.valid) / (64 * 64);
      EXPECT_NEAR(integratePdf(bsdf, wo), sampled, 0.01)
          << describe(in) << " wo.z " << wo.z;
      EXPECT_GT(sampled, 0.5);
    }
  }
}

// The directions sample() returns are distributed as pdf() says (chi-square
// at significance 0.001 over a theta x phi histogram of the sphere).
TEST(Bsdf, SamplesFollowPdf)
{
  constexpr int kBinsTheta = 20, kBinsPhi = 20, kCount = 100000;
  for (const BsdfInputs &in : roughInputs()) {
    const Bsdf bsdf(in);
    const float3 wo = direction(0.6f, 0.f);
    std::vector<double> observed(kBinsTheta * kBinsPhi, 0.0);
    for (int i = 0; i < kCount; i++) {
      const RandomSequence r({uint32_t(i), 3}, 0, 0);
      const BsdfSample s = bsdf.sample(wo, r.get2D(0), r.get1D(1));
      if (!s.valid())
        continue;
      const float theta = std::acos(clamp(s.wi.z, -1.f, 1.f));
      const float phi = std::atan2(s.wi.y, s.wi.x) + kPi;
      const int a = min(int(theta / kPi * kBinsTheta), kBinsTheta - 1);
      const int b = min(int(phi / (2.f * kPi) * kBinsPhi), kBinsPhi - 1);
      observed[a * kBinsPhi + b] += 1.0;
    }
    std::vector<double> expected(observed.size(), 0.0);
    constexpr int kSub = 8;
    for (int a = 0; a < kBinsTheta; a++) {
      for (int b = 0; b < kBinsPhi; b++) {
        double sum = 0.0;
        for (int p = 0; p < kSub; p++) {
          const float theta = kPi * (a + (p + 0.5f) / kSub) / kBinsTheta;
          const float st = std::sin(theta);
          for (int q = 0; q < kSub; q++) {
            const float phi =
                2.f * kPi * (b + (q + 0.5f) / kSub) / kBinsPhi - kPi;
            const float3 wi{
                st * std::cos(phi), st * std::sin(phi), std::cos(theta)};
            sum += bsdf.pdf(wo, wi) * st;
          }
        }
        expected[a * kBinsPhi + b] = kCount * sum * (kPi / (kBinsTheta * kSub))
                                     * (2.0 * kPi / (kBinsPhi * kSub));
      }
    }
    EXPECT_TRUE(test::passesChiSquare(observed, expected)) << describe(in);
  }
}

TEST(Bsdf, FresnelAtNormalIncidence)
{
  for (float ior : {1.33f, 1.5f, 2.f, 2.42f}) {
    const float expected =
        ((1.f - ior) / (1.f + ior)) * ((1.f - ior) / (1.f + ior));
    EXPECT_NEAR(f0FromIor(ior), expected, 1e-7f);
    EXPECT_NEAR(fresnelDielectric(1.f, ior), expected, 1e-6f);
    EXPECT_NEAR(fresnelDielectric(1.f, 1.f / ior), expected, 1e-6f);
    EXPECT_NEAR(fresnelSchlick(expected, 1.f, 1.f), expected, 1e-7f);

    // A black smooth dielectric reflects exactly f0 at normal incidence.
    BsdfInputs in = whitePlastic(0.f);
    in.baseColor = {0.f, 0.f, 0.f};
    in.ior = ior;
    const Bsdf bsdf(in);
    const BsdfSample s = bsdf.sample({0.f, 0.f, 1.f}, {0.3f, 0.6f}, 0.5f);
    ASSERT_TRUE(s.valid());
    ASSERT_TRUE(s.isDelta());
    EXPECT_NEAR(length(s.wi - float3{0.f, 0.f, 1.f}), 0.f, 1e-6f);
    EXPECT_NEAR(s.weight.x * s.pdf, expected, 1e-6f);

    // Glass transmits the rest, radiance divided by ior^2 entering it.
    BsdfInputs g = glass(0.f, 1.f);
    g.ior = ior;
    const Bsdf refractive(g);
    const BsdfSample t =
        refractive.sample({0.f, 0.f, 1.f}, {0.3f, 0.6f}, 0.999f);
    ASSERT_TRUE(t.isTransmission());
    EXPECT_NEAR(t.weight.x * t.pdf, (1.f - expected) / (ior * ior), 1e-6f);
    EXPECT_FLOAT_EQ(t.relativeIor, ior);
  }
  // Total internal reflection.
  EXPECT_EQ(fresnelDielectric(0.5f, 1.f / 1.5f), 1.f);
  EXPECT_LT(fresnelDielectric(0.8f, 1.f / 1.5f), 1.f);
}

TEST(Bsdf, ThinFilmFresnel)
{
  const float3 f0{0.04f, 0.04f, 0.04f};
  for (float c : {1.f, 0.7f, 0.3f, 0.05f}) {
    // No film, no change.
    EXPECT_NEAR(length(fresnelThinFilm(c, 1.3f, 0.f, f0)
                       - fresnelSchlick(f0, float3{1, 1, 1}, c)),
        0.f,
        1e-6f);
    for (float thickness : {100.f, 300.f, 600.f, 1200.f}) {
      const float3 f = fresnelThinFilm(c, 1.3f, thickness, f0);
      EXPECT_GE(minComponent(f), 0.f);
      EXPECT_LE(maxComponent(f), 1.f);
    }
  }
  // Interference colours the reflection.
  const float3 f = fresnelThinFilm(1.f, 1.3f, 400.f, f0);
  EXPECT_GT(maxComponent(f) - minComponent(f), 0.01f);
}

TEST(Bsdf, TiltedClearcoatReflectsAboutItsOwnNormal)
{
  // A smooth coat over a black diffuse base: its one delta direction is wo
  // mirrored about clearcoatNormal, not about the base's normal.
  BsdfInputs in = whitePlastic(1.f);
  in.baseColor = {0.f, 0.f, 0.f};
  in.clearcoat = 1.f;
  in.clearcoatRoughness = 0.f;
  const float3 n = normalize(float3{0.3f, 0.f, 1.f});
  in.clearcoatNormal = n;
  const Bsdf bsdf(in);
  const float3 wo = direction(0.8f, 0.3f);
  const float3 expected = n * (2.f * dot(wo, n)) - wo;
  int found = 0;
  for (int i = 0; i < 16; i++) {
    const BsdfSample s = bsdf.sample(wo, {0.5f, 0.5f}, (i + 0.5f) / 16.f);
    if (!s.valid() || !s.isDelta())
      continue;
    found++;
    EXPECT_NEAR(length(s.wi - expected), 0.f, 1e-5f);
    EXPECT_NEAR(
        s.weight.x * s.pdf, fresnelSchlick(0.04f, 1.f, dot(wo, n)), 1e-4f);
  }
  EXPECT_GT(found, 0);
}

TEST(Bsdf, DeltaLobes)
{
  const float3 wo = direction(0.6f, 0.7f);
  const float3 mirrorDirection{-wo.x, -wo.y, wo.z};

  // A smooth metal is a perfect mirror of Schlick's Fresnel.
  BsdfInputs in = whiteMetal(0.f);
  in.baseColor = {0.9f, 0.6f, 0.3f};
  const Bsdf metal(in);
  EXPECT_FALSE(metal.hasNonDeltaLobes());
  const BsdfSample s = metal.sample(wo, {0.2f, 0.9f}, 0.4f);
  ASSERT_TRUE(s.valid());
  EXPECT_TRUE(s.isDelta());
  EXPECT_FALSE(s.isTransmission());
  EXPECT_NEAR(length(s.wi - mirrorDirection), 0.f, 1e-6f);
  EXPECT_NEAR(
      length(s.weight - fresnelSchlick(in.baseColor, float3{1, 1, 1}, 0.6f)),
      0.f,
      1e-5f);
  EXPECT_EQ(metal.eval(wo, s.wi), (float3{0, 0, 0}));
  EXPECT_EQ(metal.pdf(wo, s.wi), 0.f);

  // Thin smooth glass: straight through.
  const Bsdf thin(glass(0.f, 0.f));
  bool sawTransmission = false;
  for (float uLobe : {0.01f, 0.5f, 0.99f}) {
    const BsdfSample t = thin.sample(wo, {0.5f, 0.5f}, uLobe);
    ASSERT_TRUE(t.isDelta());
    if (t.isTransmission()) {
      sawTransmission = true;
      EXPECT_NEAR(length(t.wi + wo), 0.f, 1e-6f);
      EXPECT_EQ(t.relativeIor, 1.f);
    }
  }
  EXPECT_TRUE(sawTransmission);

  // Smooth refraction obeys Snell's law, entering and leaving.
  const Bsdf refractive(glass(0.f, 1.f));
  const BsdfSample in1 = refractive.sample(wo, {0.5f, 0.5f}, 0.999f);
  ASSERT_TRUE(in1.isTransmission());
  const float sinO = std::sqrt(1.f - wo.z * wo.z);
  const float sinT = std::sqrt(1.f - in1.wi.z * in1.wi.z);
  EXPECT_NEAR(sinO, 1.5f * sinT, 1e-5f);
  EXPECT_LT(in1.wi.z, 0.f);
  const float3 inside = direction(-0.9f, 0.7f);
  const BsdfSample out = refractive.sample(inside, {0.5f, 0.5f}, 0.999f);
  ASSERT_TRUE(out.isTransmission());
  EXPECT_NEAR(std::sqrt(1.f - out.wi.z * out.wi.z),
      1.5f * std::sqrt(1.f - inside.z * inside.z),
      1e-5f);
  EXPECT_FLOAT_EQ(out.relativeIor, 1.f / 1.5f);
  // Beyond the critical angle inside, everything reflects.
  const float3 grazingInside = direction(-0.5f, 0.7f);
  for (float uLobe : {0.01f, 0.5f, 0.99f}) {
    const BsdfSample r = refractive.sample(grazingInside, {0.5f, 0.5f}, uLobe);
    ASSERT_TRUE(r.valid());
    EXPECT_FALSE(r.isTransmission());
    EXPECT_NEAR(r.weight.x, 1.f, 1e-6f);
  }
}

TEST(Bsdf, RobustToBadInputsAndDirections)
{
  BsdfInputs in;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  in.baseColor = {nan, 2.f, -1.f};
  in.roughness = nan;
  in.metallic = -3.f;
  in.ior = 0.f;
  in.specular = 5.f;
  in.sheenColor = {nan, 1.f, 1.f};
  in.iridescenceThickness = nan;
  const Bsdf bsdf(in);
  for (const float3 wo : kViews) {
    for (uint32_t i = 0; i < 64; i++) {
      const RandomSequence r({i, 1}, 0, 0);
      const BsdfSample s = bsdf.sample(wo, r.get2D(0), r.get1D(1));
      if (s.valid()) {
        ASSERT_TRUE(std::isfinite(s.weight.x + s.weight.y + s.weight.z));
        ASSERT_TRUE(std::isfinite(s.pdf));
      }
      const float3 f = bsdf.eval(wo, sampleUniformSphere(r.get2D(2)));
      ASSERT_TRUE(std::isfinite(f.x + f.y + f.z));
    }
  }
  // Degenerate directions give nothing rather than NaN.
  EXPECT_FALSE(bsdf.sample({1.f, 0.f, 0.f}, {0.5f, 0.5f}, 0.5f).valid());
  EXPECT_EQ(bsdf.eval({1.f, 0.f, 0.f}, {0.f, 0.f, 1.f}), (float3{0, 0, 0}));
  EXPECT_EQ(bsdf.pdf({0.f, 0.f, 1.f}, {nan, 0.f, 1.f}), 0.f);
}

TEST(Bsdf, InputsFromPhysicallyBasedValues)
{
  // The fields of PhysicallyBased::Values that the BSDF reads.
  struct Values
  {
    float3 baseColor{0.1f, 0.2f, 0.3f};
    float metallic{0.4f}, roughness{0.5f}, specular{0.6f};
    float3 specularColor{0.7f, 0.8f, 0.9f};
    float ior{1.7f}, clearcoat{0.25f}, clearcoatRoughness{0.35f};
    float transmission{0.45f}, thickness{2.f};
    float3 sheenColor{0.3f, 0.2f, 0.1f};
    float sheenRoughness{0.55f}, iridescence{0.65f}, iridescenceIor{1.4f};
    float iridescenceThickness{321.f};
    float anisotropyStrength{0.75f};
  } v;
  const BsdfInputs in = physicallyBasedBsdfInputs(v);
  EXPECT_EQ(in.baseColor, v.baseColor);
  EXPECT_EQ(in.metallic, v.metallic);
  EXPECT_EQ(in.roughness, v.roughness);
  EXPECT_EQ(in.specular, v.specular);
  EXPECT_EQ(in.specularColor, v.specularColor);
  EXPECT_EQ(in.ior, v.ior);
  EXPECT_EQ(in.clearcoat, v.clearcoat);
  EXPECT_EQ(in.clearcoatRoughness, v.clearcoatRoughness);
  EXPECT_EQ(in.transmission, v.transmission);
  EXPECT_EQ(in.thickness, v.thickness);
  EXPECT_EQ(in.sheenColor, v.sheenColor);
  EXPECT_EQ(in.sheenRoughness, v.sheenRoughness);
  EXPECT_EQ(in.iridescence, v.iridescence);
  EXPECT_EQ(in.iridescenceIor, v.iridescenceIor);
  EXPECT_EQ(in.iridescenceThickness, v.iridescenceThickness);
  EXPECT_EQ(in.anisotropy, v.anisotropyStrength);
  EXPECT_TRUE(Bsdf(in).isVolumeBoundary());
  EXPECT_TRUE(Bsdf(in).hasTransmission());
  // The spec defaults: a rough white metal.
  const BsdfInputs defaults;
  EXPECT_EQ(defaults.metallic, 1.f);
  EXPECT_EQ(defaults.roughness, 1.f);
  EXPECT_EQ(defaults.specular, 0.f);
  EXPECT_EQ(defaults.ior, 1.5f);
}

TEST(Bsdf, VolumeAttenuation)
{
  const float3 color{0.5f, 0.25f, 1.f};
  const float3 sigma = volumeAttenuationCoefficient(color, 2.f);
  for (int c = 0; c < 3; c++)
    EXPECT_NEAR(std::exp(-sigma[c] * 2.f), color[c], 1e-6f);
  EXPECT_EQ(volumeAttenuationCoefficient(
                color, std::numeric_limits<float>::infinity()),
      (float3{0, 0, 0}));
  EXPECT_EQ(volumeAttenuationCoefficient(color, 0.f), (float3{0, 0, 0}));
}

TEST(Bsdf, AlbedoTables)
{
  for (float mu : {0.f, 0.3f, 1.f}) {
    EXPECT_EQ(ggxAlbedo(mu, 0.f).total, 1.f);
    EXPECT_NEAR(ggxAlbedo(mu, 0.f).schlick, schlickWeight(mu), 1e-2f);
  }
  float previous = 1.f;
  for (float r = 0.f; r <= 1.f; r += 0.05f) {
    const GgxAlbedo a = ggxAlbedo(1.f, r);
    EXPECT_LE(a.total, previous + 1e-3f);
    EXPECT_GE(a.total, a.schlick);
    EXPECT_LE(a.meanCos, 1.f);
    EXPECT_GT(a.average, 0.f);
    EXPECT_LE(a.average, 1.f);
    previous = a.total;
  }
  // Against a 4M-sample Monte Carlo reference computed offline.
  EXPECT_NEAR(ggxAlbedo(1.f, 1.f).total, 0.30695f, 3e-3f);
  EXPECT_NEAR(ggxAlbedo(0.3f, 0.7f).total, 0.74902f, 3e-3f);
  EXPECT_NEAR(ggxAlbedo(0.3f, 0.4f).total, 0.88599f, 3e-3f);
  EXPECT_NEAR(sheenAlbedo(1.f, 1.f), 0.16379f, 3e-3f);
  EXPECT_NEAR(sheenAlbedo(0.3f, 0.6f), 0.36939f, 3e-3f);
}

// KHR_materials_anisotropy at strength 0 is the isotropic lobe, bit for bit
// (the same arithmetic, not merely the same function).
TEST(Bsdf, AnisotropyZeroIsIsotropicBitForBit)
{
  for (BsdfInputs isotropic : inputGrid()) {
    isotropic.anisotropy = 0.f;
    isotropic.anisotropyDirection = {1.f, 0.f};
    BsdfInputs turned = isotropic;
    turned.anisotropy = 0.f;
    turned.anisotropyDirection = {0.6f, -0.8f};
    const Bsdf a(isotropic), b(turned);
    for (uint32_t i = 0; i < 32; i++) {
      const RandomSequence r({i, 21}, 0, 0);
      const float3 wo = sampleUniformSphere(r.get2D(0));
      const float3 wi = sampleUniformSphere(r.get2D(1));
      float3 fa, fb;
      float pa, pb;
      a.evalAndPdf(wo, wi, fa, pa);
      b.evalAndPdf(wo, wi, fb, pb);
      ASSERT_EQ(fa, fb) << describe(isotropic);
      ASSERT_EQ(pa, pb) << describe(isotropic);
      const BsdfSample sa = a.sample(wo, r.get2D(2), r.get1D(3));
      const BsdfSample sb = b.sample(wo, r.get2D(2), r.get1D(3));
      ASSERT_EQ(sa.wi, sb.wi);
      ASSERT_EQ(sa.weight, sb.weight);
      ASSERT_EQ(sa.pdf, sb.pdf);
    }
  }
}

// The anisotropic distribution is normalised (integral of D(h) cos(h) over
// the hemisphere is 1) and so are its visible normals from any view.
TEST(Bsdf, AnisotropicGgxIsNormalised)
{
  const GgxLobe lobe(0.45f, 0.9f, {0.8f, 0.6f});
  ASSERT_TRUE(lobe.anisotropic());
  EXPECT_NEAR(lobe.alphaAcross(), 0.45f * 0.45f, 1e-6f);
  EXPECT_NEAR(lobe.alphaAlong(), lerp(0.45f * 0.45f, 1.f, 0.81f), 1e-6f);
  constexpr int kTheta = 800, kPhi = 400;
  for (const float3 wo :
      {float3{0.f, 0.f, 1.f}, direction(0.5f, 0.3f), direction(0.2f, 2.f)}) {
    double projected = 0.0, visible = 0.0;
    for (int i = 0; i < kTheta; i++) {
      const float theta = 0.5f * kPi * (i + 0.5f) / kTheta;
      const float s = std::sin(theta);
      for (int j = 0; j < kPhi; j++) {
        const float phi = 2.f * kPi * (j + 0.5f) / kPhi;
        const float3 h{s * std::cos(phi), s * std::sin(phi), std::cos(theta)};
        const double d = lobe.D(h) * s;
        projected += d * h.z;
        visible += d * lobe.G1(wo) * max(0.f, dot(wo, h)) / wo.z;
      }
    }
    const double cell = (0.5 * kPi / kTheta) * (2.0 * kPi / kPhi);
    EXPECT_NEAR(projected * cell, 1.0, 2e-3);
    EXPECT_NEAR(visible * cell, 1.0, 2e-3) << "wo.z " << wo.z;
  }
}

// White furnace of an anisotropic white metal, seen along its direction,
// across it and between. Single scattering is the exact anisotropic lobe;
// the multiple-scattering term (Kulla-Conty) reads the isotropic tables at
// the geometric-mean width, which is not the anisotropic lobe's albedo: the
// albedo stays below 1.03 (measured at most 1.027, at grazing views along
// the wide axis), and loses energy where the lobe is far wider one way
// than the other (measured down to 0.53 at strength 1 on a mirror base,
// 0.83 at strength 0.7; 0.94 and above from a base roughness of 0.3 at
// strength 0.7).
TEST(Bsdf, AnisotropicMetalWhiteFurnace)
{
  float lowest = 2.f, highest = 0.f;
  for (float strength : {0.3f, 0.7f, 1.f})
    for (float roughness : {0.f, 0.3f, 0.6f}) {
      BsdfInputs in = whiteMetal(roughness);
      in.anisotropy = strength;
      in.anisotropyDirection = {1.f, 0.f};
      const Bsdf bsdf(in);
      for (float phi : {0.f, 0.8f, 0.5f * kPi})
        for (float mu : {1.f, 0.6f, 0.25f}) {
          const AlbedoEstimate e = estimateAlbedo(bsdf, direction(mu, phi));
          EXPECT_LE(e.albedo.x, 1.03f + 3.f * e.standardError.x)
              << describe(in) << " cos " << mu << " phi " << phi;
          EXPECT_GE(e.albedo.x, 0.5f)
              << describe(in) << " cos " << mu << " phi " << phi;
          lowest = min(lowest, e.albedo.x);
          highest = max(highest, e.albedo.x);
        }
    }
  RecordProperty("lowestAlbedo", std::to_string(lowest));
  RecordProperty("highestAlbedo", std::to_string(highest));
}

// Seen head on, the reflection spreads along the anisotropy direction: at
// 25 degrees off the mirror direction it reflects more along it than
// across it, and turning the direction by 90 degrees swaps the two.
TEST(Bsdf, AnisotropicHighlightStretchesAlongItsDirection)
{
  BsdfInputs in = whiteMetal(0.2f);
  in.anisotropy = 0.8f;
  in.anisotropyDirection = {0.6f, 0.8f};
  const float3 wo{0.f, 0.f, 1.f};
  const float a = 25.f * kPi / 180.f;
  const float3 along{std::sin(a) * 0.6f, std::sin(a) * 0.8f, std::cos(a)};
  const float3 across{std::sin(a) * -0.8f, std::sin(a) * 0.6f, std::cos(a)};
  const Bsdf bsdf(in);
  EXPECT_GT(bsdf.eval(wo, along).x, 20.f * bsdf.eval(wo, across).x);
  in.anisotropyDirection = {-0.8f, 0.6f};
  const Bsdf turned(in);
  EXPECT_GT(turned.eval(wo, across).x, 20.f * turned.eval(wo, along).x);
  EXPECT_NEAR(turned.eval(wo, across).x,
      bsdf.eval(wo, along).x,
      1e-4f * bsdf.eval(wo, along).x);
}
