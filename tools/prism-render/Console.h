// prism-render's messages on stderr. One lock serialises them with the
// progress bar, because device status messages arrive on device threads
// while the bar is being redrawn.
#pragma once

#include <string>

namespace prism::render::console {

// Prints "prism-render: <text>" on its own line (clearing a progress bar
// first; the bar is redrawn on its next update).
void message(const std::string &text);
void warning(const std::string &text); // "prism-render: warning: <text>"
void error(const std::string &text);   // "prism-render: error: <text>"

// Replaces the progress line with `line` (no newline); empty clears it.
void progressLine(const std::string &line);

// Whether stderr is a terminal (progress bars only make sense there).
bool stderrIsTerminal();

} // namespace prism::render::console
