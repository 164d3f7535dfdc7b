// Progressive rendering that never blocks the UI: anariRenderFrame, then
// anariFrameReady(NO_WAIT) on every UI frame; when a frame is done its
// shown channel is copied out (the window keeps showing the last finished
// one) and the next sample starts. Any change restarts accumulation: the
// frame in flight is discarded and the next one starts from zero samples.
// The id and depth channels are copied on the first frame after each
// restart only (they do not change as samples accumulate), for picking.
#pragma once

#include "Channel.h"
#include "ChannelView.h"
#include "Picking.h"

#include <anari/anari.h>

#include <cstdint>
#include <vector>

namespace prism::viewer {

// The color channel as the device gave it (linear RGBA floats, row 0 at the
// bottom); empty when the image shows another channel or the device maps
// color otherwise.
struct LinearColorImage
{
  uint32_t width{0}, height{0};
  std::vector<float> pixels; // 4 floats a pixel
};

struct FrameStatus
{
  uint32_t samples{0};     // accumulated in the shown image
  float frameSeconds{0.f}; // the device's `duration` of the last frame
  float convergence{-1.f}; // `refinementProgress`; < 0: not reported
  uint64_t raysTraced{0};  // the renderer's `raysTraced`, where reported
  bool countsRays{false};
  double raysPerSecond{-1.0}; // over the last frame; < 0: not known
  uint64_t finished{0};       // frames finished since the start
};

class FramePipeline
{
 public:
  // `frame` has its world, renderer and camera; the pipeline sets its
  // size, channels and accumulation.
  FramePipeline(ANARIDevice device, ANARIFrame frame, ANARIRenderer renderer);
  ~FramePipeline();
  FramePipeline(const FramePipeline &) = delete;
  FramePipeline &operator=(const FramePipeline &) = delete;

  // The frame's size (a resolution scale for interaction lowers it).
  void setSize(uint32_t width, uint32_t height);
  void setChannel(Channel channel);
  Channel channel() const
  {
    return m_channel;
  }
  // No more samples than this (0: no limit) are rendered until a restart.
  void setSampleLimit(uint32_t samples)
  {
    m_sampleLimit = samples;
  }
  // The renderer whose raysTraced the status shows (the frame's).
  void setRenderer(ANARIRenderer renderer)
  {
    m_renderer = renderer;
  }
  // Called just before each anariRenderFrame (the MPI mirror tells the
  // other processes to render too).
  void beforeRender(void (*hook)(void *), void *user)
  {
    m_beforeRender = hook;
    m_beforeRenderUser = user;
  }
  // Whether a change discards the frame in flight (else it is left to
  // finish: data-parallel frames are rendered by every process together).
  void setDiscards(bool discards)
  {
    m_discards = discards;
  }
  // Something the frame shows changed (committed already).
  void restart();

  // Never waits. True when a frame finished and image() changed.
  bool poll();
  // Waits for the frame in flight (before releasing objects).
  void finish();

  const Rgba8Image &image() const
  {
    return m_image;
  }
  const LinearColorImage &linearColor() const
  {
    return m_linearColor;
  }
  // The channel image() shows (it follows setChannel with the next frame).
  Channel imageChannel() const
  {
    return m_imageChannel;
  }
  const FrameIds &ids() const
  {
    return m_ids;
  }
  const FrameStatus &status() const
  {
    return m_status;
  }
  uint32_t width() const
  {
    return m_width;
  }
  uint32_t height() const
  {
    return m_height;
  }

 private:
  void start();
  void copyOut();
  void copyStatus();
  void copyImage();
  void copyIds();

  ANARIDevice m_device;
  ANARIFrame m_frame;
  ANARIRenderer m_renderer;
  uint32_t m_width{0}, m_height{0};
  Channel m_channel{Channel::Color};
  Channel m_imageChannel{Channel::Color};
  uint32_t m_sampleLimit{0};
  bool m_inFlight{false};
  bool m_discards{true};
  void (*m_beforeRender)(void *){nullptr};
  void *m_beforeRenderUser{nullptr};
  bool m_stale{true};     // the frame in flight predates a change
  bool m_idsWanted{true}; // the next finished frame's ids are read
  Rgba8Image m_image;
  LinearColorImage m_linearColor;
  FrameIds m_ids;
  FrameStatus m_status;
};

} // namespace prism::viewer
