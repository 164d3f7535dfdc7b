// Element decoding against the spec's rules, with exact expected values.
#include "array/ElementConversion.h"

#include "anari/frontend/type_utility.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

using namespace prism;

namespace {

template <typename T>
float4 read(ANARIDataType type, const T &value)
{
  return readAsFloat4(type, &value);
}

void expectFloat4Eq(float4 actual, float4 expected)
{
  EXPECT_EQ(actual.x, expected.x);
  EXPECT_EQ(actual.y, expected.y);
  EXPECT_EQ(actual.z, expected.z);
  EXPECT_EQ(actual.w, expected.w);
}

// The EOTF in double, the reference for the float table.
double srgbReference(double encoded)
{
  return encoded <= 0.04045 ? encoded / 12.92
                            : std::pow((encoded + 0.055) / 1.055, 2.4);
}

// Every numeric element type, by its enum value.
std::vector<ANARIDataType> numericTypes()
{
  std::vector<ANARIDataType> types;
  for (int t = 1000; t <= 1075; t++)
    types.push_back(ANARIDataType(t));
  for (int t = 2000; t <= 2003; t++)
    types.push_back(ANARIDataType(t));
  return types;
}

// Equal bits, or both NaN (decoding may quiet a NaN either way).
bool sameFloat(float a, float b)
{
  return (std::isnan(a) && std::isnan(b))
         || std::memcmp(&a, &b, sizeof(a)) == 0;
}

} // namespace

TEST(ElementConversion, UFixed8DividesBy255)
{
  EXPECT_EQ(read(ANARI_UFIXED8, uint8_t(0)).x, 0.f);
  EXPECT_EQ(read(ANARI_UFIXED8, uint8_t(255)).x, 1.f);
  EXPECT_EQ(read(ANARI_UFIXED8, uint8_t(128)).x, 128.f / 255.f);
  const uint8_t rgba[4] = {255, 0, 51, 128};
  expectFloat4Eq(
      read(ANARI_UFIXED8_VEC4, rgba), {1.f, 0.f, 0.2f, 128.f / 255.f});
}

TEST(ElementConversion, Fixed8ClampsAtMinusOne)
{
  EXPECT_EQ(read(ANARI_FIXED8, int8_t(-128)).x, -1.f);
  EXPECT_EQ(read(ANARI_FIXED8, int8_t(-127)).x, -1.f);
  EXPECT_EQ(read(ANARI_FIXED8, int8_t(127)).x, 1.f);
  EXPECT_EQ(read(ANARI_FIXED8, int8_t(0)).x, 0.f);
  EXPECT_EQ(read(ANARI_FIXED8, int8_t(64)).x, 64.f / 127.f);
}

TEST(ElementConversion, SixteenBitFixedPoint)
{
  EXPECT_EQ(read(ANARI_UFIXED16, uint16_t(65535)).x, 1.f);
  EXPECT_EQ(read(ANARI_UFIXED16, uint16_t(32768)).x, 32768.f / 65535.f);
  EXPECT_EQ(read(ANARI_UFIXED16, uint16_t(1)).x, 1.f / 65535.f);
  EXPECT_EQ(read(ANARI_FIXED16, int16_t(-32768)).x, -1.f);
  EXPECT_EQ(read(ANARI_FIXED16, int16_t(-32767)).x, -1.f);
  EXPECT_EQ(read(ANARI_FIXED16, int16_t(32767)).x, 1.f);
  EXPECT_EQ(read(ANARI_FIXED16, int16_t(-16384)).x, -16384.f / 32767.f);
}

TEST(ElementConversion, WideFixedPoint)
{
  EXPECT_EQ(read(ANARI_UFIXED32, uint32_t(0xffffffffu)).x, 1.f);
  EXPECT_EQ(read(ANARI_UFIXED32, uint32_t(0)).x, 0.f);
  EXPECT_FLOAT_EQ(read(ANARI_UFIXED32, uint32_t(0x80000000u)).x, 0.5f);
  EXPECT_EQ(read(ANARI_FIXED32, int32_t(INT32_MIN)).x, -1.f);
  EXPECT_EQ(read(ANARI_FIXED32, int32_t(INT32_MAX)).x, 1.f);
  EXPECT_EQ(read(ANARI_UFIXED64, uint64_t(UINT64_MAX)).x, 1.f);
  EXPECT_EQ(read(ANARI_FIXED64, int64_t(INT64_MIN)).x, -1.f);
  EXPECT_EQ(read(ANARI_FIXED64, int64_t(INT64_MAX)).x, 1.f);
  EXPECT_FLOAT_EQ(read(ANARI_FIXED64, int64_t(INT64_MAX / 4)).x, 0.25f);
}

TEST(ElementConversion, IntegersConvertByValue)
{
  EXPECT_EQ(read(ANARI_UINT8, uint8_t(200)).x, 200.f);
  EXPECT_EQ(read(ANARI_INT8, int8_t(-128)).x, -128.f);
  EXPECT_EQ(read(ANARI_INT16, int16_t(-300)).x, -300.f);
  EXPECT_EQ(read(ANARI_UINT16, uint16_t(65535)).x, 65535.f);
  EXPECT_EQ(read(ANARI_UINT64, uint64_t(1) << 40).x, 1099511627776.f);
  const int32_t v[3] = {-5, 7, 100000};
  expectFloat4Eq(read(ANARI_INT32_VEC3, v), {-5.f, 7.f, 100000.f, 1.f});
}

TEST(ElementConversion, MissingComponentsAreZeroZeroZeroOne)
{
  expectFloat4Eq(read(ANARI_FLOAT32, 0.5f), {0.5f, 0.f, 0.f, 1.f});
  const float v2[2] = {2.f, 3.f};
  expectFloat4Eq(read(ANARI_FLOAT32_VEC2, v2), {2.f, 3.f, 0.f, 1.f});
  const float v3[3] = {2.f, 3.f, 4.f};
  expectFloat4Eq(read(ANARI_FLOAT32_VEC3, v3), {2.f, 3.f, 4.f, 1.f});
  const float v4[4] = {2.f, 3.f, 4.f, 0.f};
  expectFloat4Eq(read(ANARI_FLOAT32_VEC4, v4), {2.f, 3.f, 4.f, 0.f});
  expectFloat4Eq(read(ANARI_UINT8, uint8_t(9)), {9.f, 0.f, 0.f, 1.f});
}

TEST(ElementConversion, Float64)
{
  const double v[4] = {0.1, -2.5, 1e300, 3.0};
  expectFloat4Eq(read(ANARI_FLOAT64_VEC4, v),
      {0.1f, -2.5f, std::numeric_limits<float>::infinity(), 3.f});
}

TEST(ElementConversion, Float16KnownValues)
{
  EXPECT_EQ(halfToFloat(0x3C00), 1.f);
  EXPECT_EQ(halfToFloat(0x7BFF), 65504.f);
  EXPECT_EQ(halfToFloat(0x0001), 0x1p-24f);
  EXPECT_EQ(halfToFloat(0x03FF), 1023.f * 0x1p-24f);
  EXPECT_EQ(halfToFloat(0x0400), 0x1p-14f);
  EXPECT_EQ(halfToFloat(0xC000), -2.f);
  EXPECT_EQ(halfToFloat(0x3555), 0.333251953125f);
  EXPECT_EQ(halfToFloat(0x0000), 0.f);
  EXPECT_TRUE(std::signbit(halfToFloat(0x8000)));
  EXPECT_EQ(halfToFloat(0x7C00), std::numeric_limits<float>::infinity());
  EXPECT_EQ(halfToFloat(0xFC00), -std::numeric_limits<float>::infinity());
  EXPECT_TRUE(std::isnan(halfToFloat(0x7E00)));
  EXPECT_TRUE(std::isnan(halfToFloat(0x7C01)));
  const uint16_t v[2] = {0x3C00, 0xC000};
  expectFloat4Eq(read(ANARI_FLOAT16_VEC2, v), {1.f, -2.f, 0.f, 1.f});
}

TEST(ElementConversion, Float16AllFiniteValuesMatchDefinition)
{
  for (uint32_t bits = 0; bits < 0x10000; bits++) {
    const uint32_t exponent = (bits >> 10) & 0x1f;
    if (exponent == 31)
      continue;
    const double mantissa = bits & 0x3ff;
    const double magnitude =
        exponent == 0 ? std::ldexp(mantissa, -24)
                      : std::ldexp(1.0 + mantissa / 1024.0, int(exponent) - 15);
    const double expected = (bits & 0x8000) ? -magnitude : magnitude;
    ASSERT_EQ(halfToFloat(uint16_t(bits)), float(expected)) << bits;
  }
}

#if defined(__SSE2__)
TEST(ElementConversion, Float16SubnormalsSurviveFlushToZero)
{
  // Renderers run with FTZ/DAZ on (Embree's advice); decoding must not
  // depend on float subnormal arithmetic.
  volatile uint16_t smallest = 0x0001, largest = 0x83FF;
  const unsigned saved = _mm_getcsr();
  _mm_setcsr(saved | 0x8040u);
  const float a = halfToFloat(smallest), b = halfToFloat(largest);
  _mm_setcsr(saved);
  EXPECT_EQ(std::bit_cast<uint32_t>(a), 0x33800000u); // 2^-24
  EXPECT_EQ(
      std::bit_cast<uint32_t>(b), std::bit_cast<uint32_t>(-1023.f * 0x1p-24f));
}
#endif

TEST(ElementConversion, Srgb8TableIsTheExactEotf)
{
  for (int c = 0; c < 256; c++)
    EXPECT_EQ(kSrgb8ToLinear[c], float(srgbReference(c / 255.0))) << c;
  EXPECT_EQ(srgb8ToLinear(0), 0.f);
  EXPECT_EQ(srgb8ToLinear(255), 1.f);
  EXPECT_NEAR(srgb8ToLinear(188), 0.5029, 1e-4);
  EXPECT_FLOAT_EQ(srgb8ToLinear(188), float(srgbReference(188 / 255.0)));
}

TEST(ElementConversion, SrgbFunctionsFollowTheFormula)
{
  for (int i = 0; i <= 1000; i++) {
    const float e = i / 1000.f;
    EXPECT_NEAR(srgbToLinear(e), srgbReference(e), 1e-6) << e;
    EXPECT_NEAR(linearToSrgb(srgbToLinear(e)), e, 2e-6) << e;
  }
  EXPECT_EQ(srgbToLinear(0.04045f), 0.04045f / 12.92f);
  EXPECT_EQ(linearToSrgb(0.001f), 12.92f * 0.001f);
}

TEST(ElementConversion, SrgbTypesKeepAlphaLinear)
{
  const float s = kSrgb8ToLinear[188];
  const uint8_t rgba[4] = {188, 0, 255, 128};
  expectFloat4Eq(
      read(ANARI_UFIXED8_RGBA_SRGB, rgba), {s, 0.f, 1.f, 128.f / 255.f});
  expectFloat4Eq(read(ANARI_UFIXED8_RGB_SRGB, rgba), {s, 0.f, 1.f, 1.f});
  const uint8_t ra[2] = {188, 128};
  expectFloat4Eq(read(ANARI_UFIXED8_RA_SRGB, ra), {s, 0.f, 0.f, 128.f / 255.f});
  expectFloat4Eq(read(ANARI_UFIXED8_R_SRGB, uint8_t(188)), {s, 0.f, 0.f, 1.f});
}

TEST(ElementConversion, UnsupportedTypesGiveDefault)
{
  const float box[6] = {1, 2, 3, 4, 5, 6};
  for (ANARIDataType type : {ANARI_UNKNOWN,
           ANARI_STRING,
           ANARI_BOOL,
           ANARI_FLOAT32_BOX3,
           ANARI_FLOAT32_MAT4,
           ANARI_GEOMETRY}) {
    EXPECT_FALSE(canReadAsFloat4(type)) << anari::toString(type);
    expectFloat4Eq(readAsFloat4(type, box), {0.f, 0.f, 0.f, 1.f});
  }
  for (ANARIDataType type : numericTypes())
    EXPECT_TRUE(canReadAsFloat4(type)) << anari::toString(type);
}

TEST(ElementConversion, ReadsUnalignedElements)
{
  unsigned char buffer[1 + 3 * sizeof(float)];
  const float v[3] = {1.5f, -2.f, 8.f};
  std::memcpy(buffer + 1, v, sizeof(v));
  expectFloat4Eq(
      readAsFloat4(ANARI_FLOAT32_VEC3, buffer + 1), {1.5f, -2.f, 8.f, 1.f});
}

TEST(ElementConversion, BulkMatchesSingleForEveryType)
{
  std::mt19937 rng(7);
  constexpr size_t kCount = 37; // not a multiple of any vector width
  for (ANARIDataType type : numericTypes()) {
    const size_t size = anari::sizeOf(type);
    for (size_t stride : {size_t(0), size, size + 5}) {
      const size_t step = stride ? stride : size;
      std::vector<unsigned char> bytes(kCount * step + 8);
      for (auto &b : bytes)
        b = uint8_t(rng());
      std::vector<float4> out4(kCount);
      std::vector<float3> out3(kCount);
      std::vector<float2> out2(kCount);
      std::vector<float> out1(kCount);
      convertToFloat4(type, bytes.data(), kCount, stride, out4.data());
      convertToFloat3(type, bytes.data(), kCount, stride, out3.data());
      convertToFloat2(type, bytes.data(), kCount, stride, out2.data());
      convertToFloat(type, bytes.data(), kCount, stride, out1.data());
      for (size_t i = 0; i < kCount; i++) {
        const float4 e = readAsFloat4(type, bytes.data() + i * step);
        const bool same =
            sameFloat(out4[i].x, e.x) && sameFloat(out4[i].y, e.y)
            && sameFloat(out4[i].z, e.z) && sameFloat(out4[i].w, e.w)
            && sameFloat(out3[i].x, e.x) && sameFloat(out3[i].y, e.y)
            && sameFloat(out3[i].z, e.z) && sameFloat(out2[i].x, e.x)
            && sameFloat(out2[i].y, e.y) && sameFloat(out1[i], e.x);
        ASSERT_TRUE(same) << anari::toString(type) << " stride " << stride
                          << " element " << i;
      }
    }
  }
}

TEST(ElementConversion, BulkInterleavedAttributes)
{
  struct Vertex
  {
    float position[3];
    uint8_t color[4];
  };
  const Vertex vertices[2] = {
      {{1.f, 2.f, 3.f}, {255, 0, 0, 255}}, {{4.f, 5.f, 6.f}, {0, 51, 0, 0}}};
  float3 positions[2];
  float4 colors[2];
  convertToFloat3(ANARI_FLOAT32_VEC3, vertices, 2, sizeof(Vertex), positions);
  convertToFloat4(
      ANARI_UFIXED8_VEC4, vertices[0].color, 2, sizeof(Vertex), colors);
  EXPECT_EQ(positions[1], (float3{4.f, 5.f, 6.f}));
  expectFloat4Eq(colors[0], {1.f, 0.f, 0.f, 1.f});
  expectFloat4Eq(colors[1], {0.f, 0.2f, 0.f, 0.f});
}

TEST(ElementConversion, BulkShapes)
{
  const float v4[2][4] = {{1, 2, 3, 4}, {5, 6, 7, 8}};
  float3 out3[2];
  convertToFloat3(ANARI_FLOAT32_VEC4, v4, 2, 0, out3);
  EXPECT_EQ(out3[1], (float3{5.f, 6.f, 7.f}));
  const float s[2] = {9.f, 10.f};
  float4 out4[2];
  convertToFloat4(ANARI_FLOAT32, s, 2, 0, out4);
  expectFloat4Eq(out4[1], {10.f, 0.f, 0.f, 1.f});
  float out1[2];
  convertToFloat(ANARI_FLOAT32_VEC4, v4, 2, 0, out1);
  EXPECT_EQ(out1[0], 1.f);
  EXPECT_EQ(out1[1], 5.f);
}

TEST(ElementConversion, BulkUnsupportedWritesDefaults)
{
  const char *strings[2] = {"a", "b"};
  float4 out4[2];
  float3 out3[2];
  convertToFloat4(ANARI_STRING, strings, 2, 0, out4);
  convertToFloat3(ANARI_FLOAT32_MAT4, strings, 2, 64, out3);
  expectFloat4Eq(out4[1], {0.f, 0.f, 0.f, 1.f});
  EXPECT_EQ(out3[1], (float3{0.f, 0.f, 0.f}));
}

TEST(ElementConversion, IndicesCopyEveryComponent)
{
  const uint32_t triangles[2][3] = {{0, 1, 2}, {2, 1, 3}};
  uint32_t out[6] = {};
  convertToUint32(ANARI_UINT32_VEC3, triangles, 2, 0, out);
  EXPECT_EQ(std::vector<uint32_t>(out, out + 6),
      (std::vector<uint32_t>{0, 1, 2, 2, 1, 3}));

  const uint16_t small[3] = {7, 65535, 0};
  uint32_t out16[3];
  convertToUint32(ANARI_UINT16, small, 3, 0, out16);
  EXPECT_EQ(out16[1], 65535u);

  const uint64_t wide[2] = {5, (uint64_t(1) << 32) + 9};
  uint32_t narrowed[2];
  convertToUint32(ANARI_UINT64, wide, 2, 0, narrowed);
  EXPECT_EQ(narrowed[0], 5u);
  EXPECT_EQ(narrowed[1], 9u); // wraps like a C cast

  const int32_t negative = -1;
  uint32_t wrapped;
  convertToUint32(ANARI_INT32, &negative, 1, 0, &wrapped);
  EXPECT_EQ(wrapped, 0xffffffffu);

  // Strided: every other uvec2 of a uvec4 array.
  const uint32_t quads[2][4] = {{1, 2, 3, 4}, {5, 6, 7, 8}};
  uint32_t pairs[4];
  convertToUint32(ANARI_UINT32_VEC2, quads, 2, sizeof(quads[0]), pairs);
  EXPECT_EQ(std::vector<uint32_t>(pairs, pairs + 4),
      (std::vector<uint32_t>{1, 2, 5, 6}));
}

TEST(ElementConversion, Indices64)
{
  const uint64_t lines[2][2] = {{0, uint64_t(1) << 40}, {3, 4}};
  uint64_t out[4];
  convertToUint64(ANARI_UINT64_VEC2, lines, 2, 0, out);
  EXPECT_EQ(out[1], uint64_t(1) << 40);
  EXPECT_EQ(out[3], 4u);
  const uint32_t narrow[2] = {0xffffffffu, 1};
  uint64_t widened[2];
  convertToUint64(ANARI_UINT32, narrow, 2, 0, widened);
  EXPECT_EQ(widened[0], 0xffffffffull);
}

TEST(ElementConversion, IndicesRejectNonIntegers)
{
  EXPECT_TRUE(canReadAsUint(ANARI_UINT32_VEC3));
  EXPECT_TRUE(canReadAsUint(ANARI_INT64));
  EXPECT_FALSE(canReadAsUint(ANARI_FLOAT32));
  EXPECT_FALSE(canReadAsUint(ANARI_UFIXED8));
  EXPECT_FALSE(canReadAsUint(ANARI_UFIXED8_R_SRGB));
  EXPECT_FALSE(canReadAsUint(ANARI_STRING));
  const float v[3] = {1.f, 2.f, 3.f};
  uint32_t out[3] = {7, 7, 7};
  convertToUint32(ANARI_FLOAT32_VEC3, v, 1, 0, out);
  EXPECT_EQ(out[0], 0u);
  EXPECT_EQ(out[2], 0u);
}
