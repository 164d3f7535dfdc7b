// structuredRegular against functions each filter reproduces exactly,
// element decoding by the spec's rules, placement, bounds, conservative
// value ranges and invalid input.
#include "FieldTest.h"

#include "volume/StructuredRegularField.h"

#include <cmath>
#include <functional>
#include <random>

namespace prism {
namespace {

class StructuredRegularFieldTest : public FieldTest
{
 protected:
  // A FLOAT32 field of `dims` samples, sample (i, j, k) = f(i, j, k).
  StructuredRegularField *makeField(int3 dims,
      const std::function<float(float, float, float)> &f,
      const char *filter = "linear",
      float3 origin = {0.f, 0.f, 0.f},
      float3 spacing = {1.f, 1.f, 1.f})
  {
    std::vector<float> values;
    for (int k = 0; k < dims.z; k++)
      for (int j = 0; j < dims.y; j++)
        for (int i = 0; i < dims.x; i++)
          values.push_back(f(float(i), float(j), float(k)));
    auto *result =
        dynamic_cast<StructuredRegularField *>(field("structuredRegular"));
    set(result,
        "data",
        array(ANARI_FLOAT32, values.data(), dims.x, dims.y, dims.z));
    set(result, "filter", filter);
    set(result, "origin", origin);
    set(result, "spacing", spacing);
    commit(result);
    return result;
  }
};

float linearRamp(float x, float y, float z)
{
  return 1.f + 2.f * x - 3.f * y + 0.5f * z;
}

TEST_F(StructuredRegularFieldTest, FactoryMakesTheSubtype)
{
  EXPECT_NE(dynamic_cast<StructuredRegularField *>(field("structuredRegular")),
      nullptr);
}

TEST_F(StructuredRegularFieldTest, LinearRampIsExactAtVerticesAndMidpoints)
{
  const float3 origin{1.f, -2.f, 0.5f};
  const float3 spacing{0.5f, 2.f, 0.25f};
  auto *f = makeField({5, 4, 3}, linearRamp, "linear", origin, spacing);
  ASSERT_TRUE(f->isValid());
  for (float k = 0.f; k <= 2.f; k += 0.5f)
    for (float j = 0.f; j <= 3.f; j += 0.5f)
      for (float i = 0.f; i <= 4.f; i += 0.5f) {
        const float3 position = origin + float3{i, j, k} * spacing;
        EXPECT_NEAR(f->sample(position), linearRamp(i, j, k), 1e-5f)
            << i << " " << j << " " << k;
      }
}

TEST_F(StructuredRegularFieldTest, LinearFilterReproducesLinearFunctions)
{
  auto *f = makeField({6, 7, 5}, linearRamp);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.f, 1.f);
  for (int n = 0; n < 2000; n++) {
    const float3 p{5.f * unit(random), 6.f * unit(random), 4.f * unit(random)};
    EXPECT_NEAR(f->sample(p), linearRamp(p.x, p.y, p.z), 1e-4f);
  }
}

TEST_F(StructuredRegularFieldTest, CubicReproducesQuadraticsInTheInterior)
{
  auto quadratic = [](float x, float y, float z) {
    return 0.5f * x * x - x * y + 0.25f * z * z + 2.f * y - z + 3.f;
  };
  const float3 origin{-1.f, 0.f, 2.f};
  const float3 spacing{1.f, 0.5f, 2.f};
  auto *f = makeField({8, 9, 7}, quadratic, "cubic", origin, spacing);
  ASSERT_TRUE(f->isValid());
  std::mt19937 random(11);
  std::uniform_real_distribution<float> unit(0.f, 1.f);
  for (int n = 0; n < 2000; n++) {
    // Interior: all four taps of each axis inside the grid.
    const float3 grid{1.f + 5.f * unit(random),
        1.f + 6.f * unit(random),
        1.f + 4.f * unit(random)};
    const float expected = quadratic(grid.x, grid.y, grid.z);
    EXPECT_NEAR(f->sample(origin + grid * spacing), expected, 2e-4f)
        << grid.x << " " << grid.y << " " << grid.z;
  }
  // Between samples the cubic is not the linear interpolant of a quadratic.
  auto *linear = makeField({8, 9, 7}, quadratic, "linear", origin, spacing);
  const float3 middle = origin + float3{3.5f, 4.5f, 2.5f} * spacing;
  EXPECT_GT(
      std::abs(linear->sample(middle) - quadratic(3.5f, 4.5f, 2.5f)), 0.1f);
}

TEST_F(StructuredRegularFieldTest, GradientsAreTheInterpolantsDerivatives)
{
  const float3 spacing{0.5f, 2.f, 0.25f};
  auto *linear = makeField({8, 8, 8}, linearRamp, "linear", {}, spacing);
  auto quadratic = [](float x, float y, float z) {
    return 0.5f * x * x - x * y + 0.25f * z * z + 2.f * y - z;
  };
  auto *cubic = makeField({8, 8, 8}, quadratic, "cubic", {}, spacing);
  std::mt19937 random(19);
  std::uniform_real_distribution<float> unit(0.f, 1.f);
  for (int n = 0; n < 500; n++) {
    const float3 grid{1.f + 5.f * unit(random),
        1.f + 5.f * unit(random),
        1.f + 2.f * unit(random)};
    const float3 slope = linear->gradient(grid * spacing);
    EXPECT_NEAR(slope.x, 2.f / spacing.x, 1e-3f);
    EXPECT_NEAR(slope.y, -3.f / spacing.y, 1e-3f);
    EXPECT_NEAR(slope.z, 0.5f / spacing.z, 1e-3f);
    // The cubic reproduces the quadratic, hence its derivative.
    const float3 curve = cubic->gradient(grid * spacing);
    EXPECT_NEAR(curve.x, (grid.x - grid.y) / spacing.x, 1e-3f);
    EXPECT_NEAR(curve.y, (2.f - grid.x) / spacing.y, 1e-3f);
    EXPECT_NEAR(curve.z, (0.5f * grid.z - 1.f) / spacing.z, 1e-3f);
  }
  EXPECT_TRUE(std::isnan(linear->gradient({-1.f, 0.f, 0.f}).x));
}

TEST_F(StructuredRegularFieldTest, NearestPicksTheClosestSampleTiesRoundUp)
{
  auto index = [](float x, float y, float z) {
    return x + 10.f * y + 100.f * z;
  };
  auto *f =
      makeField({4, 4, 4}, index, "nearest", {0.f, 0.f, 0.f}, {2.f, 2.f, 2.f});
  EXPECT_EQ(f->sample({0.f, 0.f, 0.f}), 0.f);
  EXPECT_EQ(f->sample({0.9f, 0.f, 0.f}), 0.f);
  EXPECT_EQ(f->sample({1.1f, 2.9f, 0.f}), 11.f);
  EXPECT_EQ(f->sample({1.f, 1.f, 1.f}), 111.f); // ties round up
  EXPECT_EQ(f->sample({6.f, 6.f, 6.f}), 333.f);
  EXPECT_EQ(f->sample({5.1f, 0.2f, 4.9f}), 203.f);
}

TEST_F(StructuredRegularFieldTest, ElementTypesDecodeBySpecRules)
{
  auto decoded = [&](ANARIDataType type, const void *values) {
    auto *f =
        dynamic_cast<StructuredRegularField *>(field("structuredRegular"));
    set(f, "data", array(type, values, 4, 1, 1));
    commit(f);
    EXPECT_TRUE(f->isValid()) << anari::toString(type);
    std::vector<float> result;
    for (int i = 0; i < 4; i++)
      result.push_back(f->sampleAt({i, 0, 0}));
    return result;
  };
  const uint8_t ufixed8[] = {0, 51, 128, 255};
  EXPECT_EQ(decoded(ANARI_UFIXED8, ufixed8),
      (std::vector<float>{0.f, 51.f / 255.f, 128.f / 255.f, 1.f}));
  const uint16_t ufixed16[] = {0, 1, 32768, 65535};
  EXPECT_EQ(decoded(ANARI_UFIXED16, ufixed16),
      (std::vector<float>{0.f, 1.f / 65535.f, 32768.f / 65535.f, 1.f}));
  const int16_t fixed16[] = {-32768, -32767, 0, 32767};
  EXPECT_EQ(decoded(ANARI_FIXED16, fixed16),
      (std::vector<float>{-1.f, -1.f, 0.f, 1.f}));
  const int16_t fixed16Half[] = {16384, -16384, 1, -1};
  const auto half = decoded(ANARI_FIXED16, fixed16Half);
  EXPECT_FLOAT_EQ(half[0], 16384.f / 32767.f);
  EXPECT_FLOAT_EQ(half[1], -16384.f / 32767.f);
  EXPECT_FLOAT_EQ(half[2], 1.f / 32767.f);
  const float float32[] = {-1.5f, 0.f, 2.25f, 1e30f};
  EXPECT_EQ(decoded(ANARI_FLOAT32, float32),
      (std::vector<float>{-1.5f, 0.f, 2.25f, 1e30f}));
  const double float64[] = {-0.125, 3.5, 1e-3, 7.0};
  EXPECT_EQ(decoded(ANARI_FLOAT64, float64),
      (std::vector<float>{-0.125f, 3.5f, float(1e-3), 7.f}));
  EXPECT_FALSE(reportedError());
}

TEST_F(StructuredRegularFieldTest, BoundsAreVertexCentredAndInclusive)
{
  const float3 origin{1.f, 2.f, 3.f};
  const float3 spacing{0.5f, 0.25f, 2.f};
  auto *f = makeField({5, 9, 3}, linearRamp, "linear", origin, spacing);
  const box3 bounds = f->bounds();
  EXPECT_EQ(bounds.lower, origin);
  EXPECT_EQ(bounds.upper, (float3{3.f, 4.f, 7.f}));
  EXPECT_FLOAT_EQ(f->cellSize(), 0.25f);
  // Every corner is inside; a step past any face is outside.
  for (int corner = 0; corner < 8; corner++) {
    const float3 p{
        corner & 1 ? 3.f : 1.f, corner & 2 ? 4.f : 2.f, corner & 4 ? 7.f : 3.f};
    EXPECT_FALSE(std::isnan(f->sample(p))) << corner;
  }
  const float3 inside{2.f, 3.f, 5.f};
  for (int axis = 0; axis < 3; axis++) {
    float3 below = inside, above = inside;
    below[axis] = std::nextafter(bounds.lower[axis], -1e9f);
    above[axis] = std::nextafter(bounds.upper[axis], 1e9f);
    EXPECT_TRUE(std::isnan(f->sample(below))) << axis;
    EXPECT_TRUE(std::isnan(f->sample(above))) << axis;
  }
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_TRUE(std::isnan(f->sample({nan, 3.f, 5.f})));
  // The upper corner reads the last sample.
  EXPECT_NEAR(f->sample(bounds.upper), linearRamp(4.f, 8.f, 2.f), 1e-5f);
}

TEST_F(StructuredRegularFieldTest, FlatSlabsSampleWithoutDividingByZero)
{
  for (const char *filter : {"nearest", "linear", "cubic"}) {
    auto *slab = makeField(
        {4, 3, 1}, linearRamp, filter, {0.f, 0.f, 5.f}, {1.f, 1.f, 1.f});
    ASSERT_TRUE(slab->isValid()) << filter;
    EXPECT_EQ(slab->bounds().lower.z, 5.f);
    EXPECT_EQ(slab->bounds().upper.z, 5.f);
    EXPECT_FLOAT_EQ(slab->sample({2.f, 1.f, 5.f}), linearRamp(2.f, 1.f, 0.f))
        << filter;
    EXPECT_TRUE(std::isnan(slab->sample({2.f, 1.f, 5.001f})));
    float lo, hi;
    slab->valueRange(slab->bounds(), lo, hi);
    EXPECT_LE(lo, hi);

    auto *point = makeField({1, 1, 1}, linearRamp, filter);
    ASSERT_TRUE(point->isValid());
    EXPECT_EQ(point->sample({0.f, 0.f, 0.f}), 1.f);
    EXPECT_TRUE(std::isnan(point->sample({0.1f, 0.f, 0.f})));
  }
}

TEST_F(StructuredRegularFieldTest, ValueRangeCoversEverySampleOfEveryFilter)
{
  std::mt19937 random(3);
  std::uniform_real_distribution<float> unit(0.f, 1.f);
  std::vector<float> noise(23 * 18 * 11);
  for (float &v : noise)
    v = unit(random) < 0.1f ? 10.f * unit(random) : unit(random);
  const float3 origin{-3.f, 1.f, 0.f};
  const float3 spacing{0.7f, 1.3f, 0.4f};
  for (const char *filter : {"nearest", "linear", "cubic"}) {
    size_t n = 0;
    auto *f = makeField(
        {23, 18, 11},
        [&](float, float, float) { return noise[n++]; },
        filter,
        origin,
        spacing);
    ASSERT_TRUE(f->isValid());
    expectValueRangesCoverSamples(*f, 17, filter);
  }
}

TEST_F(StructuredRegularFieldTest, ValueRangeIsLocal)
{
  // A step: the low half's blocks must not report the high half's values.
  auto *f = makeField(
      {64, 4, 4}, [](float x, float, float) { return x < 32.f ? 0.f : 1.f; });
  float lo, hi;
  f->valueRange({{0.f, 0.f, 0.f}, {10.f, 3.f, 3.f}}, lo, hi);
  EXPECT_EQ(lo, 0.f);
  EXPECT_EQ(hi, 0.f);
  f->valueRange({{0.f, 0.f, 0.f}, {63.f, 3.f, 3.f}}, lo, hi);
  EXPECT_EQ(lo, 0.f);
  EXPECT_EQ(hi, 1.f);
}

TEST_F(StructuredRegularFieldTest, TheArrayMayBeFreedAfterCommit)
{
  auto values = std::make_unique<std::vector<float>>(3 * 3 * 3);
  for (size_t n = 0; n < values->size(); n++)
    (*values)[n] = float(n);
  ANARIArray3D handle = m_device.newArray3D(
      values->data(), nullptr, nullptr, ANARI_FLOAT32, 3, 3, 3);
  auto *f = field("structuredRegular");
  set(f, "data", m_device.lookup(handle));
  commit(f);
  m_device.release(handle);
  std::fill(values->begin(), values->end(), -1.f);
  values.reset();
  ASSERT_TRUE(f->isValid());
  EXPECT_FLOAT_EQ(f->sample({1.f, 2.f, 1.5f}), 1.f + 3.f * 2.f + 9.f * 1.5f);
}

TEST_F(StructuredRegularFieldTest, BadInputIsReportedAndLeavesTheFieldInvalid)
{
  const float values[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  auto expectError = [&](SpatialField *f, const char *part) {
    m_messages.clear();
    commit(f);
    EXPECT_FALSE(f->isValid()) << part;
    EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR, part)) << part;
  };
  expectError(field("structuredRegular"), "missing 'data'");

  auto *oneD = field("structuredRegular");
  set(oneD, "data", array(ANARI_FLOAT32, values, 8));
  expectError(oneD, "missing 'data'");

  const int32_t ints[8] = {};
  auto *wrongType = field("structuredRegular");
  set(wrongType, "data", array(ANARI_INT32, ints, 2, 2, 2));
  expectError(wrongType, "element type");

  const float3 badSpacings[] = {{1.f, -1.f, 1.f},
      {0.f, 1.f, 1.f},
      {1.f, 1.f, std::numeric_limits<float>::infinity()},
      {std::numeric_limits<float>::quiet_NaN(), 1.f, 1.f}};
  for (float3 spacing : badSpacings) {
    auto *f = field("structuredRegular");
    set(f, "data", array(ANARI_FLOAT32, values, 2, 2, 2));
    set(f, "spacing", spacing);
    expectError(f, "'spacing'");
  }

  // A zero dimension: the device refuses the array itself.
  m_messages.clear();
  EXPECT_EQ(array(ANARI_FLOAT32, values, 2, 0, 2), nullptr);
  EXPECT_TRUE(reportedError());

  // An unknown filter warns and falls back to linear.
  m_messages.clear();
  auto *f = field("structuredRegular");
  set(f, "data", array(ANARI_FLOAT32, values, 2, 2, 2));
  set(f, "filter", "bicubic");
  commit(f);
  EXPECT_TRUE(f->isValid());
  EXPECT_TRUE(reported(ANARI_SEVERITY_WARNING, "bicubic"));
  EXPECT_FLOAT_EQ(f->sample({0.5f, 0.5f, 0.5f}), 3.5f);

  // A valid field recommitted with bad input has no values any more.
  set(f, "spacing", float3{-1.f, 1.f, 1.f});
  commit(f);
  EXPECT_FALSE(f->isValid());
  EXPECT_TRUE(std::isnan(f->sample({0.5f, 0.5f, 0.5f})));
  float lo, hi;
  f->valueRange({{0.f, 0.f, 0.f}, {1.f, 1.f, 1.f}}, lo, hi);
  EXPECT_GT(lo, hi);

  // A field fixed after an error becomes valid again.
  set(oneD, "data", array(ANARI_FLOAT32, values, 2, 2, 2));
  commit(oneD);
  EXPECT_TRUE(oneD->isValid());
  EXPECT_FLOAT_EQ(oneD->sample({1.f, 1.f, 1.f}), 7.f);
}

} // namespace
} // namespace prism
