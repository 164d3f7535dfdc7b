// A transferFunction1D volume's tables (spec 5.12.1) as plain data, and the
// one place that turns them into a committed volume: the demo volume and
// prism-render's volume files all go through it.
#pragma once

#include "Scene.h"

#include <anari/anari.h>

#include <array>
#include <vector>

namespace prism::scenes {

struct TransferFunction
{
  std::vector<Vec3> colors;     // linear RGB, evenly spaced over valueRange
  std::vector<float> opacities; // in [0, 1], evenly spaced over valueRange
  std::array<float, 2> valueRange{0.f, 1.f}; // field values, lo < hi
  // The distance (object space) over which an opacity is reached.
  float unitDistance{1.f};
};

// A committed transferFunction1D volume of `field`; releases nothing.
ANARIVolume newTransferFunctionVolume(ANARIDevice device,
    ANARISpatialField field,
    const TransferFunction &transferFunction);

} // namespace prism::scenes
