// How prism-render shows a volume file: the --tf-* options over the data's
// value range become one transferFunction1D volume in a world of its own.
// Shared by every volume loader (raw, NanoVDB), so they look alike.
#pragma once

#include "Options.h"
#include "TransferFunction.h"

#include <anari/anari.h>

namespace prism::render {

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

} // namespace prism::render
