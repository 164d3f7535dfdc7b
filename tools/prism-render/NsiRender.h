// NSI scene files are rendered by handing them to libnsi, whose screens and
// output drivers say what is written where (scene_io::isNsiScene tells
// them by content).
#pragma once

#include "Options.h"

namespace prism::render {

// Renders the NSI stream `options.scene` on `options.library`; the process
// exit code (0, or 1 when libnsi reported an error).
int renderNsiScene(const Options &options);

} // namespace prism::render
