#include "ScriptRunner.h"

#include <cstdio>

namespace prism::viewer {
namespace {

std::string idText(uint32_t id)
{
  return id == kNoId ? "none" : std::to_string(id);
}

} // namespace

std::string pickLine(int x, int y, const Pick &pick)
{
  return "pick " + std::to_string(x) + " " + std::to_string(y) + ": objectId "
         + idText(pick.objectId) + " instanceId " + idText(pick.instanceId)
         + " primitiveId " + idText(pick.primitiveId);
}

ScriptState ScriptRunner::step(ViewerSession &session)
{
  while (m_error.empty() && !m_quit && m_next < m_script.commands.size()) {
    if (!run(m_script.commands[m_next], session))
      break;
    ++m_next;
  }
  if (!m_error.empty())
    return ScriptState::Failed;
  return m_quit || m_next >= m_script.commands.size() ? ScriptState::Finished
                                                      : ScriptState::Running;
}

bool ScriptRunner::run(const ScriptCommand &c, ViewerSession &session)
{
  auto fail = [&](const std::string &why) {
    m_error =
        "script line " + std::to_string(c.line) + " '" + c.text + "': " + why;
    return false;
  };
  FramePipeline &pipeline = session.pipeline();
  switch (c.action) {
  case ScriptAction::Orbit:
    session.camera().orbit(c.degrees, 0.f);
    session.cameraChanged();
    return true;
  case ScriptAction::Set: {
    const std::string error =
        session.setParameter(c.target, c.index, c.parameter, c.values);
    return error.empty() ? true : fail(error);
  }
  case ScriptAction::Pick: {
    // Ids are read from the first frame after a change: wait for it.
    if (pipeline.status().samples == 0)
      return false;
    const std::optional<Pick> picked = session.pick(c.x, c.y);
    if (!picked)
      return fail("pixel outside the image");
    std::printf("%s\n", pickLine(c.x, c.y, *picked).c_str());
    std::fflush(stdout);
    return true;
  }
  case ScriptAction::Channel: {
    const std::optional<Channel> channel = channelNamed(c.name);
    if (!channel)
      return fail("no channel '" + c.name
                  + "' (color, depth, normal, albedo, objectId, "
                    "primitiveId, instanceId)");
    pipeline.setChannel(*channel);
    return true;
  }
  case ScriptAction::WaitSamples:
    return pipeline.status().samples >= c.samples;
  case ScriptAction::Screenshot: {
    // The image must show the current state and channel.
    if (pipeline.status().samples == 0
        || pipeline.imageChannel() != pipeline.channel())
      return false;
    const std::string error = session.screenshot(c.name);
    return error.empty() ? true : fail(error);
  }
  case ScriptAction::WindowScreenshot:
    if (!m_capture)
      return fail("there is no window");
    if (pipeline.status().samples == 0
        || pipeline.imageChannel() != pipeline.channel())
      return false;
    m_capture(c.name);
    return true;
  case ScriptAction::Quit:
    m_quit = true;
    return true;
  }
  return true;
}

} // namespace prism::viewer
