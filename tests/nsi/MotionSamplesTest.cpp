// Time samples read at shutter times: linear between neighbours, held
// outside, and samples of different lengths told apart.
#include "MotionSamples.h"

#include <gtest/gtest.h>

#include <cstring>

namespace {

using namespace prism::nsi;

Value doubles(std::vector<double> numbers)
{
  Value v;
  v.type = NSITypeDouble;
  v.count = numbers.size();
  v.bytes.resize(numbers.size() * sizeof(double));
  std::memcpy(v.bytes.data(), numbers.data(), v.bytes.size());
  return v;
}

TEST(MotionSamples, LinearBetweenSamplesAndHeldOutside)
{
  Attribute a;
  a.samples[0.5] = doubles({0, 10});
  a.samples[1.5] = doubles({2, 20});
  ASSERT_TRUE(isMoving(a));
  NumberSamples samples;
  ASSERT_TRUE(numberSamples(a, samples));
  EXPECT_EQ(numbersAt(samples, 0.0), (std::vector<double>{0, 10}));
  EXPECT_EQ(numbersAt(samples, 0.5), (std::vector<double>{0, 10}));
  EXPECT_EQ(numbersAt(samples, 1.0), (std::vector<double>{1, 15}));
  EXPECT_EQ(numbersAt(samples, 1.5), (std::vector<double>{2, 20}));
  EXPECT_EQ(numbersAt(samples, 9.0), (std::vector<double>{2, 20}));
}

TEST(MotionSamples, PlainValuesAndSingleSamplesDoNotMove)
{
  Attribute a;
  a.samples[0] = doubles({1});
  EXPECT_FALSE(isMoving(a));
  a.samples[1] = doubles({2});
  EXPECT_TRUE(isMoving(a));
  a.value = doubles({3});
  EXPECT_FALSE(isMoving(a));
}

TEST(MotionSamples, DifferentLengthsAreToldApart)
{
  Attribute a;
  a.samples[0] = doubles({1, 2, 3});
  a.samples[1] = doubles({1, 2, 3, 4, 5, 6});
  NumberSamples samples;
  EXPECT_FALSE(numberSamples(a, samples));
  EXPECT_EQ(samples.size(), 2u); // all of them, for the message
  EXPECT_TRUE(numbersAt({}, 0.5).empty());
}

} // namespace
