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

} // namespace

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
}

Context::~Context()
{
  if (m_device)
    rtcReleaseDevice(m_device);
}

} // namespace prism::rt
