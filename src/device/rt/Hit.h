// What a traced ray found: the closest hit's distance, the primitive and
// where on it (u, v: Embree's parameterisation of that primitive type).
#pragma once

#include "../math/Vec.h"

#include <cstdint>
#include <limits>

namespace prism::rt {

constexpr uint32_t kInvalidId = 0xffffffffu;

struct Hit
{
  float t{std::numeric_limits<float>::infinity()};
  float u{0.f};
  float v{0.f};
  float3 geometricNormal{0, 0, 0}; // unnormalised, in the geometry's space
  uint32_t primitiveId{kInvalidId};
  uint32_t geometryId{kInvalidId}; // index of the surface in its group
  uint32_t instanceId{kInvalidId}; // index of the instance in the world

  bool found() const
  {
    return geometryId != kInvalidId;
  }
};

} // namespace prism::rt
