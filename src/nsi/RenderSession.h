// One render started by NSIRenderControl "start": ANARI objects built from a
// ResolvedScene on a device of the chosen library, frames accumulated on a
// thread up to each screen's oversampling, then every output written. The
// device and its objects outlive the thread, so "synchronize" renders again
// after updating only the objects an edit touched.
#pragma once

#include "AnariWorldBuilder.h"
#include "GeometryBuilder.h"
#include "ResolvedScene.h"

#include <anari/anari.h>

#include <atomic>
#include <functional>
#include <memory>
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
  // After stop(): updates the ANARI objects to `scene` and renders again,
  // reporting to `stopped` when done. What the update did is in counts().
  void synchronize(const ResolvedScene &scene, Stopped stopped);
  const AnariUpdateCounts &counts() const
  {
    return m_builder->lastUpdate();
  }
  bool hasDevice() const
  {
    return m_device != nullptr;
  }
  void wait();
  // Stops the thread; the device and its objects stay for synchronize.
  void stop();
  // Stops and releases the device (reports made meanwhile still arrive).
  void close();
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
  void apply(const ResolvedScene &scene);
  void launch();

  ReportFunction m_report;
  Stopped m_stopped;
  ANARILibrary m_library{nullptr};
  ANARIDevice m_device{nullptr};
  std::unique_ptr<AnariWorldBuilder> m_builder;
  AnariWorld m_world;
  GlobalOptions m_options; // as the renderer has them
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
