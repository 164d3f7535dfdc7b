// Ctrl-C: the first one asks the run to stop at its next check; another one
// a second or more later ends the process at once.
#pragma once

#include <csignal>

namespace prism::render {

constexpr int kExitInterrupted = 128 + SIGINT; // as shells report it

// Installs the SIGINT handler.
void watchInterrupts();

// Whether Ctrl-C came since watchInterrupts.
bool interrupted();

} // namespace prism::render
