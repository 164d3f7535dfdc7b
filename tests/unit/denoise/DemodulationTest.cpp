// Demodulation and remodulation: the round trip gives the color back, dark
// and broken albedos cannot blow it up, alpha passes through.
#include "denoise/Demodulation.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

namespace prism::denoising {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInfinity = std::numeric_limits<float>::infinity();

DenoiseInputs inputsOf(
    const std::vector<float4> &color, const std::vector<float3> &albedo)
{
  return {uint32_t(color.size()),
      1,
      color.data(),
      albedo.empty() ? nullptr : albedo.data(),
      nullptr,
      nullptr,
      1};
}

TEST(Demodulation, RemodulationInvertsDemodulation)
{
  const std::vector<float4> color{{0.5f, 0.25f, 2.f, 1.f},
      {0.f, 1e-3f, 7.f, 0.5f},
      {3.f, 0.3f, 0.03f, 0.f},
      {0.2f, 0.2f, 0.2f, 0.25f}};
  const std::vector<float3> albedo{{0.5f, 0.9f, 0.1f},
      {0.001f, 0.f, 1.f},
      {kNaN, kInfinity, 0.8f},
      {0.3f, 0.3f, 0.3f}};
  const DenoiseInputs in = inputsOf(color, albedo);
  std::vector<float4> demodulated(color.size()), out(color.size());
  demodulate(in, demodulated.data());
  remodulate(in, demodulated.data(), out.data());
  for (size_t i = 0; i < color.size(); i++) {
    EXPECT_FLOAT_EQ(out[i].x, color[i].x) << i;
    EXPECT_FLOAT_EQ(out[i].y, color[i].y) << i;
    EXPECT_FLOAT_EQ(out[i].z, color[i].z) << i;
    EXPECT_EQ(out[i].w, color[i].w) << i;
    EXPECT_EQ(demodulated[i].w, 0.f) << i;
  }
}

TEST(Demodulation, DividesByTheAlbedoClampedAwayFromBlack)
{
  const std::vector<float4> color{{0.5f, 0.02f, 0.3f, 1.f}};
  const std::vector<float3> albedo{{0.5f, 0.f, kNaN}};
  std::vector<float4> demodulated(1);
  demodulate(inputsOf(color, albedo), demodulated.data());
  EXPECT_FLOAT_EQ(demodulated[0].x, 1.f);
  EXPECT_FLOAT_EQ(demodulated[0].y, 0.02f / kMinAlbedo);
  EXPECT_FLOAT_EQ(demodulated[0].z, 0.3f); // a non-finite channel: factor 1
}

TEST(Demodulation, WithoutAlbedoIsTheIdentity)
{
  const std::vector<float4> color{{0.1f, 0.2f, 0.3f, 0.4f}};
  std::vector<float4> demodulated(1), out(1);
  const DenoiseInputs in = inputsOf(color, {});
  demodulate(in, demodulated.data());
  EXPECT_EQ(xyz(demodulated[0]), xyz(color[0]));
  remodulate(in, demodulated.data(), out.data());
  EXPECT_EQ(out[0], color[0]);
}

TEST(Demodulation, ZeroesNonFiniteColors)
{
  const std::vector<float4> color{
      {kNaN, 1.f, 1.f, 1.f}, {1.f, kInfinity, 1.f, 1.f}};
  std::vector<float4> demodulated(2);
  demodulate(inputsOf(color, {}), demodulated.data());
  for (const float4 &v : demodulated)
    EXPECT_EQ(xyz(v), (float3{0.f, 0.f, 0.f}));
}

TEST(Demodulation, RemodulatesInPlace)
{
  std::vector<float4> color{{0.4f, 0.8f, 0.2f, 0.5f}};
  const std::vector<float3> albedo{{0.5f, 0.5f, 0.5f}};
  const DenoiseInputs in = inputsOf(color, albedo);
  const std::vector<float4> filtered{{1.f, 1.f, 1.f, 0.f}};
  remodulate(in, filtered.data(), color.data());
  EXPECT_EQ(color[0], (float4{0.5f, 0.5f, 0.5f, 0.5f}));
}

} // namespace
} // namespace prism::denoising
