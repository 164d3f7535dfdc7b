// The volume transfer-function editor's state: a color map, an opacity
// curve (control values evenly spaced over the range), the value range and
// the unit distance, as scene_io's TransferFunctionOptions (prism-render's
// --tf-*), so the volume is rebuilt exactly as the loaders style it.
#pragma once

#include "VolumeStyle.h"

#include <array>
#include <string>
#include <vector>

namespace prism::viewer {

struct TransferFunctionEdit
{
  int colorMap{0}; // in scenes::colorMaps()
  std::vector<float> opacities{0.f, 0.05f, 0.2f, 0.5f, 1.f};
  bool customRange{false};
  std::array<float, 2> range{0.f, 1.f}; // low, high
  float unitDistance{1.f};
};

// The options the edit stands for; the error names a value out of bounds
// (opacities outside [0, 1], an empty range, a unit distance <= 0).
std::string transferFunctionOptions(
    const TransferFunctionEdit &edit, scene_io::TransferFunctionOptions &out);

} // namespace prism::viewer
