#include "ViewerWindow.h"

#include "ImageIO.h"

#define GLFW_INCLUDE_NONE
#include <GL/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <cstdlib>
#include <utility>

namespace prism::viewer {
namespace {

std::string lastGlfwError()
{
  const char *description = nullptr;
  glfwGetError(&description);
  return description ? description : "unknown reason";
}

} // namespace

ViewerWindow::~ViewerWindow()
{
  if (m_imgui) {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  if (m_window) {
    if (m_texture)
      glDeleteTextures(1, &m_texture);
    glfwDestroyWindow(m_window);
  }
  glfwTerminate();
}

std::string ViewerWindow::open(
    uint32_t width, uint32_t height, const std::string &title)
{
  if (!glfwInit()) {
    const char *display = std::getenv("DISPLAY");
    return "cannot open a window: "
           + std::string(
               display && *display
                   ? "display '" + std::string(display) + "' is not reachable"
                   : "no display (DISPLAY is not set; under a "
                     "headless machine use xvfb-run)")
           + " (" + lastGlfwError() + ")";
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  m_window = glfwCreateWindow(
      int(width), int(height), title.c_str(), nullptr, nullptr);
  if (!m_window)
    return "cannot open an OpenGL 3.3 window (" + lastGlfwError() + ")";
  glfwMakeContextCurrent(m_window);
  // The loop paces itself (main.cpp): no waiting for vertical sync, which
  // would tie the UI to a display that Xvfb does not have.
  glfwSwapInterval(0);
  glfwSetWindowUserPointer(m_window, this);
  glfwSetDropCallback(m_window, &ViewerWindow::onDrop);
  glfwSetWindowRefreshCallback(m_window, &ViewerWindow::onRefresh);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr; // no imgui.ini beside the user's files
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(m_window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  m_imgui = true;
  glGenTextures(1, &m_texture);
  glBindTexture(GL_TEXTURE_2D, m_texture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return {};
}

void ViewerWindow::onDrop(GLFWwindow *window, int count, const char **paths)
{
  auto *self = (ViewerWindow *)glfwGetWindowUserPointer(window);
  for (int i = 0; i < count; ++i)
    self->m_dropped.push_back(paths[i]);
}

void ViewerWindow::onRefresh(GLFWwindow *window)
{
  ((ViewerWindow *)glfwGetWindowUserPointer(window))->m_exposed = true;
}

bool ViewerWindow::activity()
{
  const ImGuiIO &io = ImGui::GetIO();
  bool active = std::exchange(m_exposed, false) || !m_dropped.empty()
                || io.MouseDelta.x != 0.f || io.MouseDelta.y != 0.f
                || io.MouseWheel != 0.f || io.MouseWheelH != 0.f
                || io.InputQueueCharacters.Size > 0;
  for (bool down : io.MouseDown)
    active |= down;
  for (bool down : io.KeysDown)
    active |= down;
  uint32_t w = 0, h = 0;
  size(w, h);
  return active || w != m_drawnWidth || h != m_drawnHeight;
}

std::vector<std::string> ViewerWindow::takeDroppedFiles()
{
  return std::exchange(m_dropped, {});
}

bool ViewerWindow::shouldClose() const
{
  return glfwWindowShouldClose(m_window);
}

void ViewerWindow::requestClose()
{
  glfwSetWindowShouldClose(m_window, GLFW_TRUE);
}

void ViewerWindow::size(uint32_t &width, uint32_t &height) const
{
  int w = 0, h = 0;
  glfwGetFramebufferSize(m_window, &w, &h);
  width = uint32_t(w > 0 ? w : 0);
  height = uint32_t(h > 0 ? h : 0);
}

void ViewerWindow::beginFrame()
{
  glfwPollEvents();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void ViewerWindow::showImage(const Rgba8Image &image)
{
  if (image.pixels.empty()) {
    m_textureWidth = m_textureHeight = 0; // nothing to show
    return;
  }
  glBindTexture(GL_TEXTURE_2D, m_texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  if (image.width != m_textureWidth || image.height != m_textureHeight) {
    glTexImage2D(GL_TEXTURE_2D,
        0,
        GL_RGBA8,
        GLsizei(image.width),
        GLsizei(image.height),
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        image.pixels.data());
    m_textureWidth = image.width;
    m_textureHeight = image.height;
  } else {
    glTexSubImage2D(GL_TEXTURE_2D,
        0,
        0,
        0,
        GLsizei(image.width),
        GLsizei(image.height),
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        image.pixels.data());
  }
}

std::string ViewerWindow::endFrame(bool draw, const std::string &capturePath)
{
  if (m_textureWidth > 0) {
    // Row 0 of the image is its bottom: v runs up.
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    ImGui::GetBackgroundDrawList()->AddImage((ImTextureID)(intptr_t)m_texture,
        ImVec2(0, 0),
        size,
        ImVec2(0, 1),
        ImVec2(1, 0));
  }
  ImGui::Render();
  if (!draw && capturePath.empty())
    return {};
  uint32_t w = 0, h = 0;
  size(w, h);
  m_drawnWidth = w;
  m_drawnHeight = h;
  glViewport(0, 0, GLsizei(w), GLsizei(h));
  glClearColor(0.1f, 0.1f, 0.1f, 1.f);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  std::string error;
  if (!capturePath.empty())
    error = capture(capturePath, w, h);
  glfwSwapBuffers(m_window);
  return error;
}

std::string ViewerWindow::capture(
    const std::string &path, uint32_t width, uint32_t height) const
{
  std::vector<uint8_t> pixels(size_t(width) * height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadBuffer(GL_BACK);
  glReadPixels(0,
      0,
      GLsizei(width),
      GLsizei(height),
      GL_RGBA,
      GL_UNSIGNED_BYTE,
      pixels.data());
  // GL's rows, like ANARI's and prism_image's, start at the bottom.
  image::Image out(width, height);
  for (size_t i = 0; i < out.pixels.size(); ++i)
    for (int c = 0; c < 4; ++c) {
      const float v = pixels[4 * i + c] / 255.f;
      out.pixels[i][c] = c == 3 ? 1.f : image::linearFromSrgb(v);
    }
  const image::Status written = image::write(path, out);
  return written.ok() ? std::string() : written.error;
}

} // namespace prism::viewer
