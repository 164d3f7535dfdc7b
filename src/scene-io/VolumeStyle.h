// How a volume file is shown: the transfer-function options over the data's
// value range become one transferFunction1D volume in a world of its own.
// Shared by every volume loader (raw, NanoVDB), so they look alike.
#pragma once

#include "TransferFunction.h"

#include <anari/anari.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace prism::scene_io {

// How volumes are colored (prism-render's --tf-*): applied wherever a
// volume is made (volume files, demo:volume). What is not given keeps the
// volume's own default (files: the data's range, coolwarm, the default
// ramp, unit distance 1).
struct TransferFunctionOptions
{
  std::optional<std::array<float, 2>> valueRange;
  std::string colorMap;         // empty: the default
  std::vector<float> opacities; // empty: the default
  std::optional<float> unitDistance;
  bool given{false}; // any option given, for "ignored" warnings
};

// The transfer function of a volume file whose data spans [dataLo,
// dataHi]: coolwarm over that range with the default opacity ramp, then
// whatever the options give.
scenes::TransferFunction transferFunctionFor(
    const TransferFunctionOptions &options, float dataLo, float dataHi);

// Replaces in `transferFunction` what the options give (the range, the
// map's colors, the opacities, the unit distance).
void applyTransferFunctionOptions(const TransferFunctionOptions &options,
    scenes::TransferFunction &transferFunction);

// A committed world holding one transferFunction1D volume of `field`
// (whose reference this takes over).
ANARIWorld newVolumeWorld(ANARIDevice device,
    ANARISpatialField field,
    const scenes::TransferFunction &transferFunction);

// Whether the device has the `fieldSubtype` spatial field and the
// transferFunction1D volume; else the error naming both extensions.
std::string whyVolumesCannotRender(ANARIDevice device,
    const char *fieldSubtype,
    const char *fieldExtension,
    const std::string &what);

} // namespace prism::scene_io
