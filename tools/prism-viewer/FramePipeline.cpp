#include "FramePipeline.h"

#include <algorithm>
#include <cstring>

namespace prism::viewer {
namespace {

ANARIDataType mappedType(Channel channel)
{
  switch (channel) {
  case Channel::Color:
    // Linear floats, so an EXR screenshot keeps what 8 bits would clip;
    // the window shows them sRGB-encoded (ChannelView).
    return ANARI_FLOAT32_VEC4;
  case Channel::Depth:
    return ANARI_FLOAT32;
  case Channel::Normal:
  case Channel::Albedo:
    return ANARI_FLOAT32_VEC3;
  default:
    return ANARI_UINT32;
  }
}

template <typename T>
std::vector<T> copyChannel(ANARIDevice device,
    ANARIFrame frame,
    const char *name,
    ANARIDataType expected,
    uint32_t width,
    uint32_t height)
{
  uint32_t w = 0, h = 0;
  ANARIDataType type = ANARI_UNKNOWN;
  const void *pixels = anariMapFrame(device, frame, name, &w, &h, &type);
  std::vector<T> out;
  if (pixels && type == expected && w == width && h == height)
    out.assign((const T *)pixels, (const T *)pixels + size_t(w) * h);
  if (pixels)
    anariUnmapFrame(device, frame, name);
  return out;
}

} // namespace

FramePipeline::FramePipeline(
    ANARIDevice device, ANARIFrame frame, ANARIRenderer renderer)
    : m_device(device), m_frame(frame), m_renderer(renderer)
{
  for (Channel c : kAllChannels) {
    const ANARIDataType type = mappedType(c);
    anariSetParameter(
        device, frame, channelParameter(c).c_str(), ANARI_DATA_TYPE, &type);
  }
  const int32_t on = 1;
  anariSetParameter(device, frame, "accumulation", ANARI_BOOL, &on);
}

FramePipeline::~FramePipeline()
{
  finish();
}

void FramePipeline::setSize(uint32_t width, uint32_t height)
{
  if (width == 0 || height == 0 || (width == m_width && height == m_height))
    return;
  m_width = width;
  m_height = height;
  const uint32_t size[2] = {width, height};
  anariSetParameter(m_device, m_frame, "size", ANARI_UINT32_VEC2, size);
  anariCommitParameters(m_device, m_frame);
  restart();
}

void FramePipeline::setChannel(Channel channel)
{
  if (channel == m_channel)
    return;
  m_channel = channel;
  // The shown image changes now, from the frame as it is.
  if (!m_inFlight && m_status.finished > 0)
    copyImage();
}

void FramePipeline::restart()
{
  m_stale = true;
  m_idsWanted = true;
  m_status.samples = 0;
  if (m_inFlight && m_discards)
    anariDiscardFrame(m_device, m_frame);
}

void FramePipeline::start()
{
  if (m_beforeRender)
    m_beforeRender(m_beforeRenderUser);
  anariRenderFrame(m_device, m_frame);
  m_inFlight = true;
  m_stale = false;
}

bool FramePipeline::poll()
{
  if (m_width == 0 || m_height == 0)
    return false;
  bool changed = false;
  if (m_inFlight) {
    if (!anariFrameReady(m_device, m_frame, ANARI_NO_WAIT))
      return false;
    m_inFlight = false;
    if (!m_stale) {
      copyOut();
      changed = true;
    }
  }
  const bool limited =
      !m_stale && m_sampleLimit > 0 && m_status.samples >= m_sampleLimit;
  if (!limited)
    start();
  return changed;
}

void FramePipeline::finish()
{
  if (m_inFlight)
    anariFrameReady(m_device, m_frame, ANARI_WAIT);
  m_inFlight = false;
}

void FramePipeline::copyOut()
{
  copyStatus();
  if (m_idsWanted)
    copyIds();
  copyImage();
}

void FramePipeline::copyStatus()
{
  ++m_status.finished;
  // The device's count where it is larger (several samples a frame), else
  // the frames finished since the change (a device reporting no count, or
  // a count that does not move).
  uint32_t samples = 0;
  anariGetProperty(m_device,
      m_frame,
      "numSamples",
      ANARI_UINT32,
      &samples,
      sizeof(samples),
      ANARI_NO_WAIT);
  m_status.samples = std::max(samples, m_status.samples + 1);
  float value = 0.f;
  if (anariGetProperty(m_device,
          m_frame,
          "duration",
          ANARI_FLOAT32,
          &value,
          sizeof(value),
          ANARI_NO_WAIT))
    m_status.frameSeconds = value;
  m_status.convergence = anariGetProperty(m_device,
                             m_frame,
                             "refinementProgress",
                             ANARI_FLOAT32,
                             &value,
                             sizeof(value),
                             ANARI_NO_WAIT)
                             ? value
                             : -1.f;
  // Rays per second: the renderer's running count across the frame, over
  // the frame's duration.
  uint64_t rays = 0;
  const bool counted = anariGetProperty(m_device,
      m_renderer,
      "raysTraced",
      ANARI_UINT64,
      &rays,
      sizeof(rays),
      ANARI_NO_WAIT);
  m_status.raysPerSecond =
      counted && m_status.countsRays && rays >= m_status.raysTraced
              && m_status.frameSeconds > 0.f
          ? double(rays - m_status.raysTraced) / m_status.frameSeconds
          : -1.0;
  m_status.countsRays = counted;
  m_status.raysTraced = rays;
}

void FramePipeline::copyImage()
{
  const std::string name = channelParameter(m_channel);
  uint32_t w = 0, h = 0;
  ANARIDataType type = ANARI_UNKNOWN;
  const void *pixels =
      anariMapFrame(m_device, m_frame, name.c_str(), &w, &h, &type);
  Rgba8Image image = channelToRgba8(m_channel, pixels, type, w, h);
  m_linearColor = {};
  if (pixels && m_channel == Channel::Color && type == ANARI_FLOAT32_VEC4) {
    m_linearColor.width = w;
    m_linearColor.height = h;
    m_linearColor.pixels.assign(
        (const float *)pixels, (const float *)pixels + 4 * size_t(w) * h);
  }
  if (pixels)
    anariUnmapFrame(m_device, m_frame, name.c_str());
  // A channel the device does not give shows (and saves) nothing rather
  // than the previous channel's image.
  m_image = std::move(image);
  m_imageChannel = m_channel;
}

void FramePipeline::copyIds()
{
  m_idsWanted = false;
  m_ids.width = m_width;
  m_ids.height = m_height;
  m_ids.objectId = copyChannel<uint32_t>(
      m_device, m_frame, "channel.objectId", ANARI_UINT32, m_width, m_height);
  m_ids.instanceId = copyChannel<uint32_t>(
      m_device, m_frame, "channel.instanceId", ANARI_UINT32, m_width, m_height);
  m_ids.primitiveId = copyChannel<uint32_t>(m_device,
      m_frame,
      "channel.primitiveId",
      ANARI_UINT32,
      m_width,
      m_height);
  m_ids.depth = copyChannel<float>(
      m_device, m_frame, "channel.depth", ANARI_FLOAT32, m_width, m_height);
}

} // namespace prism::viewer
