// The progress bar on stderr: samples done, elapsed time and an estimate of
// the time left. Drawn only when enabled (stderr a terminal, not --quiet);
// otherwise every call does nothing.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace prism::render {

class Progress
{
 public:
  // `total` units of work named `unit` ("samples", "frames").
  Progress(bool enabled, uint32_t total, std::string unit);
  ~Progress();

  // `done` units finished so far; fractions show partial frames. Redraws
  // at most ten times a second.
  void update(double done);
  // Removes the bar.
  void finish();

  // The bar for `done` of `total` after `elapsedSeconds`, `width` columns
  // of bar; exposed for tests.
  static std::string format(double done,
      uint32_t total,
      const std::string &unit,
      double elapsedSeconds,
      int width);

 private:
  bool m_enabled;
  uint32_t m_total;
  std::string m_unit;
  std::chrono::steady_clock::time_point m_start;
  std::chrono::steady_clock::time_point m_lastDraw;
  bool m_drawn{false};
};

// "1.23 s", "2 min 05 s" and the like.
std::string formatDuration(double seconds);

} // namespace prism::render
