#include "RayValidity.h"

#include <cmath>

namespace prism::rt {
namespace {

bool usable(float v)
{
  return std::isfinite(v) && std::abs(v) <= kLargestCoordinate;
}

} // namespace

bool isTraceable(const float3 &o, const float3 &d, float tMin, float tMax)
{
  return usable(o.x) && usable(o.y) && usable(o.z) && usable(d.x) && usable(d.y)
         && usable(d.z) && tMin >= 0.f && !std::isnan(tMax) && tMax >= tMin
         && std::isfinite(tMin);
}

} // namespace prism::rt
