#include "Volume.h"

#include <algorithm>

namespace prism {

Volume::Volume(DeviceState &device, const std::string &subtype)
    : Object(device, ANARI_VOLUME, subtype)
{}

void Volume::sampleLine(const float3 &start,
    const float3 &step,
    int count,
    float *extinction,
    float3 *color) const
{
  for (int i = 0; i < count; i++) {
    if (!sample(start + step * float(i), extinction[i], color[i]))
      extinction[i] = 0.f;
  }
}

void Volume::commitParameters()
{
  m_valid = false;
  m_majorants.clear();
  m_visible = readBool("visible", true);
  m_id = read<uint32_t>("id", ANARI_UINT32, ~0u);
  if (!readVolume())
    return;
  // Majorant cells of four data cells: fine enough to skip the empty
  // space around features, coarse enough to cross quickly.
  m_majorants.build(bounds(), 4.f * cellSize(), [&](const box3 &cell) {
    float lo = 0.f, hi = -1.f;
    valueRange(cell, lo, hi);
    return lo > hi ? 0.f : maxExtinction(lo, hi);
  });
  m_valid = true;
}

} // namespace prism
