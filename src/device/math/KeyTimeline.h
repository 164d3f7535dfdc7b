// Where a time falls among keys uniformly distributed over [begin, end]:
// the `time` box of every KHR_*_MOTION_* extension. Outside the span the
// first or last key holds, so an object never vanishes mid-shutter.
#pragma once

#include <algorithm>
#include <cstdint>

namespace prism {

struct KeyTimeline
{
  uint32_t keyCount{1};
  float begin{0.f};
  float end{1.f};

  // Between key `index` and the next, `fraction` of the way.
  struct Position
  {
    uint32_t index;
    float fraction;
  };
  Position locate(float time) const
  {
    if (keyCount < 2 || !(end > begin))
      return {0, 0.f};
    const float span = float(keyCount - 1);
    const float at =
        std::clamp((time - begin) / (end - begin), 0.f, 1.f) * span;
    const uint32_t index = std::min(uint32_t(at), keyCount - 2);
    return {index, at - float(index)};
  }
  // When key `key` applies.
  float keyTime(uint32_t key) const
  {
    return keyCount < 2
               ? begin
               : begin + (end - begin) * float(key) / float(keyCount - 1);
  }
};

} // namespace prism
