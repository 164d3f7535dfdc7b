// The script's grammar: every command, comments, and errors naming the line.
#include "ViewerOptions.h"
#include "ViewerScript.h"

#include <gtest/gtest.h>

namespace prism::viewer {
namespace {

TEST(ViewerScript, ReadsEveryCommand)
{
  const ParsedScript s = parseScript(
      "# a comment\n"
      "\n"
      "orbit 30\n"
      "set renderer 0 maxPathLength 1\n"
      "set light 2 color 1 0.5 0\r\n"
      "pick 10 20\n"
      "channel objectId\n"
      "wait-samples 8\n"
      "screenshot out.png\n"
      "window-screenshot window.png\n"
      "quit\n");
  ASSERT_TRUE(s.ok()) << s.error;
  ASSERT_EQ(s.commands.size(), 9u);
  EXPECT_EQ(s.commands[0].action, ScriptAction::Orbit);
  EXPECT_FLOAT_EQ(s.commands[0].degrees, 30.f);
  EXPECT_EQ(s.commands[0].line, 3);
  EXPECT_EQ(s.commands[1].target, "renderer");
  EXPECT_EQ(s.commands[1].parameter, "maxPathLength");
  EXPECT_EQ(s.commands[1].values, std::vector<std::string>{"1"});
  EXPECT_EQ(s.commands[2].index, 2);
  EXPECT_EQ(s.commands[2].values.size(), 3u);
  EXPECT_EQ(s.commands[3].x, 10);
  EXPECT_EQ(s.commands[3].y, 20);
  EXPECT_EQ(s.commands[4].name, "objectId");
  EXPECT_EQ(s.commands[5].samples, 8u);
  EXPECT_EQ(s.commands[6].name, "out.png");
  EXPECT_EQ(s.commands[7].action, ScriptAction::WindowScreenshot);
  EXPECT_EQ(s.commands[7].name, "window.png");
  EXPECT_EQ(s.commands[8].action, ScriptAction::Quit);
}

TEST(ViewerScript, AnUnknownLineIsAnErrorNamingIt)
{
  const ParsedScript s = parseScript("orbit 10\nspin 3\nquit\n");
  EXPECT_FALSE(s.ok());
  EXPECT_EQ(s.error, "line 2 'spin 3': unknown command");
  EXPECT_TRUE(s.commands.empty());
}

TEST(ViewerScript, WrongArgumentsAreErrorsNamingTheLine)
{
  for (const char *bad : {"orbit",
           "orbit ten",
           "orbit nan",
           "set renderer 0 maxPathLength",
           "set world 0 a 1",
           "set light -1 a 1",
           "pick 1",
           "pick 1 2.5",
           "channel",
           "wait-samples 0",
           "wait-samples -3",
           "screenshot",
           "quit now"}) {
    const ParsedScript s = parseScript(std::string("\n") + bad);
    EXPECT_FALSE(s.ok()) << bad;
    EXPECT_EQ(s.error.rfind("line 2 '", 0), 0u) << s.error;
  }
}

TEST(ViewerScript, AMissingFileIsNamed)
{
  const ParsedScript s = readScript("/nonexistent/script.txt");
  EXPECT_EQ(s.error, "cannot read script '/nonexistent/script.txt'");
}

TEST(ViewerOptions, ReadTheCommandLine)
{
  const char *argv[] = {"prism-viewer",
      "demo:cornell-box",
      "--size",
      "320x240",
      "--renderer",
      "ao",
      "--script",
      "s.txt",
      "--spp-limit",
      "64"};
  const ParsedOptions p = parseViewerOptions(10, argv, "helide");
  ASSERT_TRUE(p.ok()) << p.error;
  EXPECT_EQ(p.options.scene, "demo:cornell-box");
  EXPECT_EQ(p.options.width, 320u);
  EXPECT_EQ(p.options.height, 240u);
  EXPECT_EQ(p.options.renderer, "ao");
  EXPECT_EQ(p.options.library, "helide"); // $ANARI_LIBRARY
  EXPECT_EQ(p.options.script, "s.txt");
  EXPECT_EQ(p.options.sampleLimit, 64u);
}

TEST(ViewerOptions, BadOptionsAreNamed)
{
  const char *size[] = {"prism-viewer", "--size", "0x10"};
  EXPECT_NE(parseViewerOptions(3, size, nullptr).error.find("--size"),
      std::string::npos);
  const char *unknown[] = {"prism-viewer", "--frobnicate"};
  EXPECT_EQ(parseViewerOptions(2, unknown, nullptr).error,
      "unknown option '--frobnicate'");
  const char *missing[] = {"prism-viewer", "--library"};
  EXPECT_EQ(
      parseViewerOptions(2, missing, nullptr).error, "--library needs a value");
  const char *scale[] = {"prism-viewer", "--interaction-scale", "2"};
  EXPECT_FALSE(parseViewerOptions(3, scale, nullptr).ok());
}

} // namespace
} // namespace prism::viewer
