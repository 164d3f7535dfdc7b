// ViewerSession's MPI mirror: top-level changes as lines for the other
// processes, and those lines applied there (ViewerSession.h, mirrorTo).
#include "ViewerSession.h"

#include <cstdio>
#include <sstream>

namespace prism::viewer {

void ViewerSession::mirrorTo(std::function<void(const std::string &)> mirror)
{
  m_mirror = std::move(mirror);
  m_pipeline->setDiscards(!m_mirror);
  m_pipeline->beforeRender(
      [](void *self) {
        auto *session = (ViewerSession *)self;
        if (session->m_mirror)
          session->m_mirror("render");
      },
      this);
  observeParameters();
  // The followers start where this session is now.
  if (m_mirror && m_width > 0) {
    m_mirror(viewportLine(m_width, m_height, m_scale));
    m_mirror(poseLine(m_camera.pose()));
  }
}

ViewerSession::MirrorScope ViewerSession::mirrored(const std::string &line)
{
  if (m_mirror && m_mirrorDepth == 0)
    m_mirror(line);
  return MirrorScope(m_mirrorDepth);
}

std::string viewportLine(uint32_t width, uint32_t height, float scale)
{
  char line[96];
  std::snprintf(
      line, sizeof(line), "viewport %u %u %.9g", width, height, double(scale));
  return line;
}

std::string poseLine(const CameraPose &pose)
{
  char text[512];
  std::snprintf(text,
      sizeof(text),
      "pose %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g %d "
      "%.9g",
      pose.eye[0],
      pose.eye[1],
      pose.eye[2],
      pose.at[0],
      pose.at[1],
      pose.at[2],
      pose.up[0],
      pose.up[1],
      pose.up[2],
      pose.fovyDegrees,
      pose.apertureRadius,
      pose.focusDistance,
      pose.orthographic ? 1 : 0,
      pose.height);
  return text;
}

// Values set through the panels' sets reach the other processes as `set`.
void ViewerSession::observeParameters()
{
  if (!m_mirror)
    return;
  m_mirrorTargets.clear();
  auto observe = [&](ParameterSet &set, const std::string &prefix) {
    m_mirrorTargets.push_back(
        std::make_unique<MirrorTarget>(MirrorTarget{this, prefix}));
    set.observe(
        [](void *user, const std::string &name, const ParameterValue &value) {
          const auto *target = (const MirrorTarget *)user;
          ViewerSession &session = *target->session;
          if (!session.m_mirror || session.m_mirrorDepth > 0)
            return;
          std::string line = target->prefix + name;
          for (const std::string &word : valueWords(value))
            line += " " + word;
          session.m_mirror(line);
        },
        m_mirrorTargets.back().get());
  };
  observe(m_rendererParameters, "set renderer 0 ");
  observe(m_cameraParameters, "set camera 0 ");
  for (size_t i = 0; i < m_lights.size(); ++i)
    observe(m_lights[i].parameters, "set light " + std::to_string(i) + " ");
}

bool ViewerSession::applyMirrored(const std::string &line)
{
  std::istringstream in(line);
  std::string verb;
  in >> verb;
  if (verb == "quit")
    return false;
  std::string rest;
  std::getline(in >> std::ws, rest);
  std::istringstream args(rest);
  if (verb == "load") {
    loadScene(rest);
  } else if (verb == "frame") {
    frameScene();
  } else if (verb == "renderer") {
    setRenderer(rest);
  } else if (verb == "viewport") {
    uint32_t w = 0, h = 0;
    float scale = 1.f;
    args >> w >> h >> scale;
    setViewport(w, h, scale);
  } else if (verb == "pose") {
    CameraPose pose;
    args >> pose.eye[0] >> pose.eye[1] >> pose.eye[2] >> pose.at[0]
        >> pose.at[1] >> pose.at[2] >> pose.up[0] >> pose.up[1] >> pose.up[2]
        >> pose.fovyDegrees >> pose.apertureRadius >> pose.focusDistance;
    int orthographic = 0;
    args >> orthographic >> pose.height;
    pose.orthographic = orthographic != 0;
    m_camera.setPose(pose);
    cameraChanged();
  } else if (verb == "set") {
    std::string target, name;
    int index = 0;
    args >> target >> index >> name;
    std::vector<std::string> words;
    for (std::string w; args >> w;)
      words.push_back(w);
    setParameter(target, index, name, words);
  } else if (verb == "filecam") {
    int index = 0;
    args >> index;
    viewFileCamera(index);
  } else if (verb == "render") {
    anariRenderFrame(device(), m_frame);
    anariFrameReady(device(), m_frame, ANARI_WAIT);
  }
  return true;
}

} // namespace prism::viewer
