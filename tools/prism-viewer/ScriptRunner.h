// Carries out a parsed script on a session, one command at a time across UI
// frames (wait-samples waits for frames without blocking the window).
// `pick` prints the ids on stdout: "pick X Y: objectId A instanceId B
// primitiveId C" (~0u printed as "none").
#pragma once

#include "ViewerScript.h"
#include "ViewerSession.h"

#include <functional>
#include <string>

namespace prism::viewer {

enum class ScriptState { Running, Finished, Failed };

class ScriptRunner
{
 public:
  explicit ScriptRunner(ParsedScript script) : m_script(std::move(script)) {}

  // Saves the whole window to a file once this frame is drawn (the window
  // sets it; without one, window-screenshot is an error).
  using WindowCapture = std::function<void(const std::string &path)>;
  void setWindowCapture(WindowCapture capture)
  {
    m_capture = std::move(capture);
  }

  // Runs what can run now; called once per UI frame after the session's
  // update.
  ScriptState step(ViewerSession &session);
  // Why the script failed, naming the line.
  const std::string &error() const
  {
    return m_error;
  }

 private:
  // Carries out one command: true when it is done.
  bool run(const ScriptCommand &command, ViewerSession &session);

  ParsedScript m_script;
  size_t m_next{0};
  std::string m_error;
  bool m_quit{false};
  WindowCapture m_capture;
};

// The line `pick` prints.
std::string pickLine(int x, int y, const Pick &pick);

} // namespace prism::viewer
