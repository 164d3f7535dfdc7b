// One render started by NSIRenderControl "start": ANARI objects built from a
// ResolvedScene on a device of the chosen library, frames accumulated on a
// thread up to each screen's oversampling, then every output written (after
// every frame, when progressive). A suspended render issues no frames until
// it is resumed. The
// device and its objects outlive the thread, so "synchronize" renders again
// after updating only the objects an edit touched.
#pragma once

#include "AnariWorldBuilder.h"
#include "GeometryBuilder.h"
#include "OutputChannels.h"
#include "ResolvedScene.h"

#include <anari/anari.h>

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <set>
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

  // Called on the render thread after each frame, with the frames
  // rendered since the session began.
  using FrameDone = std::function<void(uint64_t frames)>;

  // Loads `library`, builds the scene and starts the thread; false (with
  // the reason reported) when no device could be had. `progressive`: the
  // outputs are written after each accumulated frame, not once at the end.
  bool start(const std::string &library,
      const ResolvedScene &scene,
      bool progressive = false);
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
  // What wait() did.
  enum class Waited {
    kEnded,          // the render ended (or none was running)
    kSuspended,      // the render is suspended: waiting would never end
    kOnRenderThread, // called from the render's own callback
  };
  // Joins the render, unless it is or becomes suspended or the caller is
  // the render thread: those return at once instead of waiting forever.
  Waited wait();
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
  // No frame starts while suspended (the one under way finishes); stop()
  // still ends the render.
  void suspend();
  void resume();
  uint64_t framesRendered() const
  {
    return m_frames;
  }
  void setFrameDone(FrameDone frameDone)
  {
    m_frameDone = std::move(frameDone);
  }
  // Called on the render thread each time it stops before a frame because
  // the render is suspended, with the frames rendered so far: from then
  // until resume() or stop() no frame starts (so a caller can tell a
  // suspended render from a slow one without waiting on a clock).
  void setParked(FrameDone parked)
  {
    m_parked = std::move(parked);
  }

 private:
  void renderAll();
  // Blocks while suspended; false once a stop is requested.
  bool waitUntilResumed();
  // Every output file of `item` from the frame's channels; `warn`: report
  // drivers without a file.
  void writeOutputs(const CameraItem &item,
      const Framing &framing,
      ANARIFrame frame,
      const std::vector<const FrameChannel *> &channels,
      bool warn);
  void release();
  void apply(const ResolvedScene &scene);
  void launch();
  // Joins the thread of render `generation` (under m_joinMutex); nothing
  // when another has been launched since.
  void join(uint64_t generation);

  ReportFunction m_report;
  std::set<std::string> m_warnedOutputs; // OutputFiles' warnings said
  Stopped m_stopped;
  ANARILibrary m_library{nullptr};
  ANARIDevice m_device{nullptr};
  std::unique_ptr<AnariWorldBuilder> m_builder;
  AnariWorld m_world;
  GlobalOptions m_options; // as the renderer has them
  ANARIRenderer m_renderer{nullptr};
  std::vector<CameraItem> m_cameras;
  bool m_hasMotion{false};
  bool m_cameraMotion{false}; // the device takes a camera's motion.transform
  std::atomic<bool> m_stopRequested{false};
  std::atomic<bool> m_running{false}; // from start until the thread ends
  std::atomic<bool> m_silent{false};
  bool m_progressive{false};
  std::atomic<uint64_t> m_frames{0};
  FrameDone m_frameDone;
  FrameDone m_parked;
  std::mutex m_suspendMutex;
  std::condition_variable m_resumed;
  // Suspended, or the thread ended: what wait() waits for.
  std::condition_variable m_suspendedOrEnded;
  bool m_suspended{false}; // guarded by m_suspendMutex
  // Launches so far: written under both mutexes, read under either.
  uint64_t m_generation{0};
  std::thread m_thread;
  std::mutex m_joinMutex; // one thread joins (and releases) at a time
};

} // namespace prism::nsi
