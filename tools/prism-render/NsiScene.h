// NSI scene files: recognised by their content (an ASCII NSI stream, plain
// or gzip), and rendered by handing them to libnsi, whose screens and output
// drivers say what is written where.
#pragma once

#include "Options.h"

#include <string>

namespace prism::render {

// Whether `path` holds an ASCII NSI stream: after blanks and '#' comments
// its text starts with an NSI statement keyword. (".nsi" also names NSIS
// installer scripts, so the name decides nothing.)
bool isNsiScene(const std::string &path);

// Renders the NSI stream `options.scene` on `options.library`; the process
// exit code (0, or 1 when libnsi reported an error).
int renderNsiScene(const Options &options);

} // namespace prism::render
