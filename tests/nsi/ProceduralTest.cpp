// NSIEvaluate type "dynamiclibrary" with the test procedural
// (procedural/SquareProcedural.c): its calls reach the context, it is
// loaded once per context and unloaded at NSIEnd, and a library that is
// missing, has no entry point or claims another NSI is reported, not run.
#include "NsiTestSupport.h"

#include <algorithm>

namespace {

class Procedural : public NsiTest
{
 protected:
  static void evaluate(NSIContext_t ctx,
      const char *library,
      const char *handle = nullptr,
      float x = 0)
  {
    NSI::ArgumentList args;
    args.addString("type", "dynamiclibrary").addString("filename", library);
    if (handle)
      args.addString("handle", handle).addFloat("x", x);
    NSIEvaluate(ctx, args.size(), args.data());
  }
  // How many messages say `text`.
  static size_t count(const std::vector<NsiMessage> &messages, const char *text)
  {
    return std::count_if(messages.begin(), messages.end(), [&](auto &m) {
      return m.text == text;
    });
  }
};

TEST_F(Procedural, ExecutesThroughTheContextItIsGiven)
{
  // A stream-writing context that runs dynamic libraries writes their calls.
  const std::string file = path("out.nsi");
  NSIContext_t ctx = beginStream(file, "dynamiclibrary");
  ASSERT_NE(ctx, NSI_BAD_CONTEXT);
  evaluate(ctx, PRISM_TEST_PROCEDURAL_SQUARE, "a", 0);
  evaluate(ctx, PRISM_TEST_PROCEDURAL_SQUARE, "b", 3);
  NSIEnd(ctx);
  const auto messages = m_messages.take();
  EXPECT_EQ(count(messages, "square procedural: loaded"), 1u);
  EXPECT_EQ(count(messages, "square procedural: executed"), 2u);
  EXPECT_EQ(count(messages, "square procedural: unloaded"), 1u);
  EXPECT_EQ(messages.back().text, "square procedural: unloaded");
  for (auto &m : messages)
    EXPECT_LT(m.level, NSIErrWarning) << m.text;
  const std::string text = readFile(file);
  EXPECT_NE(text.find("Create \"a\" \"mesh\""), std::string::npos) << text;
  EXPECT_NE(
      text.find("Connect \"b\" \"\" \".root\" \"objects\""), std::string::npos)
      << text;
  EXPECT_NE(text.find("4 1 -10 2 1 -10"), std::string::npos)
      << text; // b's x + 1
  EXPECT_EQ(text.find("Evaluate"), std::string::npos) << text;
}

TEST_F(Procedural, RecordedWhenNotExecuted)
{
  const std::string file = path("out.nsi");
  NSIContext_t ctx = beginStream(file);
  evaluate(ctx, PRISM_TEST_PROCEDURAL_SQUARE, "a");
  NSIEnd(ctx);
  EXPECT_EQ(m_messages.problems(NSIErrInfo), "");
  const std::string text = readFile(file);
  EXPECT_NE(text.find("Evaluate"), std::string::npos) << text;
  EXPECT_EQ(text.find("Create"), std::string::npos) << text;
}

TEST_F(Procedural, BadLibrariesAreReported)
{
  NSIContext_t ctx = beginRender();
  evaluate(ctx, path("absent.so").c_str());
  EXPECT_TRUE(reportedOnce(m_messages, {"absent.so", "cannot load"}));
  evaluate(ctx, PRISM_TEST_PROCEDURAL_SQUARE_NO_ENTRY);
  EXPECT_TRUE(reportedOnce(m_messages, {"has no NSIProceduralLoad"}));
  evaluate(ctx, PRISM_TEST_PROCEDURAL_SQUARE_BAD_VERSION);
  EXPECT_TRUE(reportedOnce(m_messages, {"built for NSI version 3, not 2"}));
  NSI::ArgumentList nameless;
  nameless.addString("type", "dynamiclibrary");
  NSIEvaluate(ctx, nameless.size(), nameless.data());
  EXPECT_TRUE(reportedOnce(m_messages, {"without a 'filename'"}));
  // The bad-version library was never unloaded through its procedural.
  NSIEnd(ctx);
  EXPECT_EQ(m_messages.problems(NSIErrInfo), "");
}

} // namespace
