// Mouse and keys to camera moves and picks, from ImGui's input state (1.86:
// keys by GLFW key code) when
// ImGui's own windows do not want the input: left drag orbits, right drag
// or shift + left drag pans, the wheel zooms, a click picks, a double click
// focuses depth of field, W A S D Q E fly, F frames the scene.
#pragma once

#include "ViewerSession.h"

namespace prism::viewer {

struct InputOutcome
{
  bool moved{false};  // the camera moved this frame
  bool picked{false}; // a click changed the selection
};

InputOutcome handleCameraInput(ViewerSession &session);

} // namespace prism::viewer
