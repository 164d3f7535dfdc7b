// NSIEvaluate type "lua": the nsi table's calls, script parameters, error
// reporting with lines, the sandbox and the instruction limit.
#include "NsiTestSupport.h"

#include <cstdlib>

namespace {

class Lua : public NsiTest
{
 protected:
  void SetUp() override
  {
    NsiTest::SetUp();
    NSIContext_t ctx = beginRender();
    run(ctx, "x = 1");
    NSIEnd(ctx);
    if (m_messages.problems().find("not available") != std::string::npos)
      GTEST_SKIP() << "libnsi was built without Lua";
  }

  // Evaluates `script` (and `file` when given) with `extra` parameters.
  static void run(NSIContext_t ctx,
      const std::string &script,
      const std::string &file = {},
      NSI::ArgumentList *extra = nullptr)
  {
    NSI::ArgumentList args;
    args.addString("type", "lua");
    if (!script.empty())
      args.addString("script", script.c_str());
    if (!file.empty())
      args.addString("filename", file.c_str());
    std::vector<NSIParam_t> all(args.data(), args.data() + args.size());
    if (extra)
      all.insert(all.end(), extra->data(), extra->data() + extra->size());
    NSIEvaluate(ctx, int(all.size()), all.data());
  }

  // Runs `script` in a fresh render context.
  void runAlone(const std::string &script)
  {
    NSIContext_t ctx = beginRender();
    run(ctx, script);
    NSIEnd(ctx);
  }
};

// The nsi table's calls reach the context as the same C calls would: both
// written to a stream, the texts are equal.
TEST_F(Lua, CallsMatchTheCApi)
{
  NSIContext_t ctx = beginStream(path("lua.nsi"), "lua");
  run(ctx, R"(
nsi.Create("m", "mesh")
nsi.SetAttribute("m",
  {name="nvertices", data=4},
  {name="P", type=nsi.TypePoint, data={0,0,0, 1,0,0, 1,1,0, 0,1,0}})
nsi.SetAttribute("m", {
  {name="label", data="floor"},
  {name="weight", data=0.5},
  {name="cols", type=nsi.TypeColor, arraylength=2, data={1,0,0, 0,1,0}}})
nsi.SetAttributeAtTime("m", 0.25, {name="width", data=2.5})
nsi.DeleteAttribute("m", "weight")
nsi.Connect("m", "", ".root", "objects", {name="priority", data=2})
nsi.Disconnect("m", "", ".root", "objects")
nsi.Delete("m", {name="recursive", data=1})
nsi.Evaluate({name="type", data="apistream"}, {name="filename", data="x.nsi"})
nsi.RenderControl({name="action", data="wait"})
)");
  NSIEnd(ctx);
  EXPECT_EQ(m_messages.problems(), "");

  ctx = beginStream(path("c.nsi"));
  NSICreate(ctx, "m", "mesh", 0, nullptr);
  {
    const float P[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    NSI::ArgumentList args;
    args.addInteger("nvertices", 4);
    args.add("P", NSITypePoint, P, 4);
    NSISetAttribute(ctx, "m", args.size(), args.data());
  }
  {
    const float cols[] = {1, 0, 0, 0, 1, 0};
    NSI::ArgumentList args;
    args.addString("label", "floor").addFloat("weight", 0.5f);
    args.add("cols", NSITypeColor, cols, 1, 2, NSIParamIsArray);
    NSISetAttribute(ctx, "m", args.size(), args.data());
  }
  {
    NSI::ArgumentList args;
    args.addFloat("width", 2.5f);
    NSISetAttributeAtTime(ctx, "m", 0.25, args.size(), args.data());
  }
  NSIDeleteAttribute(ctx, "m", "weight");
  {
    NSI::ArgumentList args;
    args.addInteger("priority", 2);
    NSIConnect(ctx, "m", "", ".root", "objects", args.size(), args.data());
  }
  NSIDisconnect(ctx, "m", "", ".root", "objects");
  {
    NSI::ArgumentList args;
    args.addInteger("recursive", 1);
    NSIDelete(ctx, "m", args.size(), args.data());
  }
  {
    NSI::ArgumentList args;
    args.addString("type", "apistream").addString("filename", "x.nsi");
    NSIEvaluate(ctx, args.size(), args.data());
  }
  {
    NSI::ArgumentList args;
    args.addString("action", "wait");
    NSIRenderControl(ctx, args.size(), args.data());
  }
  NSIEnd(ctx);
  EXPECT_EQ(m_messages.problems(), "");
  EXPECT_EQ(readFile(path("lua.nsi")), readFile(path("c.nsi")));
}

TEST_F(Lua, ScriptParametersReachTheScript)
{
  NSIContext_t ctx = beginRender();
  const float colors[] = {1, 0, 1, 2, 3, 4};
  NSI::ArgumentList extra;
  extra.add("userdata", NSITypeColor, colors, 1, 2, NSIParamIsArray);
  extra.addInteger("n", 7).addString("s", "hi");
  run(ctx,
      "local p = nsi.scriptparameters\n"
      "nsi.utilities.ReportError(nsi.ErrInfo, tostring(p.userdata.data[5])"
      " .. ' ' .. p.n.data .. ' ' .. p.s.data .. ' ' .. p.type.data"
      " .. ' ' .. p.userdata.arraylength .. ' ' .. p.userdata.type)",
      {},
      &extra);
  NSIEnd(ctx);
  auto messages = m_messages.take();
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0].level, NSIErrInfo);
  EXPECT_EQ(messages[0].text, "3.0 7 hi lua 2 4");
}

TEST_F(Lua, ReportErrorKeepsItsLevel)
{
  runAlone(R"(
nsi.utilities.ReportError(nsi.ErrMessage, "a message")
nsi.utilities.ReportError(nsi.ErrInfo, "some info")
nsi.utilities.ReportError(nsi.ErrWarning, "Watch out!")
nsi.utilities.ReportError(nsi.ErrError, "it broke")
)");
  auto messages = m_messages.take();
  ASSERT_EQ(messages.size(), 4u);
  const char *texts[] = {"a message", "some info", "Watch out!", "it broke"};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(messages[i].level, i);
    EXPECT_EQ(messages[i].text, texts[i]);
  }
}

TEST_F(Lua, ScriptThenFileShareOneState)
{
  const std::string file =
      writeFile("after.lua", "nsi.utilities.ReportError(nsi.ErrInfo, x)\n");
  NSIContext_t ctx = beginRender();
  run(ctx, "x = 'set by the script'", file);
  NSIEnd(ctx);
  auto messages = m_messages.take();
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0].text, "set by the script");
}

TEST_F(Lua, SyntaxErrorIsReportedWithItsLine)
{
  runAlone("x = 1\ny = 2\nnsi.Create(\"a\" \"mesh\")\n");
  EXPECT_TRUE(reportedOnce(m_messages, {"Lua", "script:3:"}));
  const std::string file = writeFile("bad.lua", "x = 1\n\nif x then\n");
  NSIContext_t ctx = beginRender();
  run(ctx, {}, file);
  NSIEnd(ctx);
  EXPECT_TRUE(reportedOnce(m_messages, {"bad.lua:4:"}));
}

TEST_F(Lua, RuntimeErrorIsReportedWithItsLine)
{
  runAlone("local a\nlocal b = 1\nb = a.field\n");
  EXPECT_TRUE(reportedOnce(m_messages, {"script:3:", "local 'a'"}));
  runAlone("\nerror('my own')\n");
  EXPECT_TRUE(reportedOnce(m_messages, {"script:2:", "my own"}));
  // A bad parameter stops the script at its line.
  runAlone(
      "\n\nnsi.SetAttribute('m', {data=1})\n"
      "nsi.utilities.ReportError(nsi.ErrError, 'not reached')\n");
  EXPECT_TRUE(reportedOnce(
      m_messages, {"script:3:", "nsi.SetAttribute", "no string 'name'"}));
  runAlone("nsi.Create('m')\n");
  EXPECT_TRUE(
      reportedOnce(m_messages, {"script:1:", "nsi.Create", "bad argument #2"}));
  runAlone(
      "nsi.SetAttribute('m', {name='c', type=nsi.TypeColor, "
      "data={1, 2}})\n");
  EXPECT_TRUE(reportedOnce(m_messages, {"script:1:", "whole items"}));
  runAlone("error({})\n");
  EXPECT_TRUE(reportedOnce(m_messages, {"error object"}));
}

TEST_F(Lua, SandboxHasNoSystemLibraries)
{
  for (const char *script : {"os.execute('true')",
           "io.open('/etc/passwd')",
           "require('os')",
           "dofile('/etc/passwd')",
           "loadfile('/etc/passwd')",
           "debug.traceback()",
           "package.loadlib('libc.so.6', 'system')"}) {
    runAlone(script);
    EXPECT_TRUE(reportedOnce(m_messages, {"script:1:", "nil value"})) << script;
  }
  // Binary chunks are refused; text ones load.
  runAlone(
      "local f, e = load(string.dump(function() end))\n"
      "assert(not f, 'binary chunk loaded')\n"
      "assert(load('return 1')() == 1)\n"
      "nsi.utilities.ReportError(nsi.ErrInfo, e)\n");
  auto messages = m_messages.take();
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0].level, NSIErrInfo);
  EXPECT_NE(messages[0].text.find("binary"), std::string::npos)
      << messages[0].text;
}

TEST_F(Lua, RunawayScriptIsStopped)
{
  ::setenv("PRISM_NSI_LUA_INSTRUCTION_LIMIT", "1000000", 1);
  runAlone("local i = 0\nwhile true do i = i + 1 end\n");
  EXPECT_TRUE(reportedOnce(m_messages, {"stopped after 1000000"}));
  // pcall does not swallow the stop.
  runAlone("while true do pcall(function() while true do end end) end\n");
  EXPECT_TRUE(reportedOnce(m_messages, {"stopped after"}));
  ::unsetenv("PRISM_NSI_LUA_INSTRUCTION_LIMIT");
}

TEST_F(Lua, NestingIsBounded)
{
  const std::string file = writeFile("self.lua",
      "nsi.Evaluate({name='type', data='lua'}, "
      "{name='filename', data=nsi.scriptparameters.filename.data})\n");
  NSIContext_t ctx = beginRender();
  run(ctx, {}, file);
  NSIEnd(ctx);
  EXPECT_TRUE(reportedOnce(m_messages, {"nested"}));
}

TEST_F(Lua, MissingSourceIsReported)
{
  runAlone({});
  EXPECT_TRUE(reportedOnce(m_messages, {"without a 'script' or 'filename'"}));
  NSIContext_t ctx = beginRender();
  run(ctx, {}, path("absent.lua"));
  NSIEnd(ctx);
  EXPECT_TRUE(reportedOnce(m_messages, {"cannot read", "absent.lua"}));
}

} // namespace
