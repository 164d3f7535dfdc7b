// The window: GLFW 3 with an OpenGL 3.3 core context and Dear ImGui on it.
// The rendered image is a GL texture drawn behind ImGui's windows; files
// dropped on the window are queued for the session to load.
#pragma once

#include "ChannelView.h"

#include <cstdint>
#include <string>
#include <vector>

struct GLFWwindow;

namespace prism::viewer {

class ViewerWindow
{
 public:
  ViewerWindow() = default;
  ~ViewerWindow();
  ViewerWindow(const ViewerWindow &) = delete;
  ViewerWindow &operator=(const ViewerWindow &) = delete;

  // Opens the window; the error says why not (no display, no OpenGL 3.3).
  std::string open(uint32_t width, uint32_t height, const std::string &title);

  bool shouldClose() const;
  void requestClose();
  // Polls events and starts an ImGui frame.
  void beginFrame();
  // Whether anything since the last frame asks for the window to be drawn
  // again: input, a resize, the window uncovered.
  bool activity();
  // Draws the image behind ImGui's windows, renders ImGui and swaps; with
  // `draw` false only ImGui's frame ends (drawing 1080p through software
  // OpenGL costs tens of ms, wasted when nothing changed). With
  // `capturePath`, first writes what was drawn there (PNG); the error says
  // why not.
  std::string endFrame(bool draw, const std::string &capturePath = {});

  // Replaces the texture's pixels (an empty image: nothing is shown).
  void showImage(const Rgba8Image &image);
  // The window's size in pixels (framebuffer).
  void size(uint32_t &width, uint32_t &height) const;
  // Paths dropped on the window since the last call.
  std::vector<std::string> takeDroppedFiles();

 private:
  static void onDrop(GLFWwindow *window, int count, const char **paths);
  static void onRefresh(GLFWwindow *window);
  std::string capture(
      const std::string &path, uint32_t width, uint32_t height) const;

  GLFWwindow *m_window{nullptr};
  bool m_imgui{false};
  unsigned m_texture{0};
  uint32_t m_textureWidth{0}, m_textureHeight{0};
  std::vector<std::string> m_dropped;
  bool m_exposed{true}; // the window needs drawing whatever else happens
  uint32_t m_drawnWidth{0}, m_drawnHeight{0};
};

} // namespace prism::viewer
