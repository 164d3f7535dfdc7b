// A device with a recording status callback, and helpers to make arrays
// and spatial fields and commit them the way a flush does.
#pragma once

#include "../ObjectTestFixture.h"
#include "volume/SpatialField.h"

#include "anari/frontend/type_utility.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace prism {

// The object fixture (tests/unit/ObjectTestFixture.h) plus fields made
// through the device's factory and 3D arrays.
class FieldTest : public testing::ObjectTestFixture
{
 protected:
  using ObjectTestFixture::reported;
  using ObjectTestFixture::set;

  // A field of `subtype` made through the device's factory.
  SpatialField *field(const char *subtype)
  {
    ANARIObject handle = m_device.newSpatialField(subtype);
    m_handles.push_back(handle);
    return dynamic_cast<SpatialField *>(m_device.lookup(handle));
  }
  // A managed array holding a copy of `values`; NULL if the device refuses
  // the shape.
  Array *array(ANARIDataType type,
      const void *values,
      uint64_t n1,
      uint64_t n2 = 0,
      uint64_t n3 = 0)
  {
    ANARIObject handle = nullptr;
    if (n3 || n2)
      handle = m_device.newArray3D(nullptr, nullptr, nullptr, type, n1, n2, n3);
    else
      handle = m_device.newArray1D(nullptr, nullptr, nullptr, type, n1);
    if (!handle)
      return nullptr;
    m_handles.push_back(handle);
    auto *result = (Array *)m_device.lookup(handle);
    std::memcpy(
        result->map(), values, result->capacity() * anari::sizeOf(type));
    result->unmap();
    return result;
  }
  static void set(Object *object, const char *name, Object *value)
  {
    object->stageParameter(name, Parameter::make(value->type(), value, value));
  }
  static void set(Object *object, const char *name, const char *value)
  {
    object->stageParameter(name, Parameter::make(ANARI_STRING, value, nullptr));
  }
  static void set(Object *object, const char *name, float3 value)
  {
    object->stageParameter(
        name, Parameter::make(ANARI_FLOAT32_VEC3, &value, nullptr));
  }
  // Whether a message of `severity` containing `part` was reported.
  bool reported(ANARIStatusSeverity severity, const char *part) const
  {
    for (const Message &message : m_messages)
      if (message.severity == severity
          && message.text.find(part) != std::string::npos)
        return true;
    return false;
  }
  bool reportedError() const
  {
    for (const Message &message : m_messages)
      if (message.severity <= ANARI_SEVERITY_ERROR)
        return true;
    return false;
  }

  // valueRange() of random regions (some poking out of the field, some
  // thin) against sample() at random points and corners inside them, and
  // an empty range for a region beside the field.
  static void expectValueRangesCoverSamples(
      const SpatialField &f, uint32_t seed, const char *label)
  {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> unit(0.f, 1.f);
    const box3 bounds = f.bounds();
    const float3 size = extent(bounds);
    for (int r = 0; r < 300; r++) {
      float3 a, b;
      for (int axis = 0; axis < 3; axis++) {
        a[axis] =
            bounds.lower[axis] + size[axis] * (1.2f * unit(random) - 0.1f);
        const float width =
            size[axis] * (r % 3 == 0 ? 0.02f : 0.3f) * unit(random);
        b[axis] = a[axis] + width;
      }
      const box3 region{a, b};
      float lo, hi;
      f.valueRange(region, lo, hi);
      const box3 clipped = intersect(region, bounds);
      if (isEmpty(clipped)) {
        EXPECT_GT(lo, hi) << label;
        continue;
      }
      ASSERT_LE(lo, hi) << label;
      for (int s = 0; s < 40; s++) {
        float3 p;
        for (int axis = 0; axis < 3; axis++) {
          // Corners first: points on block boundaries.
          p[axis] = s < 8 ? ((s >> axis) & 1 ? clipped.upper[axis]
                                             : clipped.lower[axis])
                          : clipped.lower[axis]
                                + (clipped.upper[axis] - clipped.lower[axis])
                                      * unit(random);
        }
        const float value = f.sample(p);
        ASSERT_FALSE(std::isnan(value)) << label;
        EXPECT_LE(lo, value) << label;
        EXPECT_GE(hi, value) << label;
      }
    }
    float lo, hi;
    f.valueRange({bounds.upper + 1.f, bounds.upper + 2.f}, lo, hi);
    EXPECT_GT(lo, hi) << label;
  }
};

} // namespace prism
