#include "CameraInput.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cmath>

namespace prism::viewer {
namespace {

constexpr float kOrbitDegreesPerPixel = 0.3f;
constexpr float kZoomPerNotch = 0.9f;
constexpr float kFlyFractionPerSecond = 0.5f; // of the distance to the target

bool flyKeys(ViewerSession &session, const ImGuiIO &io)
{
  float forward = 0.f, right = 0.f, up = 0.f;
  forward += ImGui::IsKeyDown(GLFW_KEY_W) ? 1.f : 0.f;
  forward -= ImGui::IsKeyDown(GLFW_KEY_S) ? 1.f : 0.f;
  right += ImGui::IsKeyDown(GLFW_KEY_D) ? 1.f : 0.f;
  right -= ImGui::IsKeyDown(GLFW_KEY_A) ? 1.f : 0.f;
  up += ImGui::IsKeyDown(GLFW_KEY_E) ? 1.f : 0.f;
  up -= ImGui::IsKeyDown(GLFW_KEY_Q) ? 1.f : 0.f;
  if (forward == 0.f && right == 0.f && up == 0.f)
    return false;
  const float step =
      kFlyFractionPerSecond * session.camera().distance() * io.DeltaTime;
  session.camera().fly(forward * step, right * step, up * step);
  return true;
}

} // namespace

InputOutcome handleCameraInput(ViewerSession &session)
{
  InputOutcome outcome;
  const ImGuiIO &io = ImGui::GetIO();
  OrbitCamera &camera = session.camera();
  if (!io.WantCaptureMouse) {
    const ImVec2 d = io.MouseDelta;
    const bool moving = d.x != 0.f || d.y != 0.f;
    const float height = io.DisplaySize.y > 0.f ? io.DisplaySize.y : 1.f;
    const bool panDrag =
        ImGui::IsMouseDragging(ImGuiMouseButton_Right)
        || (ImGui::IsMouseDragging(ImGuiMouseButton_Left) && io.KeyShift);
    if (panDrag && moving) {
      camera.pan(-d.x / height, d.y / height);
      outcome.moved = true;
    } else if (ImGui::IsMouseDragging(ImGuiMouseButton_Left) && moving) {
      camera.orbit(-d.x * kOrbitDegreesPerPixel, d.y * kOrbitDegreesPerPixel);
      outcome.moved = true;
    }
    if (io.MouseWheel != 0.f) {
      camera.zoom(std::pow(kZoomPerNotch, io.MouseWheel));
      outcome.moved = true;
    }
    // Window coordinates to framebuffer pixels (they differ on HiDPI).
    const int x = int(io.MousePos.x * io.DisplayFramebufferScale.x);
    const int y = int(io.MousePos.y * io.DisplayFramebufferScale.y);
    if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left))
      session.focusAt(x, y);
    else if (ImGui::IsMouseReleased(ImGuiMouseButton_Left)
             && ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.f).x == 0.f
             && ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.f).y == 0.f) {
      session.pick(x, y);
      outcome.picked = true;
    }
  }
  if (!io.WantCaptureKeyboard) {
    outcome.moved |= flyKeys(session, io);
    if (ImGui::IsKeyPressed(GLFW_KEY_F))
      session.frameScene();
  }
  if (outcome.moved)
    session.cameraChanged();
  return outcome;
}

} // namespace prism::viewer
