#include "Context.h"

#include <embree3/rtcore.h>

namespace prism::rt {
namespace {

void onEmbreeError(void *userPtr, RTCError code, const char *message)
{
  auto *context = (const Context *)userPtr;
  context->reportError(std::string("embree error ") + std::to_string(int(code))
                       + ": " + (message ? message : ""));
}

bool onEmbreeMemory(void *userPtr, ssize_t bytes, bool /*post*/)
{
  ((Context *)userPtr)->countBytes(int64_t(bytes));
  return true; // never refuse: limits are the system's
}

} // namespace

void Context::countBytes(int64_t change)
{
  const int64_t now =
      m_bytes.fetch_add(change, std::memory_order_relaxed) + change;
  int64_t peak = m_peakBytes.load(std::memory_order_relaxed);
  while (now > peak
         && !m_peakBytes.compare_exchange_weak(
             peak, now, std::memory_order_relaxed)) {
  }
}

bool Context::setBuildQuality(const std::string &name)
{
  if (name == "low")
    setBuildQuality(BuildQuality::Low);
  else if (name == "medium")
    setBuildQuality(BuildQuality::Medium);
  else if (name == "high")
    setBuildQuality(BuildQuality::High);
  else
    return false;
  return true;
}

Context::Context(ErrorSink onError) : m_onError(std::move(onError))
{
  // Embree uses the application's TBB scheduler, so its builds join the
  // same worker pool as rendering; no extra threads.
  m_device = rtcNewDevice(nullptr);
  if (!m_device) {
    reportError("embree could not create a device; nothing will render");
    return;
  }
  rtcSetDeviceErrorFunction(m_device, onEmbreeError, this);
  rtcSetDeviceMemoryMonitorFunction(m_device, onEmbreeMemory, this);
}

Context::~Context()
{
  if (m_device)
    rtcReleaseDevice(m_device);
}

} // namespace prism::rt
