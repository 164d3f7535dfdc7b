// Samplers against hand-computed values: Vulkan filtering and wrapping,
// in/out transforms, element decoding, the primitive and transform
// samplers, and invalid input.
#include "Device.h"
#include "array/Array.h"
#include "array/ElementConversion.h"
#include "sampler/Image1D.h"
#include "sampler/Image2D.h"
#include "sampler/Image3D.h"
#include "sampler/Primitive.h"
#include "sampler/Transform.h"

#include "anari/frontend/type_utility.h"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace prism {
namespace {

class SamplerTest : public ::testing::Test
{
 protected:
  void SetUp() override
  {
    ANARIStatusCallback callback = [](const void *user,
                                       ANARIDevice,
                                       ANARIObject,
                                       ANARIDataType,
                                       ANARIStatusSeverity,
                                       ANARIStatusCode,
                                       const char *message) {
      ((std::vector<std::string> *)user)->push_back(message);
    };
    const auto device = (ANARIObject)m_device.this_device();
    m_device.setParameter(
        device, "statusCallback", ANARI_STATUS_CALLBACK, &callback);
    m_device.setParameter(
        device, "statusCallbackUserData", ANARI_VOID_POINTER, &m_messages);
  }
  void TearDown() override
  {
    for (Object *object : m_objects)
      object->releaseInternal();
    for (ANARIObject array : m_arrays)
      m_device.release(array);
  }

  template <typename T>
  T *make()
  {
    auto *object = new T(m_device);
    m_objects.push_back(object);
    return object;
  }
  // A managed array holding a copy of `values` (the caller's element type).
  Array *array(ANARIDataType type,
      const void *values,
      uint64_t n1,
      uint64_t n2 = 0,
      uint64_t n3 = 0)
  {
    ANARIObject handle = nullptr;
    if (n3)
      handle = m_device.newArray3D(nullptr, nullptr, nullptr, type, n1, n2, n3);
    else if (n2)
      handle = m_device.newArray2D(nullptr, nullptr, nullptr, type, n1, n2);
    else
      handle = m_device.newArray1D(nullptr, nullptr, nullptr, type, n1);
    auto *result = (Array *)m_device.lookup(handle);
    std::memcpy(
        result->map(), values, result->capacity() * anari::sizeOf(type));
    result->unmap();
    m_arrays.push_back(handle);
    return result;
  }
  // For object types `mem` is the Object itself.
  static void set(
      Object *object, const char *name, ANARIDataType type, const void *mem)
  {
    Object *value = anari::isObject(type) ? (Object *)mem : nullptr;
    object->stageParameter(name, Parameter::make(type, mem, value));
  }
  static void set(Object *object, const char *name, const char *value)
  {
    set(object, name, ANARI_STRING, value);
  }
  static void commit(Object *object)
  {
    object->snapshotForCommit();
    object->applyCommit();
    object->finalize();
  }
  // Whether a reported message contains every one of `parts`.
  bool reported(std::initializer_list<const char *> parts) const
  {
    for (const std::string &message : m_messages) {
      bool all = true;
      for (const char *part : parts)
        all = all && message.find(part) != std::string::npos;
      if (all)
        return true;
    }
    return false;
  }

  std::vector<std::string> m_messages;
  Device m_device{nullptr};
  std::vector<Object *> m_objects;
  std::vector<ANARIObject> m_arrays;
};

AttributeValues at(Attribute attribute, float4 value)
{
  AttributeValues attributes;
  attributes[attribute] = value;
  return attributes;
}

AttributeValues uv(float u, float v = 0.f, float w = 0.f)
{
  return at(Attribute::Attribute0, {u, v, w, 1.f});
}

// ---------------------------------------------------------------------------
// Filter x wrap mode along every axis of image1D/2D/3D: a 4-texel line
// (10, 20, 30, 40) placed along `axis`, the other axes one texel wide.

struct WrapCase
{
  const char *filter;
  const char *wrapMode;
  float u;
  float expected;
};

// Worked by hand: nearest reads texel floor(4u); linear blends texels
// floor(4u - 0.5) and the next by the fraction of 4u - 0.5; indices wrap
// (mirrorRepeat maps -1 -> 0, -3 -> 2, 4 -> 3, 5 -> 2, 6 -> 1).
const WrapCase kWrapCases[] = {
    {"nearest", "clampToEdge", -0.6f, 10.f},
    {"nearest", "clampToEdge", -0.1f, 10.f},
    {"nearest", "clampToEdge", 0.1f, 10.f},
    {"nearest", "clampToEdge", 0.5f, 30.f},
    {"nearest", "clampToEdge", 1.1f, 40.f},
    {"nearest", "clampToEdge", 1.6f, 40.f},
    {"nearest", "repeat", -0.6f, 20.f},
    {"nearest", "repeat", -0.1f, 40.f},
    {"nearest", "repeat", 0.1f, 10.f},
    {"nearest", "repeat", 0.5f, 30.f},
    {"nearest", "repeat", 1.1f, 10.f},
    {"nearest", "repeat", 1.6f, 30.f},
    {"nearest", "mirrorRepeat", -0.6f, 30.f},
    {"nearest", "mirrorRepeat", -0.1f, 10.f},
    {"nearest", "mirrorRepeat", 0.1f, 10.f},
    {"nearest", "mirrorRepeat", 0.5f, 30.f},
    {"nearest", "mirrorRepeat", 1.1f, 40.f},
    {"nearest", "mirrorRepeat", 1.6f, 20.f},
    {"linear", "clampToEdge", -0.6f, 10.f},
    {"linear", "clampToEdge", -0.1f, 10.f},
    {"linear", "clampToEdge", 0.1f, 10.f},
    {"linear", "clampToEdge", 0.5f, 25.f},
    {"linear", "clampToEdge", 1.1f, 40.f},
    {"linear", "clampToEdge", 1.6f, 40.f},
    {"linear", "repeat", -0.6f, 21.f}, // 0.9 * 20 + 0.1 * 30
    {"linear", "repeat", -0.1f, 37.f}, // 0.9 * 40 + 0.1 * 10
    {"linear", "repeat", 0.1f, 13.f},  // 0.1 * 40 + 0.9 * 10
    {"linear", "repeat", 0.5f, 25.f},
    {"linear", "repeat", 1.1f, 13.f},        // 0.1 * 40 + 0.9 * 10
    {"linear", "repeat", 1.6f, 29.f},        // 0.1 * 20 + 0.9 * 30
    {"linear", "mirrorRepeat", -0.6f, 29.f}, // 0.9 * 30 + 0.1 * 20
    {"linear", "mirrorRepeat", -0.1f, 10.f},
    {"linear", "mirrorRepeat", 0.1f, 10.f},
    {"linear", "mirrorRepeat", 0.5f, 25.f},
    {"linear", "mirrorRepeat", 1.1f, 40.f},
    {"linear", "mirrorRepeat", 1.6f, 21.f}, // 0.1 * 30 + 0.9 * 20
};

class WrapAndFilter : public SamplerTest,
                      public ::testing::WithParamInterface<std::pair<int, int>>
{
 protected:
  // The sampler of `dimensions` with the line along `axis`, set up for `c`.
  ImageSampler *line(int dimensions, int axis, const WrapCase &c)
  {
    const float texels[4] = {10.f, 20.f, 30.f, 40.f};
    uint64_t size[3] = {1, 1, 1};
    size[axis] = 4;
    ImageSampler *sampler = nullptr;
    const char *wrapName = "wrapMode";
    if (dimensions == 1) {
      sampler = make<Image1D>();
      set(sampler, "image", ANARI_ARRAY1D, array(ANARI_FLOAT32, texels, 4));
    } else if (dimensions == 2) {
      sampler = make<Image2D>();
      set(sampler,
          "image",
          ANARI_ARRAY2D,
          array(ANARI_FLOAT32, texels, size[0], size[1]));
      wrapName = axis == 0 ? "wrapMode1" : "wrapMode2";
    } else {
      sampler = make<Image3D>();
      set(sampler,
          "image",
          ANARI_ARRAY3D,
          array(ANARI_FLOAT32, texels, size[0], size[1], size[2]));
      wrapName = axis == 0   ? "wrapMode1"
                 : axis == 1 ? "wrapMode2"
                             : "wrapMode3";
    }
    set(sampler, "filter", c.filter);
    set(sampler, wrapName, c.wrapMode);
    commit(sampler);
    return sampler;
  }
};

TEST_P(WrapAndFilter, MatchesVulkanRules)
{
  const auto [dimensions, axis] = GetParam();
  for (const WrapCase &c : kWrapCases) {
    ImageSampler *sampler = line(dimensions, axis, c);
    ASSERT_TRUE(sampler->isValid());
    float coordinates[3] = {0.5f, 0.5f, 0.5f};
    coordinates[axis] = c.u;
    const float4 value =
        sampler->sample(uv(coordinates[0], coordinates[1], coordinates[2]));
    EXPECT_NEAR(value.x, c.expected, 1e-5f)
        << c.filter << " " << c.wrapMode << " u=" << c.u;
    // A FLOAT32 image completes to (value, 0, 0, 1).
    EXPECT_EQ(value.y, 0.f);
    EXPECT_EQ(value.z, 0.f);
    EXPECT_FLOAT_EQ(value.w, 1.f);
  }
  EXPECT_TRUE(m_messages.empty()) << m_messages.front();
}

INSTANTIATE_TEST_SUITE_P(EveryAxis,
    WrapAndFilter,
    ::testing::Values(std::pair{1, 0},
        std::pair{2, 0},
        std::pair{2, 1},
        std::pair{3, 0},
        std::pair{3, 1},
        std::pair{3, 2}),
    [](const auto &info) {
      return "image" + std::to_string(info.param.first) + "D_axis"
             + std::to_string(info.param.second + 1);
    });

TEST_F(SamplerTest, ClampToBorderBlendsTheBorderColor)
{
  const float texels[4] = {10.f, 20.f, 30.f, 40.f};
  auto *sampler = make<Image1D>();
  set(sampler, "image", ANARI_ARRAY1D, array(ANARI_FLOAT32, texels, 4));
  set(sampler, "wrapMode", "clampToBorder");
  const float4 border{100.f, 100.f, 100.f, 100.f};
  set(sampler, "borderColor", ANARI_FLOAT32_VEC4, &border);
  commit(sampler);
  EXPECT_NEAR(sampler->sample(uv(0.1f)).x, 19.f, 1e-5f); // 0.1 * 100 + 0.9*10
  EXPECT_NEAR(sampler->sample(uv(0.5f)).x, 25.f, 1e-5f);
  set(sampler, "filter", "nearest");
  commit(sampler);
  EXPECT_EQ(sampler->sample(uv(-0.1f)), border);
  EXPECT_EQ(sampler->sample(uv(0.9f)).x, 40.f);
}

TEST_F(SamplerTest, DefaultsAreLinearAndClampToEdge)
{
  const float texels[4] = {10.f, 20.f, 30.f, 40.f};
  auto *sampler = make<Image1D>();
  set(sampler, "image", ANARI_ARRAY1D, array(ANARI_FLOAT32, texels, 4));
  commit(sampler);
  EXPECT_EQ(sampler->filter(), Filter::Linear);
  EXPECT_EQ(sampler->wrapMode(0), WrapMode::ClampToEdge);
  EXPECT_EQ(sampler->sample(uv(0.5f)).x, 25.f);
  EXPECT_EQ(sampler->sample(uv(-3.f)).x, 10.f);
}

// ---------------------------------------------------------------------------
// image2D

class Image2DTest : public SamplerTest
{
 protected:
  // 2x2 texels, x fastest: (0,0)=1, (1,0)=2, (0,1)=3, (1,1)=4.
  Image2D *quad(const char *filter)
  {
    const float texels[4] = {1.f, 2.f, 3.f, 4.f};
    auto *sampler = make<Image2D>();
    set(sampler, "image", ANARI_ARRAY2D, array(ANARI_FLOAT32, texels, 2, 2));
    set(sampler, "filter", filter);
    return sampler;
  }
};

TEST_F(Image2DTest, BilinearIsExactAtTexelCentres)
{
  Image2D *sampler = quad("linear");
  commit(sampler);
  EXPECT_EQ(sampler->sample(uv(0.25f, 0.25f)).x, 1.f);
  EXPECT_EQ(sampler->sample(uv(0.75f, 0.25f)).x, 2.f);
  EXPECT_EQ(sampler->sample(uv(0.25f, 0.75f)).x, 3.f);
  EXPECT_EQ(sampler->sample(uv(0.75f, 0.75f)).x, 4.f);
}

TEST_F(Image2DTest, BilinearAveragesAtMidpoints)
{
  Image2D *sampler = quad("linear");
  commit(sampler);
  EXPECT_EQ(sampler->sample(uv(0.5f, 0.25f)).x, 1.5f);
  EXPECT_EQ(sampler->sample(uv(0.5f, 0.75f)).x, 3.5f);
  EXPECT_EQ(sampler->sample(uv(0.25f, 0.5f)).x, 2.f);
  EXPECT_EQ(sampler->sample(uv(0.5f, 0.5f)).x, 2.5f);
  // A quarter of the way: 0.75 * (0.75 * 1 + 0.25 * 2) + 0.25 * (...).
  EXPECT_NEAR(sampler->sample(uv(0.375f, 0.375f)).x, 1.75f, 1e-6f);
}

TEST_F(Image2DTest, NearestPicksTheTexelContainingTheCoordinate)
{
  Image2D *sampler = quad("nearest");
  commit(sampler);
  EXPECT_EQ(sampler->sample(uv(0.49f, 0.51f)).x, 3.f);
  EXPECT_EQ(sampler->sample(uv(0.5f, 0.5f)).x, 4.f);
  EXPECT_EQ(sampler->sample(uv(0.f, 0.f)).x, 1.f);
}

TEST_F(Image2DTest, WrapModesApplyPerDimension)
{
  Image2D *sampler = quad("nearest");
  set(sampler, "wrapMode1", "mirrorRepeat");
  set(sampler, "wrapMode2", "repeat");
  commit(sampler);
  // x index -1 mirrors to 0, y index -1 repeats to 1: texel (0, 1).
  EXPECT_EQ(sampler->sample(uv(-0.1f, -0.1f)).x, 3.f);
  set(sampler, "wrapMode1", "repeat");
  set(sampler, "wrapMode2", "mirrorRepeat");
  commit(sampler);
  EXPECT_EQ(sampler->sample(uv(-0.1f, -0.1f)).x, 2.f);
}

TEST_F(Image2DTest, DecodesSrgbTexelsToLinear)
{
  const uint8_t texel[4] = {188, 128, 0, 128};
  auto *sampler = make<Image2D>();
  set(sampler,
      "image",
      ANARI_ARRAY2D,
      array(ANARI_UFIXED8_RGBA_SRGB, texel, 1, 1));
  commit(sampler);
  const float4 value = sampler->sample(uv(0.3f, 0.7f));
  // ((188 / 255 + 0.055) / 1.055)^2.4; alpha stays linear.
  EXPECT_NEAR(value.x, 0.5028865f, 1e-6f);
  EXPECT_EQ(value.x, srgb8ToLinear(188));
  EXPECT_EQ(value.y, srgb8ToLinear(128));
  EXPECT_EQ(value.z, 0.f);
  EXPECT_FLOAT_EQ(value.w, 128.f / 255.f);
}

TEST_F(Image2DTest, DecodesFixedPointTexels)
{
  const uint16_t unorm[2] = {0, 65535};
  auto *sampler = make<Image2D>();
  set(sampler, "image", ANARI_ARRAY2D, array(ANARI_UFIXED16, unorm, 2, 1));
  commit(sampler);
  EXPECT_EQ(sampler->sample(uv(0.5f, 0.5f)).x, 0.5f);

  // The image2D JSON also takes signed FIXED8 (normal maps).
  const int8_t snorm[3] = {-127, 0, 127};
  set(sampler, "image", ANARI_ARRAY2D, array(ANARI_FIXED8_VEC3, snorm, 1, 1));
  commit(sampler);
  ASSERT_TRUE(sampler->isValid());
  EXPECT_EQ(sampler->sample(uv(0.5f, 0.5f)), (float4{-1.f, 0.f, 1.f, 1.f}));
}

// ---------------------------------------------------------------------------
// image3D

TEST_F(SamplerTest, Image3DTrilinearAtCellCentre)
{
  // Texel (i, j, k) holds i + 2j + 4k.
  float texels[8];
  for (int i = 0; i < 8; i++)
    texels[i] = float(i);
  auto *sampler = make<Image3D>();
  set(sampler, "image", ANARI_ARRAY3D, array(ANARI_FLOAT32, texels, 2, 2, 2));
  commit(sampler);
  EXPECT_EQ(sampler->sample(uv(0.5f, 0.5f, 0.5f)).x, 3.5f);
  EXPECT_EQ(sampler->sample(uv(0.25f, 0.75f, 0.75f)).x, 6.f);
  EXPECT_EQ(sampler->sample(uv(0.5f, 0.25f, 0.75f)).x, 4.5f);
  set(sampler, "filter", "nearest");
  commit(sampler);
  EXPECT_EQ(sampler->sample(uv(0.9f, 0.1f, 0.6f)).x, 5.f);
}

// ---------------------------------------------------------------------------
// Transforms and offsets

TEST_F(SamplerTest, InTransformAndOffsetMapTheInputAttribute)
{
  const float texels[4] = {10.f, 20.f, 30.f, 40.f};
  auto *sampler = make<Image1D>();
  set(sampler, "image", ANARI_ARRAY1D, array(ANARI_FLOAT32, texels, 4));
  set(sampler, "inAttribute", "attribute1");
  // u = 0.5 * y + 0.25 (column-major: column 1 feeds x).
  mat4 transform{};
  transform.col[1] = {0.5f, 0.f, 0.f, 0.f};
  transform.col[3] = {0.f, 0.f, 0.f, 1.f};
  const float4 offset{0.25f, 0.f, 0.f, 0.f};
  set(sampler, "inTransform", ANARI_FLOAT32_MAT4, &transform);
  set(sampler, "inOffset", ANARI_FLOAT32_VEC4, &offset);
  commit(sampler);
  // u = 0.5 * 0.25 + 0.25 = 0.375: the centre of texel 1.
  const AttributeValues hit = at(Attribute::Attribute1, {0.9f, 0.25f, 0, 1});
  EXPECT_EQ(sampler->sample(hit).x, 20.f);
  // attribute0 is not the input: attribute1 stays 0, so u = 0.25.
  EXPECT_EQ(sampler->sample(uv(0.9f)).x, 15.f);
}

TEST_F(SamplerTest, OutTransformAndOffsetMapTheSample)
{
  const float texels[4] = {10.f, 20.f, 30.f, 40.f};
  auto *sampler = make<Image1D>();
  set(sampler, "image", ANARI_ARRAY1D, array(ANARI_FLOAT32, texels, 4));
  // out = (y, 2x, z, w) + (1, 2, 3, 4)
  mat4 transform{};
  transform.col[0] = {0.f, 2.f, 0.f, 0.f};
  transform.col[1] = {1.f, 0.f, 0.f, 0.f};
  transform.col[2] = {0.f, 0.f, 1.f, 0.f};
  transform.col[3] = {0.f, 0.f, 0.f, 1.f};
  const float4 offset{1.f, 2.f, 3.f, 4.f};
  set(sampler, "outTransform", ANARI_FLOAT32_MAT4, &transform);
  set(sampler, "outOffset", ANARI_FLOAT32_VEC4, &offset);
  commit(sampler);
  // The texel (20, 0, 0, 1) becomes (0, 40, 0, 1) + offset.
  EXPECT_EQ(sampler->sample(uv(0.375f)), (float4{1.f, 42.f, 3.f, 5.f}));
}

// ---------------------------------------------------------------------------
// primitive

TEST_F(SamplerTest, PrimitiveReadsPrimitiveIdPlusInOffset)
{
  const float values[8] = {0, 1, 10, 11, 20, 21, 30, 31};
  auto *sampler = make<Primitive>();
  set(sampler, "array", ANARI_ARRAY1D, array(ANARI_FLOAT32_VEC2, values, 4));
  commit(sampler);
  ASSERT_TRUE(sampler->isValid());
  AttributeValues hit;
  hit.primitiveId = 2;
  EXPECT_EQ(sampler->sample(hit), (float4{20.f, 21.f, 0.f, 1.f}));

  const uint64_t offset = 1;
  set(sampler, "inOffset", ANARI_UINT64, &offset);
  commit(sampler);
  EXPECT_EQ(sampler->sample(hit), (float4{30.f, 31.f, 0.f, 1.f}));
  // Past the end: an unset attribute.
  hit.primitiveId = 3;
  EXPECT_EQ(sampler->sample(hit), (float4{0.f, 0.f, 0.f, 1.f}));
  hit.primitiveId = 0xffffffffu;
  const uint64_t huge = ~uint64_t(0);
  set(sampler, "inOffset", ANARI_UINT64, &huge);
  commit(sampler);
  EXPECT_EQ(sampler->sample(hit), (float4{0.f, 0.f, 0.f, 1.f}));
  EXPECT_TRUE(m_messages.empty()) << m_messages.front();
}

TEST_F(SamplerTest, PrimitiveHonoursTheArrayRegionAndOutTransform)
{
  const uint8_t values[4] = {0, 51, 102, 255};
  Array *data = array(ANARI_UFIXED8, values, 4);
  struct Region
  {
    uint64_t lower, upper;
  } region{1, 3};
  set(data, "region", ANARI_UINT64_REGION1, &region);
  commit(data);
  auto *sampler = make<Primitive>();
  set(sampler, "array", ANARI_ARRAY1D, data);
  const float4 offset{0.f, 0.f, 0.f, 1.f};
  set(sampler, "outOffset", ANARI_FLOAT32_VEC4, &offset);
  commit(sampler);
  AttributeValues hit;
  hit.primitiveId = 1; // element 2 of the array: 102 / 255
  const float4 value = sampler->sample(hit);
  EXPECT_FLOAT_EQ(value.x, 0.4f);
  EXPECT_EQ(value.w, 2.f);
  hit.primitiveId = 2; // element 3 is outside the region
  EXPECT_EQ(sampler->sample(hit), (float4{0.f, 0.f, 0.f, 2.f}));
}

// ---------------------------------------------------------------------------
// transform

TEST_F(SamplerTest, TransformPassesTheAttributeThroughOutTransform)
{
  auto *sampler = make<Transform>();
  commit(sampler);
  EXPECT_EQ(
      sampler->sample(uv(0.1f, 0.2f, 0.3f)), (float4{0.1f, 0.2f, 0.3f, 1.f}));

  set(sampler, "inAttribute", "worldPosition");
  mat4 scale{};
  scale.col[0] = {2.f, 0.f, 0.f, 0.f};
  scale.col[1] = {0.f, 3.f, 0.f, 0.f};
  scale.col[2] = {0.f, 0.f, 4.f, 0.f};
  scale.col[3] = {0.f, 0.f, 0.f, 1.f};
  const float4 offset{1.f, 1.f, 1.f, 0.f};
  set(sampler, "outTransform", ANARI_FLOAT32_MAT4, &scale);
  set(sampler, "outOffset", ANARI_FLOAT32_VEC4, &offset);
  commit(sampler);
  const AttributeValues hit =
      at(Attribute::WorldPosition, {1.f, 2.f, 3.f, 1.f});
  EXPECT_EQ(sampler->sample(hit), (float4{3.f, 7.f, 13.f, 1.f}));
  EXPECT_TRUE(m_messages.empty()) << m_messages.front();
}

// ---------------------------------------------------------------------------
// Invalid input: reported, isValid() false, sampling stays safe.

TEST_F(SamplerTest, MissingImageIsReportedAndInvalid)
{
  auto *sampler = make<Image2D>();
  commit(sampler);
  EXPECT_FALSE(sampler->isValid());
  EXPECT_TRUE(reported({"image2D", "'image'", "not set"}));
  EXPECT_EQ(sampler->sample(uv(0.5f, 0.5f)), (float4{0.f, 0.f, 0.f, 1.f}));
}

TEST_F(SamplerTest, WrongElementTypeIsReportedAndInvalid)
{
  const int32_t texels[4] = {1, 2, 3, 4};
  auto *sampler = make<Image1D>();
  set(sampler, "image", ANARI_ARRAY1D, array(ANARI_INT32, texels, 4));
  commit(sampler);
  EXPECT_FALSE(sampler->isValid());
  EXPECT_TRUE(reported({"'image'", "ANARI_INT32", "invalid"}));

  // Signed FIXED8 is an image2D-only addition.
  const int8_t snorm[3] = {0, 0, 127};
  set(sampler, "image", ANARI_ARRAY1D, array(ANARI_FIXED8_VEC3, snorm, 1));
  commit(sampler);
  EXPECT_FALSE(sampler->isValid());
  EXPECT_TRUE(reported({"ANARI_FIXED8_VEC3"}));

  // Fixing the parameter makes the sampler valid again.
  const float good[1] = {1.f};
  set(sampler, "image", ANARI_ARRAY1D, array(ANARI_FLOAT32, good, 1));
  commit(sampler);
  EXPECT_TRUE(sampler->isValid());
}

TEST_F(SamplerTest, WrongArrayDimensionIsReportedAndInvalid)
{
  const float texels[4] = {1.f, 2.f, 3.f, 4.f};
  auto *sampler = make<Image2D>();
  set(sampler, "image", ANARI_ARRAY1D, array(ANARI_FLOAT32, texels, 4));
  commit(sampler);
  EXPECT_FALSE(sampler->isValid());
  EXPECT_TRUE(reported({"'image'", "ANARI_ARRAY2D"}));
}

TEST_F(SamplerTest, PrimitiveWithoutArrayIsReportedAndInvalid)
{
  auto *sampler = make<Primitive>();
  commit(sampler);
  EXPECT_FALSE(sampler->isValid());
  EXPECT_TRUE(reported({"primitive", "'array'", "not set"}));
  AttributeValues hit;
  EXPECT_EQ(sampler->sample(hit), (float4{0.f, 0.f, 0.f, 1.f}));
}

TEST_F(SamplerTest, UnknownStringsWarnAndUseDefaults)
{
  const float texels[4] = {10.f, 20.f, 30.f, 40.f};
  auto *sampler = make<Image1D>();
  set(sampler, "image", ANARI_ARRAY1D, array(ANARI_FLOAT32, texels, 4));
  set(sampler, "filter", "cubic");
  set(sampler, "wrapMode", "wobble");
  set(sampler, "inAttribute", "texcoord");
  commit(sampler);
  EXPECT_TRUE(sampler->isValid());
  EXPECT_EQ(sampler->filter(), Filter::Linear);
  EXPECT_EQ(sampler->wrapMode(0), WrapMode::ClampToEdge);
  EXPECT_TRUE(reported({"'filter'", "cubic"}));
  EXPECT_TRUE(reported({"'wrapMode'", "wobble"}));
  EXPECT_TRUE(reported({"'inAttribute'", "texcoord"}));
  EXPECT_EQ(sampler->sample(uv(0.5f)).x, 25.f); // attribute0 after all
}

TEST_F(SamplerTest, NonFiniteCoordinatesStayInTheImage)
{
  const float texels[4] = {10.f, 20.f, 30.f, 40.f};
  auto *sampler = make<Image1D>();
  set(sampler, "image", ANARI_ARRAY1D, array(ANARI_FLOAT32, texels, 4));
  set(sampler, "wrapMode", "repeat");
  commit(sampler);
  const float inf = std::numeric_limits<float>::infinity();
  for (float u : {std::numeric_limits<float>::quiet_NaN(), inf, -inf, 1e30f}) {
    const float x = sampler->sample(uv(u)).x;
    EXPECT_TRUE(x >= 10.f && x <= 40.f) << u;
  }
}

TEST_F(SamplerTest, WorksThroughTheDeviceApi)
{
  const float texels[2] = {1.f, 3.f};
  ANARIArray1D image =
      m_device.newArray1D(nullptr, nullptr, nullptr, ANARI_FLOAT32, 2);
  std::memcpy(m_device.mapArray(image), texels, sizeof(texels));
  m_device.unmapArray(image);
  ANARISampler handle = m_device.newSampler("image1D");
  m_device.setParameter(handle, "image", ANARI_ARRAY1D, &image);
  m_device.commitParameters(handle);
  m_device.flushCommits();
  auto *sampler = dynamic_cast<Sampler *>(m_device.lookup(handle));
  ASSERT_NE(sampler, nullptr);
  EXPECT_TRUE(sampler->isValid());
  EXPECT_EQ(sampler->sample(uv(0.5f)).x, 2.f);
  // New array contents reach the sampler at the next refresh (frame start).
  ((float *)m_device.mapArray(image))[1] = 5.f;
  m_device.unmapArray(image);
  sampler->refresh(1);
  EXPECT_EQ(sampler->sample(uv(0.5f)).x, 3.f);
  m_device.release(handle);
  m_device.release(image);
  EXPECT_TRUE(m_messages.empty()) << m_messages.front();
}

TEST_F(SamplerTest, FactoryKnowsEverySubtype)
{
  for (const char *subtype :
      {"image1D", "image2D", "image3D", "primitive", "transform"}) {
    Sampler *sampler = createSampler(m_device, subtype);
    ASSERT_NE(sampler, nullptr) << subtype;
    EXPECT_EQ(sampler->subtype(), subtype);
    EXPECT_EQ(sampler->type(), ANARI_SAMPLER);
    sampler->releaseInternal();
  }
  EXPECT_EQ(createSampler(m_device, "image4D"), nullptr);
}

} // namespace
} // namespace prism
