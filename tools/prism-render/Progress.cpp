#include "Progress.h"

#include "Console.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace prism::render {

std::string formatDuration(double seconds)
{
  char text[64];
  if (!std::isfinite(seconds) || seconds < 0.0)
    return "?";
  if (seconds < 60.0) {
    std::snprintf(
        text, sizeof(text), "%.*f s", seconds < 10.0 ? 2 : 1, seconds);
  } else if (seconds < 3600.0) {
    const int whole = int(seconds + 0.5);
    std::snprintf(text, sizeof(text), "%d min %02d s", whole / 60, whole % 60);
  } else {
    const int minutes = int(seconds / 60.0 + 0.5);
    std::snprintf(
        text, sizeof(text), "%d h %02d min", minutes / 60, minutes % 60);
  }
  return text;
}

Progress::Progress(bool enabled, uint32_t total, std::string unit)
    : m_enabled(enabled && total > 0),
      m_total(total),
      m_unit(std::move(unit)),
      m_start(std::chrono::steady_clock::now())
{}

Progress::~Progress()
{
  finish();
}

std::string Progress::format(double done,
    uint32_t total,
    const std::string &unit,
    double elapsedSeconds,
    int width)
{
  const double fraction = total > 0 ? std::clamp(done / total, 0.0, 1.0) : 1.0;
  const int filled = int(fraction * width + 0.5);
  std::string bar(size_t(width) + 2, '.');
  bar.front() = '[';
  bar.back() = ']';
  std::fill_n(bar.begin() + 1, filled, '#');
  char counts[96];
  std::snprintf(counts,
      sizeof(counts),
      " %u/%u %s  %3d%%",
      unsigned(std::floor(done)),
      total,
      unit.c_str(),
      int(fraction * 100.0));
  std::string line =
      bar + counts + "  elapsed " + formatDuration(elapsedSeconds);
  // The estimate needs some progress to stand on.
  if (fraction > 0.01 && fraction < 1.0)
    line +=
        "  ETA " + formatDuration(elapsedSeconds * (1.0 - fraction) / fraction);
  return line;
}

void Progress::update(double done)
{
  if (!m_enabled)
    return;
  const auto now = std::chrono::steady_clock::now();
  if (m_drawn && now - m_lastDraw < std::chrono::milliseconds(100)
      && done < m_total)
    return;
  m_lastDraw = now;
  m_drawn = true;
  const double elapsed = std::chrono::duration<double>(now - m_start).count();
  console::progressLine(format(done, m_total, m_unit, elapsed, 30));
}

void Progress::finish()
{
  if (m_enabled && m_drawn)
    console::progressLine("");
  m_drawn = false;
}

} // namespace prism::render
