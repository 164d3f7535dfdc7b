#include "ViewerScript.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace prism::viewer {
namespace {

std::vector<std::string> words(const std::string &line)
{
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;)
    out.push_back(w);
  return out;
}

template <typename T>
bool number(const std::string &text, T &value)
{
  const char *end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if constexpr (std::is_floating_point_v<T>)
    if (!std::isfinite(value))
      return false;
  return ec == std::errc() && ptr == end;
}

// Fills `c` from the words after the command; the error says what is wrong.
std::string parseArguments(const std::vector<std::string> &w, ScriptCommand &c)
{
  const std::string &verb = w[0];
  const size_t n = w.size() - 1;
  if (verb == "orbit") {
    c.action = ScriptAction::Orbit;
    if (n != 1 || !number(w[1], c.degrees))
      return "orbit takes one angle in degrees";
  } else if (verb == "set") {
    c.action = ScriptAction::Set;
    c.target = n > 0 ? w[1] : std::string();
    if (c.target == "material" || c.target == "geometry") {
      // The picked surface's: there is one of each.
      if (n < 3)
        return "set " + c.target + " takes PARAM VALUE...";
      c.parameter = w[2];
      c.values.assign(w.begin() + 3, w.end());
      return {};
    }
    if (n < 4)
      return "set takes renderer|camera|light N PARAM VALUE... or "
             "material|geometry PARAM VALUE...";
    if (c.target != "renderer" && c.target != "camera" && c.target != "light")
      return "set applies to renderer, camera, light, material or geometry, "
             "not '"
             + c.target + "'";
    if (!number(w[2], c.index) || c.index < 0)
      return "'" + w[2] + "' is not an index";
    c.parameter = w[3];
    c.values.assign(w.begin() + 4, w.end());
  } else if (verb == "pick") {
    c.action = ScriptAction::Pick;
    if (n != 2 || !number(w[1], c.x) || !number(w[2], c.y))
      return "pick takes a pixel X Y";
  } else if (verb == "channel") {
    c.action = ScriptAction::Channel;
    if (n != 1)
      return "channel takes a name";
    c.name = w[1];
  } else if (verb == "wait-samples") {
    c.action = ScriptAction::WaitSamples;
    if (n != 1 || !number(w[1], c.samples) || c.samples == 0)
      return "wait-samples takes a sample count (1 or more)";
  } else if (verb == "screenshot") {
    c.action = ScriptAction::Screenshot;
    if (n != 1)
      return "screenshot takes a file name (no spaces)";
    c.name = w[1];
  } else if (verb == "window-screenshot") {
    c.action = ScriptAction::WindowScreenshot;
    if (n != 1)
      return "window-screenshot takes a file name (no spaces)";
    c.name = w[1];
  } else if (verb == "quit") {
    c.action = ScriptAction::Quit;
    if (n != 0)
      return "quit takes nothing";
  } else {
    return "unknown command";
  }
  return {};
}

} // namespace

ParsedScript parseScript(const std::string &text)
{
  ParsedScript script;
  std::istringstream in(text);
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    const std::vector<std::string> w = words(line);
    if (w.empty() || w[0][0] == '#')
      continue;
    ScriptCommand c;
    c.line = number;
    c.text = line;
    const std::string error = parseArguments(w, c);
    if (!error.empty()) {
      script.error =
          "line " + std::to_string(number) + " '" + line + "': " + error;
      script.commands.clear();
      return script;
    }
    script.commands.push_back(std::move(c));
  }
  return script;
}

ParsedScript readScript(const std::string &path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    ParsedScript failed;
    failed.error = "cannot read script '" + path + "'";
    return failed;
  }
  std::ostringstream text;
  text << in.rdbuf();
  ParsedScript script = parseScript(text.str());
  if (!script.ok())
    script.error = "script '" + path + "' " + script.error;
  return script;
}

} // namespace prism::viewer
