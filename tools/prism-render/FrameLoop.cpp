#include "FrameLoop.h"

#include "Interrupt.h"
#include "Progress.h"
#include "RendererParameters.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>

namespace prism::render {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// How far the frame being rendered is, 0 to 1 (0 where the device does
// not say).
double partialFrame(ANARIDevice device, ANARIFrame frame)
{
  float partial = 0.f;
  anariGetProperty(device,
      frame,
      "renderProgress",
      ANARI_FLOAT32,
      &partial,
      sizeof(partial),
      ANARI_NO_WAIT);
  return std::clamp(double(partial), 0.0, 1.0);
}

// Waits for frame `index` (counted from 0) to finish. Ctrl-C does not cut
// it short: a frame ends whole, so the image holds whole samples.
void waitForFrame(const FrameLoop &loop, uint32_t index, Progress &progress)
{
  // The progress bar counts samples, of which a frame may take several.
  auto samplesDone = [&](double frames) {
    return frames * loop.samplesPerFrame;
  };
  if (loop.completions) {
    // Woken by the device when the frame is done, and every 20 ms to move
    // the progress bar.
    while (!loop.completions->waitFor(index + 1, 20))
      if (loop.showProgress)
        progress.update(
            samplesDone(index + partialFrame(loop.device, loop.frame)));
  } else if (loop.showProgress) {
    while (!anariFrameReady(loop.device, loop.frame, ANARI_NO_WAIT)) {
      progress.update(
          samplesDone(index + partialFrame(loop.device, loop.frame)));
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
  anariFrameReady(loop.device, loop.frame, ANARI_WAIT);
  if (loop.showProgress)
    progress.update(samplesDone(index + 1));
}

} // namespace

void FrameCompletions::onFrame(const void *user, ANARIDevice, ANARIFrame)
{
  auto *self = (FrameCompletions *)user;
  {
    std::lock_guard lock(self->m_mutex);
    self->m_done++;
  }
  self->m_changed.notify_all();
}

bool FrameCompletions::waitFor(uint64_t count, int ms)
{
  std::unique_lock lock(m_mutex);
  return m_changed.wait_for(
      lock, std::chrono::milliseconds(ms), [&] { return m_done >= count; });
}

void callBackWhenDone(
    ANARIDevice device, ANARIFrame frame, FrameCompletions &completions)
{
  const ANARIFrameCompletionCallback callback = &FrameCompletions::onFrame;
  anariSetParameter(device,
      frame,
      "frameCompletionCallback",
      ANARI_FRAME_COMPLETION_CALLBACK,
      &callback);
  // VOID_POINTER values are passed as the pointer itself (spec).
  anariSetParameter(device,
      frame,
      "frameCompletionCallbackUserData",
      ANARI_VOID_POINTER,
      &completions);
}

LoopResult renderFrames(const FrameLoop &loop)
{
  LoopResult result;
  Progress progress(
      loop.showProgress, loop.frames * loop.samplesPerFrame, loop.unit);
  const auto start = Clock::now();
  for (uint32_t i = 0; i < loop.frames; i++) {
    if (interrupted()) {
      result.interrupted = true;
      break;
    }
    const auto frameStart = Clock::now();
    anariRenderFrame(loop.device, loop.frame);
    waitForFrame(loop, i, progress);
    result.frameSeconds.push_back(secondsSince(frameStart));
  }
  result.seconds = secondsSince(start);
  progress.finish();
  return result;
}

uint32_t takeSamplesPerCall(ANARIDevice device,
    ANARIRenderer renderer,
    const std::string &subtype,
    uint32_t samples,
    uint64_t pixels)
{
  if (samples <= 1
      || rendererDeclares(device, subtype, "pixelSamples") != Declared::Yes)
    return 1;
  // At most 2^24 pixel samples a call (512x512 at 64 spp, seconds on
  // simple scenes), so Ctrl-C, which waits for the call in flight, is
  // answered soon; and at most the renderer's largest pixelSamples.
  const uint64_t mostPerCall = std::clamp<uint64_t>(
      (uint64_t(1) << 24) / std::max<uint64_t>(pixels, 1), 1, 65536);
  // The fewest calls of at most that many that take exactly `samples`.
  uint32_t calls = uint32_t((samples + mostPerCall - 1) / mostPerCall);
  while (samples % calls != 0)
    calls++;
  const int32_t perCall = int32_t(samples / calls);
  anariSetParameter(device, renderer, "pixelSamples", ANARI_INT32, &perCall);
  return uint32_t(perCall);
}

std::string benchSummary(const std::vector<double> &frameSeconds)
{
  std::vector<double> sorted = frameSeconds;
  std::sort(sorted.begin(), sorted.end());
  if (sorted.empty())
    return "no frames";
  const size_t n = sorted.size();
  const double median =
      n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
  char text[160];
  std::snprintf(text,
      sizeof(text),
      "min %.2f ms, median %.2f ms, max %.2f ms",
      sorted.front() * 1e3,
      median * 1e3,
      sorted.back() * 1e3);
  return text;
}

} // namespace prism::render
