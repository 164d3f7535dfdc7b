#include "SpatialField.h"

#include <cmath>
#include <limits>

namespace prism {

SpatialField::SpatialField(DeviceState &device, const std::string &subtype)
    : Object(device, ANARI_SPATIAL_FIELD, subtype)
{}

void SpatialField::commitParameters()
{
  m_valid = false;
  m_valid = readField();
}

FieldFilter SpatialField::readFilter()
{
  const std::string filter = readString("filter", "linear");
  if (filter == "nearest")
    return FieldFilter::Nearest;
  if (filter == "cubic")
    return FieldFilter::Cubic;
  if (filter != "linear") {
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "unknown 'filter' \"%s\"; using linear",
        filter.c_str());
  }
  return FieldFilter::Linear;
}

bool SpatialField::clipToBounds(const box3 &region, box3 &clipped) const
{
  clipped = intersect(region, bounds());
  // Written so that NaN corners count as a miss.
  return clipped.lower.x <= clipped.upper.x
         && clipped.lower.y <= clipped.upper.y
         && clipped.lower.z <= clipped.upper.z;
}

void SpatialField::sampleLine(
    const float3 &start, const float3 &step, int count, float *values) const
{
  for (int i = 0; i < count; i++)
    values[i] = sample(start + step * float(i));
}

float3 SpatialField::gradient(const float3 &position) const
{
  const float h = 0.5f * cellSize();
  auto difference = [&](float3 step) {
    const float ahead = sample(position + step);
    const float behind = sample(position - step);
    // At the domain's edge, a one-sided difference.
    const float centre = sample(position);
    if (std::isnan(ahead))
      return (centre - behind) / h;
    if (std::isnan(behind))
      return (ahead - centre) / h;
    return (ahead - behind) / (2.f * h);
  };
  return {difference({h, 0.f, 0.f}),
      difference({0.f, h, 0.f}),
      difference({0.f, 0.f, h})};
}

} // namespace prism
