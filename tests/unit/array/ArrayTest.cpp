// Array regions (KHR_ARRAY1D_REGION clamping) and element access.
#include "Device.h"
#include "array/Array.h"

#include <gtest/gtest.h>

namespace prism {
namespace {

struct Region
{
  uint64_t lower, upper;
};

class ArrayRegion : public ::testing::Test
{
 protected:
  Array *newArray(uint64_t count)
  {
    m_values.resize(count);
    for (uint64_t i = 0; i < count; i++)
      m_values[i] = float(i);
    auto handle = m_device.newArray1D(
        m_values.data(), nullptr, nullptr, ANARI_FLOAT32, count);
    return (Array *)m_device.lookup((ANARIObject)handle);
  }
  // Sets `region`, commits, and returns (first value, count) in use.
  std::pair<float, uint64_t> applyRegion(Array *array, Region region)
  {
    m_device.setParameter(
        array->handle(), "region", ANARI_UINT64_REGION1, &region);
    m_device.commitParameters(array->handle());
    m_device.flushCommits();
    return {*(const float *)array->begin(), array->count()};
  }

  Device m_device{nullptr};
  std::vector<float> m_values;
};

TEST_F(ArrayRegion, DefaultsToTheWholeArray)
{
  Array *array = newArray(10);
  EXPECT_EQ(array->count(), 10u);
  EXPECT_EQ(*(const float *)array->begin(), 0.f);
  m_device.release(array->handle());
}

TEST_F(ArrayRegion, UsesTheGivenSubrange)
{
  Array *array = newArray(10);
  EXPECT_EQ(applyRegion(array, {2, 5}), std::make_pair(2.f, uint64_t(3)));
  m_device.release(array->handle());
}

TEST_F(ArrayRegion, ClampsPerTheSpec)
{
  Array *array = newArray(10);
  // upper clamped from above by the capacity
  EXPECT_EQ(applyRegion(array, {4, 100}), std::make_pair(4.f, uint64_t(6)));
  // upper clamped from below by lower + 1
  EXPECT_EQ(applyRegion(array, {7, 3}), std::make_pair(7.f, uint64_t(1)));
  // lower clamped from above by upper - 1 (after upper's clamps)
  EXPECT_EQ(applyRegion(array, {50, 60}), std::make_pair(9.f, uint64_t(1)));
  EXPECT_EQ(applyRegion(array, {0, 0}), std::make_pair(0.f, uint64_t(1)));
  m_device.release(array->handle());
}

TEST_F(ArrayRegion, UnsettingRestoresTheWholeArray)
{
  Array *array = newArray(10);
  applyRegion(array, {2, 5});
  m_device.unsetParameter(array->handle(), "region");
  m_device.commitParameters(array->handle());
  m_device.flushCommits();
  EXPECT_EQ(array->count(), 10u);
  m_device.release(array->handle());
}

TEST(ArrayShape, ObjectArraysRegionTheirObjects)
{
  Device device(nullptr);
  ANARIObject worlds[3] = {device.newWorld(), device.newWorld(), nullptr};
  auto handle = device.newArray1D(worlds, nullptr, nullptr, ANARI_WORLD, 3);
  auto *array = (Array *)device.lookup((ANARIObject)handle);
  ASSERT_TRUE(array->isObjectArray());
  auto objects = array->objects();
  ASSERT_EQ(objects.size(), 3u);
  EXPECT_EQ(objects[0], device.lookup(worlds[0]));
  EXPECT_EQ(objects[2], nullptr);
  const Region region{1, 2};
  device.setParameter(handle, "region", ANARI_UINT64_REGION1, &region);
  device.commitParameters(handle);
  device.flushCommits();
  objects = array->objects();
  ASSERT_EQ(objects.size(), 1u);
  EXPECT_EQ(objects[0], device.lookup(worlds[1]));
  device.release(worlds[0]);
  device.release(worlds[1]);
  device.release(handle);
}

} // namespace
} // namespace prism
