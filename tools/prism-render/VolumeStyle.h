// How prism-render shows a volume file: the --tf-* options over the data's
// value range become one transferFunction1D volume in a world of its own.
// Shared by every volume loader (raw, NanoVDB), so they look alike.
#pragma once

#include "Options.h"
#include "TransferFunction.h"

#include <anari/anari.h>

namespace prism::render {

// The transfer function for data spanning [dataLo, dataHi]: --tf-range over
// that range, the named color map, the opacity ramp, the unit distance.
scenes::TransferFunction transferFunctionFor(
    const TransferFunctionOptions &options, float dataLo, float dataHi);

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
