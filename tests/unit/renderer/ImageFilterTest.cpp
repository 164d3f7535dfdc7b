// Bilinear sampling and resizing of float4 images.
#include "renderer/ImageFilter.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

using namespace prism;

namespace {

float4 gray(float v)
{
  return {v, v, v, v};
}

// Row-major, first row at the bottom: t[y * width + x].
std::vector<float4> randomImage(uint32_t width, uint32_t height, int seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> value(-1.f, 4.f);
  std::vector<float4> image(size_t(width) * height);
  for (auto &t : image)
    t = {value(rng), value(rng), value(rng), value(rng)};
  return image;
}

void expectNear(float4 a, float4 b, float tolerance)
{
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
  EXPECT_NEAR(a.w, b.w, tolerance);
}

} // namespace

TEST(ImageFilter, TexelCentresReturnTexels)
{
  for (uint32_t width : {1u, 2u, 3u, 5u, 7u}) {
    for (uint32_t height : {1u, 2u, 3u, 6u}) {
      const auto image = randomImage(width, height, int(width * 10 + height));
      for (uint32_t y = 0; y < height; y++) {
        for (uint32_t x = 0; x < width; x++) {
          const float u = (x + 0.5f) / width;
          const float v = (y + 0.5f) / height;
          EXPECT_EQ(sampleBilinear(image.data(), width, height, u, v),
              image[y * width + x])
              << width << "x" << height << " texel " << x << "," << y;
        }
      }
    }
  }
}

TEST(ImageFilter, MidpointsAverage)
{
  // 2x2: bottom row (0, 1), top row (2, 4).
  const float4 image[4] = {gray(0.f), gray(1.f), gray(2.f), gray(4.f)};
  EXPECT_EQ(sampleBilinear(image, 2, 2, 0.5f, 0.25f), gray(0.5f));
  EXPECT_EQ(sampleBilinear(image, 2, 2, 0.5f, 0.75f), gray(3.f));
  EXPECT_EQ(sampleBilinear(image, 2, 2, 0.25f, 0.5f), gray(1.f));
  EXPECT_EQ(sampleBilinear(image, 2, 2, 0.5f, 0.5f), gray(1.75f));
}

TEST(ImageFilter, ClampsToEdge)
{
  const float4 image[4] = {gray(0.f), gray(1.f), gray(2.f), gray(4.f)};
  EXPECT_EQ(sampleBilinear(image, 2, 2, 0.f, 0.f), gray(0.f));
  EXPECT_EQ(sampleBilinear(image, 2, 2, -3.f, 0.25f), gray(0.f));
  EXPECT_EQ(sampleBilinear(image, 2, 2, 1.f, 1.f), gray(4.f));
  EXPECT_EQ(sampleBilinear(image, 2, 2, 7.f, 0.25f), gray(1.f));
  EXPECT_EQ(sampleBilinear(image, 2, 2, 0.25f, 100.f), gray(2.f));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(sampleBilinear(image, 2, 2, nan, nan), gray(0.f));
  EXPECT_EQ(sampleBilinear(image, 0, 2, 0.5f, 0.5f), gray(0.f));
}

TEST(ImageFilter, Resize2x2To4x4)
{
  const float4 image[4] = {gray(0.f), gray(1.f), gray(2.f), gray(4.f)};
  // Source positions (x + 0.5) / 2 - 0.5 = -0.25, 0.25, 0.75, 1.25: weights
  // 1, 3/4, 1/4, 0 on the first texel; rows stay bottom to top.
  const float expected[4][4] = {{0.f, 0.25f, 0.75f, 1.f},
      {0.5f, 0.8125f, 1.4375f, 1.75f},
      {1.5f, 1.9375f, 2.8125f, 3.25f},
      {2.f, 2.5f, 3.5f, 4.f}};
  float4 out[16];
  resizeBilinear(image, 2, 2, out, 4, 4);
  for (int y = 0; y < 4; y++) {
    for (int x = 0; x < 4; x++)
      EXPECT_EQ(out[y * 4 + x], gray(expected[y][x])) << x << "," << y;
  }
}

TEST(ImageFilter, ResizeDownAveragesBlocks)
{
  // 4x2 -> 2x1: each output pixel sits between four texels.
  const float4 image[8] = {gray(0.f),
      gray(2.f),
      gray(4.f),
      gray(8.f),
      gray(1.f),
      gray(3.f),
      gray(5.f),
      gray(7.f)};
  float4 out[2];
  resizeBilinear(image, 4, 2, out, 2, 1);
  EXPECT_EQ(out[0], gray(1.5f));
  EXPECT_EQ(out[1], gray(6.f));
}

TEST(ImageFilter, ResizeToSameSizeCopies)
{
  const auto image = randomImage(5, 3, 1);
  std::vector<float4> out(15);
  resizeBilinear(image.data(), 5, 3, out.data(), 5, 3);
  EXPECT_EQ(out, image);
}

TEST(ImageFilter, ResizeAgreesWithSampling)
{
  const auto image = randomImage(3, 5, 2);
  const uint32_t width = 7, height = 4;
  std::vector<float4> out(width * height);
  resizeBilinear(image.data(), 3, 5, out.data(), width, height);
  for (uint32_t y = 0; y < height; y++) {
    for (uint32_t x = 0; x < width; x++) {
      const float4 s = sampleBilinear(
          image.data(), 3, 5, (x + 0.5f) / width, (y + 0.5f) / height);
      expectNear(out[y * width + x], s, 1e-5f);
    }
  }
}

TEST(ImageFilter, ResizeEmptySourceGivesZeros)
{
  float4 out[4] = {gray(9.f), gray(9.f), gray(9.f), gray(9.f)};
  resizeBilinear(nullptr, 0, 0, out, 2, 2);
  for (const float4 &p : out)
    EXPECT_EQ(p, gray(0.f));
  resizeBilinear(out, 2, 2, nullptr, 0, 0);
}
