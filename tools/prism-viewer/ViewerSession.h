// Everything the viewer drives on the device, without any UI: the library
// and device, the loaded scene and its lighting, the renderer, the camera
// (OrbitCamera's pose), the frame pipeline and the parameter sets the
// panels edit. The window (main.cpp, Panels.*) and the script both act
// through this, so the tests exercise what the UI does.
#pragma once

#include "DeviceSession.h"
#include "FramePipeline.h"
#include "OrbitCamera.h"
#include "ParameterModel.h"
#include "SceneLoader.h"
#include "TransferFunctionEdit.h"
#include "ViewerOptions.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace prism::viewer {

// One light the viewer knows the subtype of, and its parameters.
struct ViewerLight
{
  std::string label;
  ParameterSet parameters;
};

// The picked surface's material and geometry, as the scene lists them.
struct SelectedSurface
{
  std::string label; // "surface 3: triangle geometry, matte material"
  ParameterSet material;
  ParameterSet geometry;
};

class ViewerSession
{
 public:
  explicit ViewerSession(const ViewerOptions &options);
  ~ViewerSession();
  ViewerSession(const ViewerSession &) = delete;
  ViewerSession &operator=(const ViewerSession &) = delete;

  // Opens the library and device and makes the renderer, camera and frame
  // (over an empty world); the error says why not.
  std::string open();
  // Replaces the scene; on failure the previous one stays and the error
  // names the file and the problem.
  std::string loadScene(const std::string &source);
  const std::string &sceneName() const
  {
    return m_sceneName;
  }
  // Whether the scene is a glTF file (whose cameras viewFileCamera picks).
  bool hasFileCameras() const;
  // Reloads the file viewing through its camera `index`; on failure (no
  // such camera) the scene stays and the error says why.
  std::string viewFileCamera(int index);
  int fileCamera() const
  {
    return m_loadOptions.gltfCamera;
  }
  // Whether the scene is a volume whose transfer function can be edited
  // (volume files, demo:volume).
  bool hasVolume() const;
  // Rebuilds the volume with `edit`'s transfer function, keeping the view;
  // the error says why not.
  std::string restyleVolume(const TransferFunctionEdit &edit);

  // Render-target size in pixels (the window's, times the scale).
  void setViewport(uint32_t width, uint32_t height, float scale);
  // Never waits; true when a new image is ready.
  bool update();

  OrbitCamera &camera()
  {
    return m_camera;
  }
  // Copies the camera's pose to the device and restarts accumulation.
  void cameraChanged();
  // Frames the scene again (the file's camera, else its bounds).
  void frameScene();

  std::vector<std::string> rendererSubtypes() const;
  std::string setRenderer(const std::string &subtype);
  ParameterSet &rendererParameters()
  {
    return m_rendererParameters;
  }
  ParameterSet &cameraParameters()
  {
    return m_cameraParameters;
  }
  std::vector<ViewerLight> &lights()
  {
    return m_lights;
  }
  // The picked surface's parameter sets; nothing when nothing is picked or
  // the scene does not list the picked surface (NSI streams, surfaces
  // without an id).
  std::optional<SelectedSurface> &selectedSurface()
  {
    return m_selectedSurface;
  }
  // `set renderer|camera|light N PARAM VALUE...` and `set material|geometry
  // 0 PARAM VALUE...` (the picked surface's): through the panels' sets; the
  // error names the problem.
  std::string setParameter(const std::string &target,
      int index,
      const std::string &name,
      const std::vector<std::string> &words);
  // After a panel edited a set: restart accumulation.
  void parametersChanged();

  // The object under pixel (x, y) of the shown image (from its top-left),
  // which becomes the selection (highlighted).
  std::optional<Pick> pick(int x, int y);
  const std::optional<Pick> &selection() const
  {
    return m_selection;
  }
  // Focuses depth of field on what is under (x, y).
  bool focusAt(int x, int y);

  FramePipeline &pipeline()
  {
    return *m_pipeline;
  }
  // The shown image with the selection tinted.
  Rgba8Image shownImage() const;
  // PNG or EXR (by extension) of the shown channel, unhighlighted.
  std::string screenshot(const std::string &path) const;

  // Under mpirun: every top-level change (load, frame, renderer, viewport,
  // pose, parameter values, file camera, render) goes to `mirror` as one
  // line, before it is made here, so the other processes make it in the
  // same order (their collective calls match). Frames in flight are no
  // longer discarded.
  void mirrorTo(std::function<void(const std::string &)> mirror);
  // Makes one mirrored change (the other processes); false on "quit".
  bool applyMirrored(const std::string &line);

  ANARIDevice device() const
  {
    return m_session.device();
  }
  int deviceErrors() const
  {
    return m_session.errors();
  }

 private:
  std::string load(const scene_io::SceneSource &source,
      const scene_io::LoadOptions &options,
      bool reframe);
  void releaseScene();
  void lightScene();
  void describeLights();
  void selectSurface();
  // Replaces the camera object when the pose needs another subtype.
  void useCameraSubtype(const std::string &subtype);
  scenes::Bounds worldBounds() const;
  // Sends `line` when not inside another mirrored change; the scope ends
  // the change.
  class MirrorScope
  {
   public:
    explicit MirrorScope(int &depth) : m_depth(depth)
    {
      ++m_depth;
    }
    ~MirrorScope()
    {
      --m_depth;
    }
    MirrorScope(const MirrorScope &) = delete;
    MirrorScope &operator=(const MirrorScope &) = delete;

   private:
    int &m_depth;
  };
  MirrorScope mirrored(const std::string &line);
  // Each parameter set's values go to the mirror as `set` lines.
  void observeParameters();
  struct MirrorTarget
  {
    ViewerSession *session;
    std::string prefix; // "set renderer 0 "
  };

  const ViewerOptions &m_options;
  tools::DeviceSession m_session;
  std::string m_rendererSubtype;
  ANARIRenderer m_renderer{nullptr};
  ANARICamera m_cameraObject{nullptr};
  ANARIFrame m_frame{nullptr};
  ANARIWorld m_emptyWorld{nullptr};
  std::unique_ptr<FramePipeline> m_pipeline;
  scenes::Scene m_scene;
  std::string m_sceneName;
  scene_io::SceneSource m_source;
  scene_io::LoadOptions m_loadOptions;
  OrbitCamera m_camera;
  ParameterSet m_rendererParameters;
  ParameterSet m_cameraParameters;
  std::vector<ViewerLight> m_lights;
  ANARILight m_environment{nullptr}; // the one the viewer added, if any
  std::optional<Pick> m_selection;
  std::optional<SelectedSurface> m_selectedSurface;
  uint32_t m_width{0}, m_height{0};
  float m_scale{1.f};
  std::function<void(const std::string &)> m_mirror;
  int m_mirrorDepth{0};
  std::vector<std::unique_ptr<MirrorTarget>> m_mirrorTargets;
};

// The camera parameters the viewer's pose sets on every move (position,
// direction, up, aspect, fovy or height, apertureRadius, focusDistance).
bool isPoseParameter(const std::string &name);

// The mirror's lines for a camera pose and a viewport.
std::string poseLine(const CameraPose &pose);
std::string viewportLine(uint32_t width, uint32_t height, float scale);

// Prints "prism-viewer: <line>" on stderr (device messages too).
void printMessage(const std::string &line);

} // namespace prism::viewer
