// Renders a frame again and again (accumulating samples, or timing frames
// for --bench), showing progress on a terminal. Ctrl-C stops the loop when
// the frame in flight is done, so what was accumulated is whole samples
// (a render call of many samples, pixelSamples, ends whole too: Ctrl-C
// then waits for all of them, which takeSamplesPerCall keeps to a bounded
// number of pixel samples; a second Ctrl-C ends the process at once).
// Devices that call back when a frame is done
// (KHR_FRAME_COMPLETION_CALLBACK) let the loop sleep until then; bench runs
// wait plainly, to time frames alone.
#pragma once

#include <anari/anari.h>

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace prism::render {

// Counts the frames the device reports done.
class FrameCompletions
{
 public:
  // NOTE: runs on a device thread.
  static void onFrame(const void *user, ANARIDevice, ANARIFrame);
  // Whether `count` frames are done, waiting at most `ms` for it.
  bool waitFor(uint64_t count, int ms);

 private:
  std::mutex m_mutex;
  std::condition_variable m_changed;
  uint64_t m_done{0};
};

struct FrameLoop
{
  ANARIDevice device{nullptr};
  ANARIFrame frame{nullptr};
  uint32_t frames{1};
  // Samples per pixel each render call takes (the renderer's pixelSamples);
  // the progress bar counts samples.
  uint32_t samplesPerFrame{1};
  // Set as the frame's completion callback (before its commit); null: wait
  // plainly.
  FrameCompletions *completions{nullptr};
  bool showProgress{false};
  const char *unit{"samples"};
};

struct LoopResult
{
  std::vector<double> frameSeconds; // each finished frame's wall time
  double seconds{0.0};              // the whole loop's
  bool interrupted{false};          // Ctrl-C stopped it before `frames`
};

LoopResult renderFrames(const FrameLoop &loop);

// Gives `renderer` (of `subtype`, committed afterwards by the caller) as
// many of `samples` per render call of `pixels` as its 'pixelSamples'
// allows and Ctrl-C can wait for, so the device's threads stay busy from
// one sample to the next; returns the samples per call, a divisor of
// `samples` (1: the renderer declares no pixelSamples).
uint32_t takeSamplesPerCall(ANARIDevice device,
    ANARIRenderer renderer,
    const std::string &subtype,
    uint32_t samples,
    uint64_t pixels);

// Registers `completions` as `frame`'s completion callback (not committed).
void callBackWhenDone(
    ANARIDevice device, ANARIFrame frame, FrameCompletions &completions);

// "<scene>: N frames of WxH, renderer R: min, median, max" for --bench.
std::string benchSummary(const std::vector<double> &frameSeconds);

} // namespace prism::render
