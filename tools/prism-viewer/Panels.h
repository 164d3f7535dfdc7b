// The ImGui panels: scene and renderer choice, channel view, camera (field
// of view, depth of field), screenshot, the parameter panels generated from
// introspection (ParameterModel.*), the selection and the status bar.
#pragma once

#include "TransferFunctionEdit.h"
#include "ViewerSession.h"

#include <string>

namespace prism::viewer {

// What the panels keep between frames.
struct PanelState
{
  std::string sceneText;
  std::string screenshotPath{"prism-viewer.png"};
  std::string message; // the last error or note, shown until replaced
  bool messageIsError{false};
  bool startFolded{false}; // the main panel starts collapsed
  bool openAll{false};     // every section starts open (--panels open)
  TransferFunctionEdit transferFunction;
  int fileCamera{0}; // the glTF camera to view through
};

// Draws every panel; edits go to the session at once.
void drawPanels(ViewerSession &session, PanelState &state);

// One parameter's widget; true when the user changed it (and it was set).
bool drawParameter(ParameterSet &set, const ParameterWidget &widget);

} // namespace prism::viewer
