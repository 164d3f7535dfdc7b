// Frame channel formats and the encoding of one pixel into each.
#include "frame/PixelFormat.h"

#include "array/ElementConversion.h"

#include "anari/frontend/type_utility.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

using namespace prism;

namespace {

struct Rgba8
{
  uint8_t r, g, b, a;
  bool operator==(const Rgba8 &) const = default;
};

Rgba8 color8(ANARIDataType format, float4 c)
{
  Rgba8 p{};
  writeColor(format, c, &p);
  return p;
}

} // namespace

TEST(PixelFormat, ChannelFormatsFollowTheSpec)
{
  EXPECT_TRUE(isValidColorFormat(ANARI_UFIXED8_VEC4));
  EXPECT_TRUE(isValidColorFormat(ANARI_UFIXED8_RGBA_SRGB));
  EXPECT_TRUE(isValidColorFormat(ANARI_FLOAT32_VEC4));
  EXPECT_FALSE(isValidColorFormat(ANARI_FLOAT32_VEC3));
  EXPECT_FALSE(isValidColorFormat(ANARI_UFIXED8_VEC3));
  EXPECT_TRUE(isValidDepthFormat(ANARI_FLOAT32));
  EXPECT_FALSE(isValidDepthFormat(ANARI_FLOAT64));
  EXPECT_TRUE(isValidNormalFormat(ANARI_FLOAT32_VEC3));
  EXPECT_TRUE(isValidNormalFormat(ANARI_FIXED16_VEC3));
  EXPECT_FALSE(isValidNormalFormat(ANARI_UFIXED8_VEC3));
  EXPECT_TRUE(isValidAlbedoFormat(ANARI_UFIXED8_VEC3));
  EXPECT_TRUE(isValidAlbedoFormat(ANARI_UFIXED8_RGB_SRGB));
  EXPECT_TRUE(isValidAlbedoFormat(ANARI_FLOAT32_VEC3));
  EXPECT_FALSE(isValidAlbedoFormat(ANARI_UFIXED8_VEC4));
  EXPECT_TRUE(isValidIdFormat(ANARI_UINT32));
  EXPECT_FALSE(isValidIdFormat(ANARI_UINT64));
}

TEST(PixelFormat, PixelSize)
{
  EXPECT_EQ(pixelSize(ANARI_UFIXED8_VEC4), 4u);
  EXPECT_EQ(pixelSize(ANARI_UFIXED8_RGBA_SRGB), 4u);
  EXPECT_EQ(pixelSize(ANARI_FLOAT32_VEC4), 16u);
  EXPECT_EQ(pixelSize(ANARI_FLOAT32), 4u);
  EXPECT_EQ(pixelSize(ANARI_FLOAT32_VEC3), 12u);
  EXPECT_EQ(pixelSize(ANARI_FIXED16_VEC3), 6u);
  EXPECT_EQ(pixelSize(ANARI_UFIXED8_VEC3), 3u);
  EXPECT_EQ(pixelSize(ANARI_UFIXED8_RGB_SRGB), 3u);
  EXPECT_EQ(pixelSize(ANARI_UINT32), 4u);
  EXPECT_EQ(pixelSize(ANARI_FLOAT64), 0u);
  EXPECT_EQ(pixelSize(ANARI_UNKNOWN), 0u);
}

TEST(PixelFormat, Unorm8RoundsToNearest)
{
  EXPECT_EQ(color8(ANARI_UFIXED8_VEC4, {0.f, 1.f, 0.5f, 0.25f}),
      (Rgba8{0, 255, 128, 64}));
  // v * 255 + 0.5 truncated: exactly half a step rounds up.
  EXPECT_EQ(toUnorm8(0.5f / 255.f), 1);
  EXPECT_EQ(toUnorm8(0.49f / 255.f), 0);
  EXPECT_EQ(toUnorm8(254.5f / 255.f), 255);
  EXPECT_EQ(toUnorm8(254.4f / 255.f), 254);
  for (int c = 0; c < 256; c++)
    EXPECT_EQ(toUnorm8(c / 255.f), c);
}

TEST(PixelFormat, Unorm8Clamps)
{
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  EXPECT_EQ(color8(ANARI_UFIXED8_VEC4, {-1.f, 2.f, nan, inf}),
      (Rgba8{0, 255, 0, 255}));
  EXPECT_EQ(color8(ANARI_UFIXED8_RGBA_SRGB, {-1.f, 2.f, nan, -inf}),
      (Rgba8{0, 255, 0, 0}));
}

TEST(PixelFormat, SrgbEncodesColourButNotAlpha)
{
  // linearToSrgb(0.5) = 0.7354, * 255 = 187.5 -> 188; alpha 0.5 -> 128.
  EXPECT_EQ(color8(ANARI_UFIXED8_RGBA_SRGB, {0.5f, 0.f, 1.f, 0.5f}),
      (Rgba8{188, 0, 255, 128}));
  EXPECT_EQ(toSrgb8(0.0031308f * 0.5f), toUnorm8(12.92f * 0.0031308f * 0.5f));
}

TEST(PixelFormat, Srgb8RoundTripsEveryCode)
{
  for (int c = 0; c < 256; c++)
    EXPECT_EQ(toSrgb8(kSrgb8ToLinear[c]), c) << c;
}

TEST(PixelFormat, LinearToSrgb8ToLinearWithinOneStep)
{
  // Quantising to 8-bit sRGB moves a value by at most half a code in the
  // encoded domain; allow one code.
  for (int i = 0; i <= 4096; i++) {
    const float linear = i / 4096.f;
    const float decoded = srgb8ToLinear(toSrgb8(linear));
    EXPECT_LE(
        std::abs(linearToSrgb(decoded) - linearToSrgb(linear)), 1.f / 255.f)
        << linear;
  }
}

TEST(PixelFormat, Float32IsRaw)
{
  const float4 c{-0.5f, 2.f, 0.25f, 1.f};
  float4 out{};
  writeColor(ANARI_FLOAT32_VEC4, c, &out);
  EXPECT_EQ(out, c);
}

TEST(PixelFormat, InvalidFormatWritesNothing)
{
  uint8_t buffer[16];
  std::memset(buffer, 0xab, sizeof(buffer));
  writeColor(ANARI_FLOAT32_VEC3, {1.f, 1.f, 1.f, 1.f}, buffer);
  writeVec3(ANARI_UFIXED8_VEC4, {1.f, 1.f, 1.f}, buffer);
  writeDepth(ANARI_FLOAT64, 1.f, buffer);
  writeId(ANARI_INT32, 1u, buffer);
  for (uint8_t b : buffer)
    EXPECT_EQ(b, 0xab);
}

TEST(PixelFormat, Albedo)
{
  uint8_t rgb[3];
  writeVec3(ANARI_UFIXED8_VEC3, {0.5f, 1.5f, 0.2f}, rgb);
  EXPECT_EQ(rgb[0], 128);
  EXPECT_EQ(rgb[1], 255);
  EXPECT_EQ(rgb[2], 51);
  writeVec3(ANARI_UFIXED8_RGB_SRGB, {0.5f, 0.f, 1.f}, rgb);
  EXPECT_EQ(rgb[0], 188);
  EXPECT_EQ(rgb[1], 0);
  EXPECT_EQ(rgb[2], 255);
  float3 raw;
  writeVec3(ANARI_FLOAT32_VEC3, {0.5f, 1.5f, -0.2f}, &raw);
  EXPECT_EQ(raw, (float3{0.5f, 1.5f, -0.2f}));
}

TEST(PixelFormat, NormalAsSnorm16)
{
  int16_t n[3];
  writeVec3(ANARI_FIXED16_VEC3, {1.f, -1.f, 0.f}, n);
  EXPECT_EQ(n[0], 32767);
  EXPECT_EQ(n[1], -32767);
  EXPECT_EQ(n[2], 0);
  writeVec3(ANARI_FIXED16_VEC3, {-2.f, 0.5f, -0.5f}, n);
  EXPECT_EQ(n[0], -32767);
  EXPECT_EQ(n[1], 16384); // 16383.5 rounds away from zero
  EXPECT_EQ(n[2], -16384);
  EXPECT_EQ(toSnorm16(std::numeric_limits<float>::quiet_NaN()), 0);
  // Decoding gives the value back within half a step.
  EXPECT_NEAR(readAsFloat4(ANARI_FIXED16, &n[1]).x, 0.5f, 0.5f / 32767.f);
}

TEST(PixelFormat, DepthAndIds)
{
  float depth = 0.f;
  writeDepth(ANARI_FLOAT32, 12.5f, &depth);
  EXPECT_EQ(depth, 12.5f);
  uint32_t id = 0;
  writeId(ANARI_UINT32, 0xfffffffeu, &id);
  EXPECT_EQ(id, 0xfffffffeu);
}

TEST(PixelFormat, RowsMatchSinglePixels)
{
  const float4 row[5] = {{0.f, 0.1f, 0.2f, 0.3f},
      {0.4f, 0.5f, 0.6f, 0.7f},
      {0.8f, 0.9f, 1.f, 1.1f},
      {-0.1f, 0.01f, 0.001f, 0.5f},
      {0.25f, 0.75f, 0.333f, 1.f}};
  for (ANARIDataType format :
      {ANARI_UFIXED8_VEC4, ANARI_UFIXED8_RGBA_SRGB, ANARI_FLOAT32_VEC4}) {
    const size_t size = pixelSize(format);
    std::vector<uint8_t> bulk(5 * size), single(5 * size);
    writeColorPixels(format, row, 5, bulk.data());
    for (size_t i = 0; i < 5; i++)
      writeColor(format, row[i], single.data() + i * size);
    EXPECT_EQ(bulk, single) << anari::toString(format);
  }
  for (ANARIDataType format : {ANARI_UFIXED8_VEC3,
           ANARI_UFIXED8_RGB_SRGB,
           ANARI_FIXED16_VEC3,
           ANARI_FLOAT32_VEC3}) {
    const size_t size = pixelSize(format);
    std::vector<uint8_t> bulk(5 * size), single(5 * size);
    float3 values[5];
    for (size_t i = 0; i < 5; i++)
      values[i] = xyz(row[i]);
    writeVec3Pixels(format, values, 5, bulk.data());
    for (size_t i = 0; i < 5; i++)
      writeVec3(format, values[i], single.data() + i * size);
    EXPECT_EQ(bulk, single) << anari::toString(format);
  }
}

TEST(PixelFormat, RunsOfOneColorMatchSinglePixels)
{
  // sRGB rows encode a run of equal pixels once: runs, changes after a run,
  // and values equal but for their bits (-0, NaN) must all still match.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float4 row[8] = {{0.2f, 0.4f, 0.6f, 1.f},
      {0.2f, 0.4f, 0.6f, 1.f},
      {0.2f, 0.4f, 0.6f, 1.f},
      {0.2f, 0.4f, 0.61f, 1.f},
      {-0.f, 0.5f, nan, 0.5f},
      {0.f, 0.5f, nan, 0.5f},
      {0.f, 0.5f, nan, 0.5f},
      {0.2f, 0.4f, 0.6f, 1.f}};
  std::vector<uint8_t> bulk(8 * 4), single(8 * 4);
  writeColorPixels(ANARI_UFIXED8_RGBA_SRGB, row, 8, bulk.data());
  for (size_t i = 0; i < 8; i++)
    writeColor(ANARI_UFIXED8_RGBA_SRGB, row[i], single.data() + i * 4);
  EXPECT_EQ(bulk, single);
}
