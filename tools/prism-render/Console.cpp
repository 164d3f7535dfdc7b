#include "Console.h"

#include <unistd.h>

#include <cstdio>
#include <mutex>

namespace prism::render::console {
namespace {

std::mutex g_mutex;
bool g_progressShown = false;

// Call with g_mutex held.
void clearProgressLocked()
{
  if (g_progressShown) {
    std::fputs("\r\033[K", stderr);
    g_progressShown = false;
  }
}

void printLine(const std::string &line)
{
  std::lock_guard lock(g_mutex);
  clearProgressLocked();
  std::fprintf(stderr, "prism-render: %s\n", line.c_str());
  std::fflush(stderr);
}

} // namespace

void message(const std::string &text)
{
  printLine(text);
}

void warning(const std::string &text)
{
  printLine("warning: " + text);
}

void error(const std::string &text)
{
  printLine("error: " + text);
}

void progressLine(const std::string &line)
{
  std::lock_guard lock(g_mutex);
  clearProgressLocked();
  if (!line.empty()) {
    std::fputs(line.c_str(), stderr);
    g_progressShown = true;
  }
  std::fflush(stderr);
}

bool stderrIsTerminal()
{
  return isatty(STDERR_FILENO) == 1;
}

} // namespace prism::render::console
