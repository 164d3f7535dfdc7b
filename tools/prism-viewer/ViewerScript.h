// `--script FILE`: UI actions one per line, for tests and demos. Parsing
// only; ScriptRunner carries the commands out on a session. Blank lines and
// lines starting with '#' are skipped; anything else that is not a command
// below, or has the wrong arguments, is an error naming the line.
//
//   orbit DEGREES                        about the scene's centre, around up
//   set renderer|camera|light N PARAM VALUE...
//   pick X Y                             pixel from the top-left corner
//   channel NAME                         color, depth, normal, albedo,
//                                        objectId, primitiveId, instanceId
//   wait-samples N
//   screenshot PATH                      PNG (or .exr) of the rendered image
//   window-screenshot PATH               PNG of the whole window, panels too
//   quit
#pragma once

#include <string>
#include <vector>

namespace prism::viewer {

enum class ScriptAction {
  Orbit,
  Set,
  Pick,
  Channel,
  WaitSamples,
  Screenshot,
  WindowScreenshot,
  Quit
};

struct ScriptCommand
{
  ScriptAction action{ScriptAction::Quit};
  int line{0};                     // 1-based, in the file
  std::string text;                // the line as written
  float degrees{0.f};              // orbit
  std::string target;              // set: renderer, camera or light
  int index{0};                    // set: which one (renderer/camera: 0)
  std::string parameter;           // set
  std::vector<std::string> values; // set: the value's words
  int x{0}, y{0};                  // pick
  std::string name;                // channel NAME, screenshot PATH
  unsigned samples{0};             // wait-samples
};

struct ParsedScript
{
  std::vector<ScriptCommand> commands;
  std::string error; // empty on success: "line 3: unknown command 'spin'"

  bool ok() const
  {
    return error.empty();
  }
};

ParsedScript parseScript(const std::string &text);
// Reads and parses `path`; the error names the file.
ParsedScript readScript(const std::string &path);

} // namespace prism::viewer
