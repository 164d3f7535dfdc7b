// The à-trous denoiser on a procedural scene with known clean values: noise
// reduction, sharp geometric edges, isolated background, converged input
// left alone, determinism, degenerate sizes and missing guide buffers.
#include "denoise/Denoiser.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <vector>

using namespace prism;

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

enum Region : uint8_t {
  kBackground,
  kRegionA, // lit plane with a hard shadow
  kRegionB, // dimmer plane meeting A at a crease (continuous depth)
  kRegionC, // nearer object: checker texture under a smooth light gradient
};

// Clean and noisy buffers of a synthetic frame, row 0 at the bottom.
struct Scene
{
  uint32_t width = 0, height = 0;
  uint32_t horizon = 0, crease = 0, depthEdge = 0; // region borders
  std::vector<float4> clean, color;
  std::vector<float3> albedo, normal;
  std::vector<float> depth;
  std::vector<Region> region;

  DenoiseInputs inputs(uint32_t samples) const
  {
    return {width,
        height,
        color.data(),
        albedo.data(),
        normal.data(),
        depth.data(),
        samples};
  }
  size_t index(uint32_t x, uint32_t y) const
  {
    return size_t(y) * width + x;
  }
};

uint64_t splitMix64(uint64_t v)
{
  v += 0x9e3779b97f4a7c15ull;
  v = (v ^ (v >> 30)) * 0xbf58476d1ce4e5b9ull;
  v = (v ^ (v >> 27)) * 0x94d049bb133111ebull;
  return v ^ (v >> 31);
}

// Standard normal deviate for (seed, key) by Box-Muller, written out so the
// noise is the same with every standard library.
float gaussian(uint64_t seed, uint64_t key)
{
  const uint64_t a = splitMix64(seed * 0x100000001b3ull + 2 * key);
  const uint64_t b = splitMix64(seed * 0x100000001b3ull + 2 * key + 1);
  const double u1 = (double(a >> 11) + 1.0) / 9007199254740993.0; // (0, 1]
  const double u2 = double(b >> 11) / 9007199254740992.0;
  return float(
      std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2));
}

const float3 kSky{0.3f, 0.5f, 0.9f};

// Background on top, then left to right: A | crease | B | depth edge | C.
// `noiseSigma` is the standard deviation added to every surface channel,
// standing in for a 1-sample path-traced color; the sky is deterministic.
Scene makeScene(
    uint32_t width, uint32_t height, float noiseSigma, uint64_t seed = 1)
{
  Scene s;
  s.width = width;
  s.height = height;
  s.horizon = height * 3 / 4;
  s.crease = width * 3 / 8;
  s.depthEdge = width * 11 / 16;
  const size_t pixels = size_t(width) * height;
  s.clean.resize(pixels);
  s.color.resize(pixels);
  s.albedo.resize(pixels);
  s.normal.resize(pixels);
  s.depth.resize(pixels);
  s.region.resize(pixels);
  const float3 normalA = normalize(float3{-0.5f, 0.f, 1.f});
  const float3 normalB = normalize(float3{0.6f, 0.f, 1.f});
  const float3 normalC = normalize(float3{0.f, 0.3f, 1.f});
  for (uint32_t y = 0; y < height; y++) {
    for (uint32_t x = 0; x < width; x++) {
      const size_t i = s.index(x, y);
      // Arbitrary alpha pattern, to check it is copied bit for bit.
      const float alpha = float((x * 7 + y * 13) % 11) / 10.f;
      const float fx = float(x), fy = float(y);
      float3 rgb = kSky;
      if (y >= s.horizon) {
        s.region[i] = kBackground;
        s.albedo[i] = {0.f, 0.f, 0.f};
        s.normal[i] = {0.f, 0.f, 0.f};
        s.depth[i] = kInfinity;
      } else if (x < s.crease) {
        s.region[i] = kRegionA;
        s.albedo[i] = {0.8f, 0.35f, 0.2f};
        s.normal[i] = normalA;
        s.depth[i] = 8.f + 0.02f * fx + 0.01f * fy;
        const bool shadowed = x >= width / 10 && x < width * 2 / 9
                              && y >= height / 6 && y < height * 5 / 12;
        rgb = s.albedo[i] * (shadowed ? 0.3f : 1.f);
      } else if (x < s.depthEdge) {
        s.region[i] = kRegionB;
        s.albedo[i] = {0.2f, 0.55f, 0.85f};
        s.normal[i] = normalB;
        s.depth[i] = 8.f + 0.02f * float(s.crease) + 0.01f * fy
                     - 0.015f * (fx - float(s.crease));
        rgb = s.albedo[i] * 0.5f;
      } else {
        s.region[i] = kRegionC;
        const bool light = ((x / 8) + (y / 8)) % 2 == 0;
        s.albedo[i] =
            light ? float3{0.9f, 0.9f, 0.9f} : float3{0.25f, 0.6f, 0.3f};
        s.normal[i] = normalC;
        s.depth[i] = 5.f + 0.005f * fy;
        const float t = fy / float(s.horizon);
        rgb = s.albedo[i] * (0.15f + 0.75f * t * t);
      }
      s.clean[i] = makeVec4(rgb, alpha);
      float3 noisy = rgb;
      if (s.region[i] != kBackground) {
        noisy = noisy
                + float3{gaussian(seed, 3 * i),
                      gaussian(seed, 3 * i + 1),
                      gaussian(seed, 3 * i + 2)}
                      * noiseSigma;
      }
      s.color[i] = makeVec4(noisy, alpha);
    }
  }
  return s;
}

// Root mean square error over all pixels and rgb channels.
double rmse(const std::vector<float4> &image, const std::vector<float4> &truth)
{
  double sum = 0.0;
  for (size_t i = 0; i < image.size(); i++) {
    const float3 d = xyz(image[i]) - xyz(truth[i]);
    sum += double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z;
  }
  return std::sqrt(sum / (3.0 * double(image.size())));
}

float maxAbsDifference(
    const std::vector<float4> &a, const std::vector<float4> &b)
{
  float largest = 0.f;
  for (size_t i = 0; i < a.size(); i++)
    largest = max(largest, maxComponent(abs(xyz(a[i]) - xyz(b[i]))));
  return largest;
}

std::vector<float4> denoised(const DenoiseInputs &in)
{
  std::vector<float4> out(size_t(in.width) * in.height);
  denoise(in, out.data());
  return out;
}

bool allFinite(const std::vector<float4> &image)
{
  for (const float4 &p : image) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      return false;
  }
  return true;
}

bool sameAlpha(const std::vector<float4> &a, const std::vector<float4> &b)
{
  for (size_t i = 0; i < a.size(); i++) {
    if (std::memcmp(&a[i].w, &b[i].w, sizeof(float)) != 0)
      return false;
  }
  return true;
}

constexpr uint32_t kWidth = 128, kHeight = 96;
constexpr float kNoiseSigma = 0.2f;

} // namespace

TEST(Denoiser, ReducesNoiseAtLeastThreefold)
{
  const Scene scene = makeScene(kWidth, kHeight, kNoiseSigma);
  const std::vector<float4> out = denoised(scene.inputs(1));
  const double noisy = rmse(scene.color, scene.clean);
  const double filtered = rmse(out, scene.clean);
  std::printf("[ RMSE     ] noisy %.4f, denoised %.4f (%.1fx smaller)\n",
      noisy,
      filtered,
      noisy / filtered);
  RecordProperty("rmseNoisy", std::to_string(noisy));
  RecordProperty("rmseDenoised", std::to_string(filtered));
  EXPECT_LT(filtered * 3.0, noisy);
  EXPECT_TRUE(allFinite(out));
  EXPECT_TRUE(sameAlpha(out, scene.color));
}

// Across the crease (normal and albedo change, depth continuous) and the
// depth edge, each side keeps its own value, and so do the texels on either
// side of the checker's albedo edges. Bleeding shows up as a bias of the
// pixels next to an edge, which averaging over many of them exposes.
TEST(Denoiser, KeepsNormalDepthAndAlbedoEdgesSharp)
{
  const Scene scene = makeScene(kWidth, kHeight, kNoiseSigma);
  const std::vector<float4> out = denoised(scene.inputs(1));
  // Red differs by 0.7 across the crease, so a 5% blend alone would bias it
  // by 0.035; the noisy input's largest per-pixel errors are 0.5 to 0.8.
  constexpr float kMaxBias = 0.02f, kMaxError = 0.15f;
  for (uint32_t edge : {scene.crease, scene.depthEdge}) {
    for (uint32_t x = edge - 2; x < edge + 2; x++) {
      float3 biasSum{0.f, 0.f, 0.f};
      float largestError = 0.f;
      for (uint32_t y = 0; y < scene.horizon; y++) {
        const size_t i = scene.index(x, y);
        const float3 error = xyz(out[i]) - xyz(scene.clean[i]);
        biasSum += error;
        largestError = max(largestError, maxComponent(abs(error)));
      }
      const float3 bias = biasSum / float(scene.horizon);
      EXPECT_LT(maxComponent(abs(bias)), kMaxBias) << "column " << x;
      EXPECT_LT(largestError, kMaxError) << "column " << x;
    }
  }
  // Checker texels next to a vertical albedo edge (albedos differ by 0.3 to
  // 0.65 per channel), light and dark squares separately.
  for (bool light : {false, true}) {
    float3 biasSum{0.f, 0.f, 0.f};
    int count = 0;
    for (uint32_t y = 0; y < scene.horizon; y++) {
      for (uint32_t x = scene.depthEdge + 2; x < kWidth; x++) {
        if ((x % 8 != 0 && x % 8 != 7) || ((x / 8 + y / 8) % 2 == 0) != light)
          continue;
        const size_t i = scene.index(x, y);
        biasSum += xyz(out[i]) - xyz(scene.clean[i]);
        count++;
      }
    }
    ASSERT_GT(count, 100);
    EXPECT_LT(maxComponent(abs(biasSum / float(count))), kMaxBias)
        << (light ? "light" : "dark") << " texels";
  }
}

// Background pixels keep the sky exactly, and changing either side leaves
// the other bit-identical: no tap ever crosses the horizon.
TEST(Denoiser, NeverMixesBackgroundWithSurfaces)
{
  const Scene scene = makeScene(kWidth, kHeight, kNoiseSigma);
  const std::vector<float4> out = denoised(scene.inputs(1));
  Scene otherSky = scene;
  Scene otherNoise = makeScene(kWidth, kHeight, kNoiseSigma, 99);
  for (size_t i = 0; i < scene.region.size(); i++) {
    if (scene.region[i] == kBackground)
      otherSky.color[i] = {40.f, 0.f, 7.f, scene.color[i].w};
  }
  const std::vector<float4> outOtherSky = denoised(otherSky.inputs(1));
  const std::vector<float4> outOtherNoise = denoised(otherNoise.inputs(1));
  size_t backgroundPixels = 0;
  for (size_t i = 0; i < scene.region.size(); i++) {
    if (scene.region[i] == kBackground) {
      backgroundPixels++;
      EXPECT_LT(maxComponent(abs(xyz(out[i]) - kSky)), 1e-6f);
      EXPECT_EQ(0, std::memcmp(&out[i], &outOtherNoise[i], sizeof(float4)));
    } else {
      EXPECT_EQ(0, std::memcmp(&out[i], &outOtherSky[i], sizeof(float4)));
    }
  }
  EXPECT_EQ(backgroundPixels, size_t(kWidth) * (kHeight - scene.horizon));
}

// A converged (noise-free) image, including its hard shadow and texture,
// comes back unchanged.
TEST(Denoiser, LeavesNoiseFreeImageAlmostUnchanged)
{
  const Scene scene = makeScene(kWidth, kHeight, 0.f);
  for (uint32_t samples : {4096u, 1u}) {
    const std::vector<float4> out = denoised(scene.inputs(samples));
    EXPECT_LT(maxAbsDifference(out, scene.clean), 1e-3f)
        << samples << " samples";
    EXPECT_TRUE(sameAlpha(out, scene.clean));
  }
}

// The same noisy image is smoothed less the more samples it claims: the
// noise estimate is capped by a Monte Carlo prior that shrinks as
// 1 / samples, so claimed convergence protects the image.
TEST(Denoiser, FiltersLessAsSamplesGrow)
{
  const Scene scene = makeScene(kWidth, kHeight, kNoiseSigma);
  std::vector<float> changes;
  for (uint32_t samples : {1u, 64u, 4096u, 1000000u})
    changes.push_back(
        float(rmse(denoised(scene.inputs(samples)), scene.color)));
  for (size_t k = 1; k < changes.size(); k++)
    EXPECT_LT(changes[k], changes[k - 1]) << "step " << k;
  EXPECT_LT(changes.back(), 0.5f * changes.front());
}

TEST(Denoiser, IsDeterministicForAnyThreadCountAndInPlace)
{
  const Scene scene = makeScene(kWidth, kHeight, kNoiseSigma);
  const DenoiseInputs in = scene.inputs(1);
  std::vector<float4> single(scene.color.size());
  tbb::task_arena(1).execute([&] { denoise(in, single.data()); });
  std::vector<float4> many(scene.color.size());
  tbb::task_arena(tbb::task_arena::automatic).execute([&] {
    denoise(in, many.data());
  });
  EXPECT_EQ(0,
      std::memcmp(single.data(), many.data(), single.size() * sizeof(float4)));

  // A reused Denoiser (scratch kept from a different size) and in-place
  // output give the same bits.
  Denoiser denoiser;
  std::vector<float4> small(7 * 5);
  denoiser.denoise(makeScene(7, 5, kNoiseSigma).inputs(1), small.data());
  Scene inPlace = scene;
  DenoiseInputs inPlaceInputs = inPlace.inputs(1);
  denoiser.denoise(inPlaceInputs, inPlace.color.data());
  EXPECT_EQ(0,
      std::memcmp(
          single.data(), inPlace.color.data(), single.size() * sizeof(float4)));
}

TEST(Denoiser, HandlesDegenerateSizes)
{
  // Empty images and a missing color buffer leave `out` alone.
  float4 untouched{1.f, 2.f, 3.f, 4.f};
  denoise({0, 0, nullptr, nullptr, nullptr, nullptr, 1}, &untouched);
  const Scene one = makeScene(1, 1, kNoiseSigma);
  DenoiseInputs noColor = one.inputs(1);
  noColor.color = nullptr;
  denoise(noColor, &untouched);
  DenoiseInputs zeroWide = one.inputs(1);
  zeroWide.width = 0;
  denoise(zeroWide, &untouched);
  EXPECT_EQ(untouched, (float4{1.f, 2.f, 3.f, 4.f}));

  // A single pixel has nothing to average with.
  const std::vector<float4> single = denoised(one.inputs(1));
  EXPECT_LT(maxAbsDifference(single, one.color), 1e-6f);

  for (auto [w, h] : {std::pair{1u, 9u},
           std::pair{9u, 1u},
           std::pair{2u, 2u},
           std::pair{3u, 5u},
           std::pair{33u, 17u}}) {
    const Scene s = makeScene(w, h, kNoiseSigma, w * 100 + h);
    const std::vector<float4> out = denoised(s.inputs(1));
    EXPECT_TRUE(allFinite(out)) << w << "x" << h;
    EXPECT_TRUE(sameAlpha(out, s.color)) << w << "x" << h;
    EXPECT_LE(rmse(out, s.clean), rmse(s.color, s.clean) + 1e-6)
        << w << "x" << h;
  }
}

// Every combination of missing albedo, normal and depth still denoises.
TEST(Denoiser, FallsBackWithoutGuideBuffers)
{
  const Scene scene = makeScene(kWidth, kHeight, kNoiseSigma);
  const double noisy = rmse(scene.color, scene.clean);
  for (int mask = 0; mask < 8; mask++) {
    DenoiseInputs in = scene.inputs(1);
    if (mask & 1)
      in.albedo = nullptr;
    if (mask & 2)
      in.normal = nullptr;
    if (mask & 4)
      in.depth = nullptr;
    const std::vector<float4> out = denoised(in);
    const double filtered = rmse(out, scene.clean);
    std::printf("[ RMSE     ] albedo %d normal %d depth %d: %.4f\n",
        !(mask & 1),
        !(mask & 2),
        !(mask & 4),
        filtered);
    EXPECT_TRUE(allFinite(out)) << "mask " << mask;
    EXPECT_TRUE(sameAlpha(out, scene.color)) << "mask " << mask;
    EXPECT_LT(filtered * 2.0, noisy) << "mask " << mask;
    // Either geometric guide alone keeps the sky apart (zero normals or
    // infinite depth mark it).
    if ((mask & 6) != 6) {
      for (size_t i = 0; i < scene.region.size(); i++) {
        if (scene.region[i] == kBackground) {
          ASSERT_LT(maxComponent(abs(xyz(out[i]) - kSky)), 1e-6f)
              << "mask " << mask;
        }
      }
    }
  }
}

// One NaN or infinite sample must not spread through the kernel.
TEST(Denoiser, ContainsNonFiniteColor)
{
  Scene scene = makeScene(kWidth, kHeight, kNoiseSigma);
  scene.color[scene.index(20, 30)].x = std::numeric_limits<float>::quiet_NaN();
  scene.color[scene.index(80, 40)].y = kInfinity;
  const std::vector<float4> out = denoised(scene.inputs(1));
  EXPECT_TRUE(allFinite(out));
}
