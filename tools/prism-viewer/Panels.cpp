#include "Panels.h"

#include "ColorMaps.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>

namespace prism::viewer {
namespace {

constexpr float kStatusBarHeight = 24.f;

// Every section starts open with --panels open (demos, tests), else folded.
bool g_openAll = false;
ImGuiTreeNodeFlags openFlags()
{
  return g_openAll ? ImGuiTreeNodeFlags_DefaultOpen : 0;
}

bool drawNumbers(ParameterSet &set, const ParameterWidget &w, ParameterValue &v)
{
  float f[4] = {};
  int i[4] = {};
  for (int c = 0; c < w.components; ++c) {
    f[c] = float(v.numbers[c]);
    i[c] = int(v.numbers[c]);
  }
  bool changed = false;
  const char *label = w.name.c_str();
  if (w.kind == WidgetKind::Color) {
    changed = w.components == 4
                  ? ImGui::ColorEdit4(label, f, ImGuiColorEditFlags_Float)
                  : ImGui::ColorEdit3(label, f, ImGuiColorEditFlags_Float);
  } else if (w.kind == WidgetKind::Float) {
    const bool ranged = w.minimum && w.maximum && w.components == 1;
    changed = ranged ? ImGui::SliderFloat(
                  label, f, float(*w.minimum), float(*w.maximum))
                     : ImGui::DragScalarN(
                         label, ImGuiDataType_Float, f, w.components, 0.01f);
  } else if (w.kind == WidgetKind::Integer) {
    changed = ImGui::InputScalarN(label, ImGuiDataType_S32, i, w.components);
  } else if (w.kind == WidgetKind::Toggle) {
    bool b = v.numbers[0] != 0.0;
    changed = ImGui::Checkbox(label, &b);
    i[0] = b ? 1 : 0;
  }
  if (!changed)
    return false;
  for (int c = 0; c < w.components; ++c) {
    double n = w.kind == WidgetKind::Float || w.kind == WidgetKind::Color
                   ? double(f[c])
                   : double(i[c]);
    if (w.minimum)
      n = std::max(n, *w.minimum);
    if (w.maximum)
      n = std::min(n, *w.maximum);
    v.numbers[c] = n;
  }
  return set.set(w.name, v);
}

void drawParameterSet(ViewerSession &session, ParameterSet &set)
{
  ImGui::PushID(&set);
  for (const ParameterWidget &w : set.widgets())
    if (drawParameter(set, w))
      session.parametersChanged();
  ImGui::PopID();
}

void drawSceneControls(ViewerSession &session, PanelState &state)
{
  ImGui::InputText("scene", &state.sceneText);
  ImGui::SameLine();
  if (ImGui::Button("Open")) {
    const std::string error = session.loadScene(state.sceneText);
    state.message = error.empty() ? "opened " + state.sceneText : error;
    state.messageIsError = !error.empty();
  }
  const std::vector<std::string> renderers = session.rendererSubtypes();
  const std::string current = session.rendererParameters().subtype();
  if (ImGui::BeginCombo("renderer", current.c_str())) {
    for (const std::string &r : renderers)
      if (ImGui::Selectable(r.c_str(), r == current) && r != current) {
        const std::string error = session.setRenderer(r);
        state.message = error;
        state.messageIsError = !error.empty();
      }
    ImGui::EndCombo();
  }
  const Channel shown = session.pipeline().channel();
  if (ImGui::BeginCombo("channel", channelName(shown))) {
    for (Channel c : kAllChannels)
      if (ImGui::Selectable(channelName(c), c == shown))
        session.pipeline().setChannel(c);
    ImGui::EndCombo();
  }
}

// The camera's own parameters but those the pose sets on every move.
void drawCameraParameters(ViewerSession &session)
{
  ParameterSet &set = session.cameraParameters();
  ImGui::PushID(&set);
  for (const ParameterWidget &w : set.widgets()) {
    if (isPoseParameter(w.name))
      continue;
    if (drawParameter(set, w))
      session.parametersChanged();
  }
  ImGui::PopID();
}

void drawDenoiseToggle(ViewerSession &session)
{
  ParameterSet &set = session.rendererParameters();
  const ParameterWidget *denoise = set.find("denoise");
  if (denoise && denoise->kind == WidgetKind::Toggle
      && drawParameter(set, *denoise))
    session.parametersChanged();
}

// The glTF file's cameras: the file is loaded again through camera N.
void drawFileCamera(ViewerSession &session, PanelState &state)
{
  ImGui::SetNextItemWidth(100.f);
  ImGui::InputInt("##camera", &state.fileCamera);
  state.fileCamera = std::max(state.fileCamera, 0);
  ImGui::SameLine();
  if (ImGui::Button("View through the file's camera")) {
    const std::string error = session.viewFileCamera(state.fileCamera);
    state.message = error;
    state.messageIsError = !error.empty();
  }
}

void drawCameraControls(ViewerSession &session, PanelState &state)
{
  OrbitCamera &camera = session.camera();
  bool changed = false;
  if (camera.pose().orthographic) {
    // The file's orthographic camera: zooming scales its view height.
    ImGui::Text("orthographic, view height %.3g", camera.pose().height);
  } else {
    float fovy = camera.pose().fovyDegrees;
    changed = ImGui::SliderFloat("fov (degrees)", &fovy, 5.f, 120.f);
    if (changed)
      camera.setFovy(fovy);
    float aperture = camera.pose().apertureRadius;
    const float scale = std::max(camera.distance(), 1e-6f);
    if (ImGui::SliderFloat("aperture", &aperture, 0.f, 0.05f * scale)) {
      camera.setAperture(aperture);
      changed = true;
    }
    ImGui::Text("focus distance %.3g (double-click to focus)",
        camera.pose().focusDistance);
  }
  if (ImGui::Button("Frame the scene (F)"))
    session.frameScene();
  else if (changed)
    session.cameraChanged();
  if (session.hasFileCameras())
    drawFileCamera(session, state);
  if (ImGui::TreeNodeEx("camera parameters", openFlags())) {
    drawCameraParameters(session);
    ImGui::TreePop();
  }
}

void drawScreenshot(ViewerSession &session, PanelState &state)
{
  ImGui::InputText("file (.png, .exr)", &state.screenshotPath);
  if (ImGui::Button("Save screenshot")) {
    const std::string error = session.screenshot(state.screenshotPath);
    state.message = error.empty() ? "wrote " + state.screenshotPath : error;
    state.messageIsError = !error.empty();
  }
}

// Color map, opacity curve, value range, unit distance; the volume is
// rebuilt when an edit is done (a slider released), not on every drag step.
void drawTransferFunction(ViewerSession &session, PanelState &state)
{
  TransferFunctionEdit &edit = state.transferFunction;
  bool done = false;
  const auto &maps = scenes::colorMaps();
  if (ImGui::BeginCombo("color map", maps[edit.colorMap].name)) {
    for (size_t i = 0; i < maps.size(); ++i)
      if (ImGui::Selectable(maps[i].name, int(i) == edit.colorMap)) {
        edit.colorMap = int(i);
        done = true;
      }
    ImGui::EndCombo();
  }
  ImGui::PlotLines("opacity",
      edit.opacities.data(),
      int(edit.opacities.size()),
      0,
      nullptr,
      0.f,
      1.f,
      ImVec2(0, 60));
  for (size_t i = 0; i < edit.opacities.size(); ++i) {
    ImGui::PushID(int(i));
    ImGui::VSliderFloat(
        "##o", ImVec2(24, 80), &edit.opacities[i], 0.f, 1.f, "");
    done |= ImGui::IsItemDeactivatedAfterEdit();
    ImGui::PopID();
    ImGui::SameLine();
  }
  if (ImGui::Button("+") && edit.opacities.size() < 16)
    edit.opacities.push_back(1.f), done = true;
  ImGui::SameLine();
  if (ImGui::Button("-") && edit.opacities.size() > 1)
    edit.opacities.pop_back(), done = true;
  done |= ImGui::Checkbox("own value range", &edit.customRange);
  if (edit.customRange) {
    ImGui::InputFloat2("range", edit.range.data());
    done |= ImGui::IsItemDeactivatedAfterEdit();
  }
  ImGui::DragFloat("unit distance",
      &edit.unitDistance,
      0.01f,
      1e-4f,
      1e4f,
      "%.4g",
      ImGuiSliderFlags_Logarithmic);
  done |= ImGui::IsItemDeactivatedAfterEdit();
  if (done) {
    const std::string error = session.restyleVolume(edit);
    state.message = error;
    state.messageIsError = !error.empty();
  }
}

void drawSelection(ViewerSession &session)
{
  const std::optional<Pick> &pick = session.selection();
  if (!pick) {
    ImGui::TextDisabled("click the image to pick an object");
    return;
  }
  auto id = [](uint32_t v) {
    return v == kNoId ? -1LL : (long long)v;
  };
  ImGui::Text("objectId %lld  instanceId %lld  primitiveId %lld",
      id(pick->objectId),
      id(pick->instanceId),
      id(pick->primitiveId));
  std::optional<SelectedSurface> &surface = session.selectedSurface();
  if (!surface) {
    ImGui::TextDisabled("the scene does not list this surface");
    return;
  }
  ImGui::TextUnformatted(surface->label.c_str());
  if (ImGui::TreeNodeEx("Material", openFlags())) {
    drawParameterSet(session, surface->material);
    ImGui::TreePop();
  }
  if (ImGui::TreeNodeEx("Geometry", openFlags())) {
    drawParameterSet(session, surface->geometry);
    ImGui::TreePop();
  }
}

void drawStatusBar(ViewerSession &session)
{
  const ImGuiIO &io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0, io.DisplaySize.y - kStatusBarHeight));
  ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, kStatusBarHeight));
  ImGui::Begin("status",
      nullptr,
      ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs
          | ImGuiWindowFlags_NoSavedSettings);
  const FramePipeline &pipeline = session.pipeline();
  const FrameStatus &s = pipeline.status();
  char line[256];
  int n = std::snprintf(line,
      sizeof(line),
      "%u spp  %.1f ms/frame  %ux%u",
      s.samples,
      s.frameSeconds * 1e3f,
      pipeline.width(),
      pipeline.height());
  if (s.raysPerSecond >= 0.0 && n > 0 && n < int(sizeof(line)))
    n += std::snprintf(
        line + n, sizeof(line) - n, "  %.2f Mrays/s", s.raysPerSecond * 1e-6);
  if (s.convergence >= 0.f && n > 0 && n < int(sizeof(line)))
    std::snprintf(line + n,
        sizeof(line) - n,
        "  converged %.0f %%",
        s.convergence * 100.f);
  ImGui::TextUnformatted(line);
  ImGui::End();
}

} // namespace

bool drawParameter(ParameterSet &set, const ParameterWidget &w)
{
  if (w.kind == WidgetKind::ReadOnly) {
    ImGui::TextDisabled("%s", w.name.c_str());
    return false;
  }
  // Without a default the widget starts at zero (or the minimum); nothing
  // is set until the user edits it.
  std::optional<ParameterValue> value = set.value(w.name);
  if (!value) {
    value = ParameterValue{};
    value->numbers.assign(w.components, w.minimum.value_or(0.0));
  }
  bool changed = false;
  if (w.kind == WidgetKind::Choice) {
    if (ImGui::BeginCombo(w.name.c_str(), value->text.c_str())) {
      for (const std::string &c : w.choices)
        if (ImGui::Selectable(c.c_str(), c == value->text)) {
          value->text = c;
          changed = set.set(w.name, *value);
        }
      ImGui::EndCombo();
    }
  } else if (w.kind == WidgetKind::Text) {
    if (ImGui::InputText(
            w.name.c_str(), &value->text, ImGuiInputTextFlags_EnterReturnsTrue))
      changed = set.set(w.name, *value);
  } else if (int(value->numbers.size()) == w.components) {
    changed = drawNumbers(set, w, *value);
  }
  if (!w.description.empty() && ImGui::IsItemHovered())
    ImGui::SetTooltip("%s", w.description.c_str());
  return changed;
}

void drawPanels(ViewerSession &session, PanelState &state)
{
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  const float height = ImGui::GetIO().DisplaySize.y - kStatusBarHeight - 16.f;
  ImGui::SetNextWindowSize(
      ImVec2(380,
          std::max(120.f, std::min(height, state.openAll ? 4000.f : 520.f))),
      ImGuiCond_FirstUseEver);
  g_openAll = state.openAll;
  ImGui::SetNextWindowCollapsed(
      state.startFolded && !state.openAll, ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("prism-viewer")) {
    ImGui::End();
    drawStatusBar(session);
    return;
  }
  drawSceneControls(session, state);
  drawDenoiseToggle(session);
  if (ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen))
    drawCameraControls(session, state);
  if (ImGui::CollapsingHeader("Renderer", openFlags()))
    drawParameterSet(session, session.rendererParameters());
  for (ViewerLight &light : session.lights())
    if (ImGui::CollapsingHeader(light.label.c_str(), openFlags()))
      drawParameterSet(session, light.parameters);
  if (session.hasVolume()
      && ImGui::CollapsingHeader("Volume transfer function", openFlags()))
    drawTransferFunction(session, state);
  if (ImGui::CollapsingHeader("Selection", ImGuiTreeNodeFlags_DefaultOpen))
    drawSelection(session);
  if (ImGui::CollapsingHeader("Screenshot", openFlags()))
    drawScreenshot(session, state);
  if (!state.message.empty()) {
    const ImVec4 colour = state.messageIsError ? ImVec4(1.f, 0.4f, 0.4f, 1.f)
                                               : ImVec4(0.7f, 1.f, 0.7f, 1.f);
    ImGui::TextColored(colour, "%s", state.message.c_str());
  }
  ImGui::End();
  drawStatusBar(session);
}

} // namespace prism::viewer
