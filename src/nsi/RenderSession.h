// One render started by NSIRenderControl "start": ANARI objects built from a
// ResolvedScene on a device of the chosen library, frames accumulated on a
// thread up to each screen's oversampling, then every output written.
#pragma once

#include "GeometryBuilder.h"
#include "ResolvedScene.h"

#include <anari/anari.h>

#include <atomic>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace prism::nsi {

class RenderSession
{
 public:
  // Called on the render thread when it ends, with an NSIStoppingStatus.
  using Stopped = std::function<void(int status)>;

  RenderSession(ReportFunction report, Stopped stopped);
  ~RenderSession();
  RenderSession(const RenderSession &) = delete;
  RenderSession &operator=(const RenderSession &) = delete;

  // Loads `library`, builds the scene and starts the thread; false (with
  // the reason reported) when no device could be had.
  bool start(const std::string &library, const ResolvedScene &scene);
  void wait();
  void stop();
  // The stopped callback is not called for this render (it is replaced).
  void silenceStopped()
  {
    m_silent = true;
  }
  bool running() const
  {
    return m_running;
  }

 private:
  void renderAll();
  void release();

  ReportFunction m_report;
  Stopped m_stopped;
  ANARILibrary m_library{nullptr};
  ANARIDevice m_device{nullptr};
  ANARIWorld m_world{nullptr};
  ANARIRenderer m_renderer{nullptr};
  std::vector<CameraItem> m_cameras;
  bool m_hasMotion{false};
  std::atomic<bool> m_stopRequested{false};
  std::atomic<bool> m_running{false}; // from start until the thread ends
  std::atomic<bool> m_silent{false};
  std::thread m_thread;
  std::mutex m_joinMutex; // one thread joins (and releases) at a time
};

} // namespace prism::nsi
