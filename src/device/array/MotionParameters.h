// The motion.* parameters shared by moving instances and cameras: arrays of
// keys uniformly distributed over the object's `time` box.
#pragma once

#include "../math/MotionTransform.h"

#include <functional>
#include <string>

namespace prism {

class Array;

struct MotionParameters
{
  const Array *transform{nullptr};   // FLOAT32_MAT4 keys; wins if usable
  const Array *scale{nullptr};       // FLOAT32_VEC3
  const Array *rotation{nullptr};    // FLOAT32_QUAT_IJKW
  const Array *translation{nullptr}; // FLOAT32_VEC3
  float2 time{0.f, 1.f};             // of the first and the last key
};

// The keys the parameters give. Unusable input is reported to `warn` and
// dropped: arrays of another element type or without elements, keys that
// are not finite or not invertible, an empty `time`. Decomposed arrays of
// different lengths are each resampled to the longest.
MotionTransform readMotionTransform(const MotionParameters &parameters,
    const std::function<void(const std::string &)> &warn);

} // namespace prism
