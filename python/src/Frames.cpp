// Frames: rendering and waiting with the GIL released (other Python threads
// run meanwhile), and channels copied out of the mapped frame.
#include "Binding.h"

#include <anari/frontend/type_utility.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <thread>
#include <vector>

namespace prism::python {

namespace {

void renderAsync(Frame &frame)
{
  frame.withHandle("render", [](ANARIDevice d, ANARIObject h) {
    anariRenderFrame(d, static_cast<ANARIFrame>(h));
  });
}

// Whether the frame finished within `timeoutSeconds` (< 0: wait for it).
bool wait(Frame &frame, double timeoutSeconds)
{
  return frame.withHandle("wait", [&](ANARIDevice d, ANARIObject h) {
    if (timeoutSeconds < 0)
      return anariFrameReady(d, static_cast<ANARIFrame>(h), ANARI_WAIT) != 0;
    // ANARI waits forever or not at all; a deadline is polled: yielding for
    // the first 100 us (small frames finish by then), then sleeping from
    // 20 us up to 1 ms between looks.
    using Clock = std::chrono::steady_clock;
    const Clock::time_point deadline =
        Clock::now()
        + std::chrono::duration_cast<Clock::duration>(
            std::chrono::duration<double>(timeoutSeconds));
    const Clock::time_point spinUntil =
        Clock::now() + std::chrono::microseconds(100);
    Clock::duration pause = std::chrono::microseconds(20);
    while (!anariFrameReady(d, static_cast<ANARIFrame>(h), ANARI_NO_WAIT)) {
      const Clock::time_point now = Clock::now();
      if (now >= deadline)
        return false;
      if (now < spinUntil) {
        std::this_thread::yield();
        continue;
      }
      std::this_thread::sleep_for(std::min(pause, deadline - now));
      pause =
          std::min<Clock::duration>(pause * 2, std::chrono::milliseconds(1));
    }
    return true;
  });
}

// (pixel type, width, height, bytes as a uint8 ndarray) or None when the
// frame has no such channel.
py::object mapChannel(Frame &frame, const std::string &channel)
{
  uint32_t width = 0, height = 0;
  ANARIDataType type = ANARI_UNKNOWN;
  std::vector<unsigned char> pixels;
  const bool mapped =
      frame.withHandle("get", [&](ANARIDevice d, ANARIObject h) {
        const void *memory = anariMapFrame(d,
            static_cast<ANARIFrame>(h),
            channel.c_str(),
            &width,
            &height,
            &type);
        if (!memory)
          return false;
        const size_t bytes = size_t(width) * height * anari::sizeOf(type);
        pixels.resize(bytes);
        std::memcpy(pixels.data(), memory, bytes);
        anariUnmapFrame(d, static_cast<ANARIFrame>(h), channel.c_str());
        return true;
      });
  if (!mapped || type == ANARI_UNKNOWN)
    return py::none();
  py::array_t<uint8_t> out(py::ssize_t(pixels.size()));
  std::memcpy(out.mutable_data(), pixels.data(), pixels.size());
  return py::make_tuple(int(type), width, height, out);
}

} // namespace

void bindFrames(py::module_ &m)
{
  py::class_<Frame, Object, std::shared_ptr<Frame>>(m, "Frame")
      .def("renderAsync", &renderAsync)
      .def("render",
          [](Frame &frame) {
            renderAsync(frame);
            wait(frame, -1.0);
          })
      .def("ready",
          [](Frame &frame) {
            return frame.withHandle("ready", [](ANARIDevice d, ANARIObject h) {
              return anariFrameReady(
                         d, static_cast<ANARIFrame>(h), ANARI_NO_WAIT)
                     != 0;
            });
          })
      .def("wait", &wait, py::arg("timeout") = -1.0)
      .def("discard",
          [](Frame &frame) {
            frame.withHandle("discard", [](ANARIDevice d, ANARIObject h) {
              anariDiscardFrame(d, static_cast<ANARIFrame>(h));
            });
          })
      .def("mapChannel", &mapChannel);
}

} // namespace prism::python
