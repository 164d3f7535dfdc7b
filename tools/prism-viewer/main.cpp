// prism-viewer: an interactive viewer for any ANARI library. See --help and
// docs/viewer.md. This parses options, opens the window and the session,
// and runs the UI loop: input, the frame pipeline's poll, the script's
// next commands, the panels.
#include "CameraInput.h"
#include "MpiProcesses.h"
#include "Panels.h"
#include "ScriptRunner.h"
#include "ViewerOptions.h"
#include "ViewerSession.h"
#include "ViewerWindow.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <optional>
#include <thread>
#include <utility>

namespace prism::viewer {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;
// The loop runs at most this often: the renderer keeps the cores.
constexpr auto kFramePeriod = std::chrono::milliseconds(16);
// After the camera stops, frames render at the interaction scale this long.
constexpr auto kStillAfter = std::chrono::milliseconds(250);
// After input or a change, the window is drawn this many frames (ImGui's
// hover and focus settle over a frame or two); otherwise only when a new
// image arrives.
constexpr int kDrawsAfterActivity = 3;

int fail(const std::string &message, int code = kExitFailure)
{
  printMessage("error: " + message);
  return code;
}

// Keeps the window open with `message` until it is closed: a library that
// failed to load leaves nothing else to show.
int showUntilClosed(ViewerWindow &window, const std::string &message)
{
  while (!window.shouldClose()) {
    window.beginFrame();
    ImGui::Begin("prism-viewer");
    ImGui::TextColored(ImVec4(1.f, 0.4f, 0.4f, 1.f), "%s", message.c_str());
    ImGui::End();
    window.endFrame(true);
    std::this_thread::sleep_for(kFramePeriod);
  }
  return kExitFailure;
}

class ViewerLoop
{
 public:
  ViewerLoop(const ViewerOptions &options,
      ViewerWindow &window,
      ViewerSession &session,
      std::unique_ptr<ScriptRunner> script)
      : m_options(options),
        m_window(window),
        m_session(session),
        m_script(std::move(script))
  {
    if (!options.frameTimes.empty())
      m_frameTimes.open(options.frameTimes);
    m_state.sceneText = options.scene;
    m_state.openAll = options.panelsOpen;
    if (m_script) {
      m_script->setWindowCapture(
          [this](const std::string &path) { m_capturePath = path; });
      // Scripts look at the image: the panel starts folded.
      m_state.startFolded = true;
    }
  }

  void setMessage(const std::string &message, bool error)
  {
    m_state.message = message;
    m_state.messageIsError = error;
  }

  int run()
  {
    Clock::time_point previous = Clock::now();
    while (!m_window.shouldClose()) {
      const Clock::time_point start = Clock::now();
      const double interval =
          std::chrono::duration<double, std::milli>(start - previous).count();
      previous = start;
      const std::optional<int> status = frame();
      if (m_frameTimes.is_open())
        // The loop's interval, and how long this frame's drawing took
        // (0: not drawn). Whole lines, even if the run is killed.
        m_frameTimes << interval << ' ' << m_drawMs << std::endl;
      if (status)
        return *status;
      std::this_thread::sleep_until(start + kFramePeriod);
    }
    return 0;
  }

 private:
  // One UI frame; an exit status when the script ends the run.
  std::optional<int> frame()
  {
    m_window.beginFrame();
    if (m_window.activity())
      m_drawsLeft = kDrawsAfterActivity;
    for (const std::string &path : m_window.takeDroppedFiles()) {
      const std::string error = m_session.loadScene(path);
      setMessage(error.empty() ? "opened " + path : error, !error.empty());
      if (error.empty())
        m_state.sceneText = path;
    }
    bool refresh = false;
    if (!m_script) {
      const InputOutcome input = handleCameraInput(m_session);
      if (input.moved)
        m_lastMove = Clock::now();
      refresh = input.picked;
    }
    const bool moving = Clock::now() - m_lastMove < kStillAfter;
    uint32_t w = 0, h = 0;
    m_window.size(w, h);
    m_session.setViewport(w, h, moving ? m_options.interactionScale : 1.f);
    refresh |= m_session.update();
    std::optional<int> status;
    if (m_script) {
      const std::optional<Pick> before = m_session.selection();
      const ScriptState state = m_script->step(m_session);
      refresh |= m_session.selection().has_value() != before.has_value();
      if (state == ScriptState::Failed)
        status = fail(m_script->error());
      else if (state == ScriptState::Finished)
        status = 0;
    }
    if (refresh) {
      m_window.showImage(m_session.shownImage());
      m_drawsLeft = std::max(m_drawsLeft, 1);
    }
    if (m_state.message != m_shownMessage) {
      m_shownMessage = m_state.message;
      m_drawsLeft = std::max(m_drawsLeft, 1);
    }
    drawPanels(m_session, m_state);
    const bool draw = m_drawsLeft > 0;
    m_drawsLeft -= draw ? 1 : 0;
    const Clock::time_point drawStart = Clock::now();
    const std::string captureError =
        m_window.endFrame(draw, std::exchange(m_capturePath, {}));
    m_drawMs = draw ? std::chrono::duration<double, std::milli>(
                   Clock::now() - drawStart)
                          .count()
                    : 0.0;
    if (!captureError.empty() && !status)
      status = fail(captureError);
    return status;
  }

  const ViewerOptions &m_options;
  ViewerWindow &m_window;
  ViewerSession &m_session;
  std::unique_ptr<ScriptRunner> m_script;
  PanelState m_state;
  Clock::time_point m_lastMove{};
  std::ofstream m_frameTimes;
  std::string m_capturePath; // window-screenshot's, for this frame
  int m_drawsLeft{kDrawsAfterActivity};
  std::string m_shownMessage;
  double m_drawMs{0.0}; // the last frame's drawing, for --frame-times
};

// The processes of an mpirun but rank 0: no window; they make rank 0's
// changes on their own device until it quits.
int followRankZero(const ViewerOptions &options, const MpiProcesses &mpi)
{
  if (mpi.receive() != "start")
    return 0; // rank 0 could not open its window
  ViewerSession session(options);
  if (const std::string error = session.open(); !error.empty())
    return fail("process " + std::to_string(mpi.rank()) + ": " + error);
  while (session.applyMirrored(mpi.receive())) {
  }
  return 0;
}

// Tells the other processes to stop when rank 0's run ends (before its
// session, whose device release is collective, is destroyed).
struct QuitFollowers
{
  const MpiProcesses &mpi;
  ~QuitFollowers()
  {
    mpi.send("quit");
  }
};

int run(int argc, char **argv)
{
  const ParsedOptions parsed =
      parseViewerOptions(argc, argv, std::getenv("ANARI_LIBRARY"));
  if (!parsed.ok()) {
    printMessage("error: " + parsed.error);
    printMessage("try 'prism-viewer --help'");
    return kExitUsage;
  }
  const ViewerOptions &options = parsed.options;
  if (options.help) {
    std::fputs(viewerHelp().c_str(), stdout);
    return 0;
  }
  std::unique_ptr<ScriptRunner> script;
  if (!options.script.empty()) {
    ParsedScript commands = readScript(options.script);
    if (!commands.ok())
      return fail(commands.error, kExitUsage);
    script = std::make_unique<ScriptRunner>(std::move(commands));
  }
  const MpiProcesses mpi;
  if (mpi.rank() > 0)
    return followRankZero(options, mpi);
  ViewerWindow window;
  if (const std::string error =
          window.open(options.width, options.height, "prism-viewer");
      !error.empty()) {
    mpi.send("quit");
    return fail(error);
  }
  mpi.send("start");
  ViewerSession session(options);
  const QuitFollowers quitFollowers{mpi};
  if (const std::string error = session.open(); !error.empty()) {
    printMessage("error: " + error);
    return script ? kExitFailure : showUntilClosed(window, error);
  }
  if (mpi.size() > 1)
    session.mirrorTo([&mpi](const std::string &line) { mpi.send(line); });
  uint32_t w = 0, h = 0;
  window.size(w, h);
  session.setViewport(w, h, 1.f);
  ViewerLoop loop(options, window, session, std::move(script));
  if (!options.scene.empty()) {
    const std::string error = session.loadScene(options.scene);
    if (!error.empty()) {
      printMessage("error: " + error);
      if (!options.script.empty())
        return kExitFailure;
      loop.setMessage(error, true);
    }
  }
  return loop.run();
}

} // namespace
} // namespace prism::viewer

int main(int argc, char **argv)
{
  try {
    return prism::viewer::run(argc, argv);
  } catch (const std::bad_alloc &) {
    prism::viewer::printMessage("error: out of memory");
  } catch (const std::exception &e) {
    prism::viewer::printMessage(std::string("error: ") + e.what());
  }
  return 1;
}
