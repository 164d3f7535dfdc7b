// The ASCII stream: what the writer writes, what the reader accepts, and
// that a written stream read back and written again is the same, byte for
// byte (so the reader made the same calls).
#include "NsiTestSupport.h"

#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>

namespace {

class Stream : public NsiTest
{
 protected:
  // Reads `source` into a context that writes the calls to a new file and
  // returns that file's text.
  std::string rewrite(const std::string &source, const std::string &name)
  {
    const std::string out = path(name);
    NSIContext_t ctx = beginStream(out, "apistream");
    EXPECT_NE(ctx, NSI_BAD_CONTEXT);
    include(ctx, source);
    NSIEnd(ctx);
    return readFile(out);
  }
  // The statements of a written stream, without its header comments.
  static std::string body(const std::string &text)
  {
    std::string out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
      if (!line.empty() && line[0] != '#')
        out += line + "\n";
    }
    return out;
  }
};

TEST_F(Stream, RoundTripIsExact)
{
  const std::string first = path("first.nsi");
  {
    NSIContext_t ctx = beginStream(first);
    ASSERT_NE(ctx, NSI_BAD_CONTEXT);
    NSI::ArgumentList mesh;
    const float points[6] = {0.1f, -2.5e-8f, 3.0f, 1e30f, 0.333333343f, -0.f};
    mesh.add("P", NSITypePoint, points, 2, 0, NSIParamPerVertex);
    const int counts[2] = {3, -7};
    mesh.add("nvertices", NSITypeInteger, counts, 2);
    const double matrix[16] = {
        1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.1, 1.0 / 3.0, -6e300, 1};
    mesh.add("transformationmatrix", NSITypeDoubleMatrix, matrix);
    const int64_t big = INT64_C(-9007199254740993);
    mesh.add("id", NSITypeInt64, &big);
    const float st[4] = {0, 0.5f, 1, 0.25f};
    mesh.add("st",
        NSITypeFloat,
        st,
        2,
        2,
        NSIParamIsArray | NSIParamPerFace | NSIParamInterpolateLinear);
    mesh.add("empty", NSITypeColor, nullptr, 0);
    mesh.addString("label", "say \"hi\"\\\t\n\x01 #not a comment");
    mesh.addPointer("callback", &big); // no stream form: left out
    NSICreate(ctx, "weird \"handle\"", "mesh", 0, nullptr);
    NSISetAttribute(ctx, "weird \"handle\"", mesh.size(), mesh.data());
    NSISetAttributeAtTime(ctx, "xf", -0.25, mesh.size(), mesh.data());
    NSIDeleteAttribute(ctx, "xf", "P");
    NSI::ArgumentList priority;
    priority.addInteger("priority", 2);
    NSIConnect(ctx, "a", "", "b", "objects", priority.size(), priority.data());
    NSIDisconnect(ctx, NSI_ALL_NODES, "", NSI_SCENE_ROOT, "objects");
    NSI::ArgumentList recursive;
    recursive.addInteger("recursive", 1);
    NSIDelete(ctx, "a", recursive.size(), recursive.data());
    // Recorded, not run (only included streams are inlined on rereading).
    NSI::ArgumentList evaluate;
    evaluate.addString("type", "lua").addString("filename", "${HOME}/x.lua");
    NSIEvaluate(ctx, evaluate.size(), evaluate.data());
    NSI::ArgumentList action;
    action.addString("action", "start");
    NSIRenderControl(ctx, action.size(), action.data());
    NSIEnd(ctx);
  }
  const std::string written = readFile(first);
  // The writer's form of a few values, checked by hand.
  EXPECT_NE(written.find("Create \"weird \\\"handle\\\"\" \"mesh\"\n"),
      std::string::npos)
      << written;
  EXPECT_NE(
      written.find(
          "  \"P\" \"v point\" 2 [ 0.1 -2.5e-08 3 1e+30 0.33333334 -0 ]\n"),
      std::string::npos)
      << written;
  EXPECT_NE(written.find("  \"st\" \"fl float[2]\" 2 [ 0 0.5 1 0.25 ]\n"),
      std::string::npos)
      << written;
  EXPECT_NE(written.find("  \"id\" \"int64\" 1 [ -9007199254740993 ]\n"),
      std::string::npos)
      << written;
  EXPECT_NE(written.find("  \"empty\" \"color\" 0 [ ]\n"), std::string::npos)
      << written;
  EXPECT_NE(written.find("  \"label\" \"string\" 1 [ \"say "
                         "\\\"hi\\\"\\\\\\t\\n\\001 #not a comment\" ]\n"),
      std::string::npos)
      << written;
  EXPECT_NE(
      written.find("SetAttributeAtTime \"xf\" -0.25\n"), std::string::npos)
      << written;
  EXPECT_NE(written.find("0.33333333333333331"), std::string::npos) << written;
  EXPECT_NE(written.find("  \"filename\" \"string\" 1 [ \"${HOME}/x.lua\" ]\n"),
      std::string::npos)
      << written;
  EXPECT_EQ(written.find("callback"), std::string::npos);
  EXPECT_EQ(m_messages.problems(), "");

  const std::string second = rewrite(first, "second.nsi");
  EXPECT_EQ(m_messages.problems(), "");
  EXPECT_EQ(second, written);
}

TEST_F(Stream, GrammarCases)
{
  // Not line based, bare scalars, flags in any order, 'i', comments, counts.
  const std::string source = writeFile("grammar.nsi", R"(# a comment
Create "hair" "curves" SetAttribute "hair" "nvertices" "int" 1 4
  "width" "lv float" 2 [ .1 5e-1 ]   # per vertex
  "old" "i float" 1 2
  "st" "float[2]" 2 [ 0 0 1 0 ] "st.indices" "int" 2 [ 0 1 ]
SetAttribute "tag" "label" "string" 2 [ "a#b" "c\td\001\101\"" ] "none" "int" 0 [ ]
  "name" "string" 1 [ "lua" ]
Connect "mirror" "" "ghost" "visibility" "value" "int" 1 1 "priority" "int" 1 2
Disconnect ".all" "" ".root" "objects" DeleteAttribute "xf" "transformationmatrix"
)");
  const std::string out = body(rewrite(source, "out.nsi"));
  EXPECT_EQ(m_messages.problems(), "");
  EXPECT_EQ(out,
      "Create \"hair\" \"curves\"\n"
      "SetAttribute \"hair\"\n"
      "  \"nvertices\" \"int\" 1 [ 4 ]\n"
      "  \"width\" \"vl float\" 2 [ 0.1 0.5 ]\n"
      "  \"old\" \"float\" 1 [ 2 ]\n"
      "  \"st\" \"float[2]\" 2 [ 0 0 1 0 ]\n"
      "  \"st.indices\" \"int\" 2 [ 0 1 ]\n"
      "SetAttribute \"tag\"\n"
      "  \"label\" \"string\" 2 [ \"a#b\" \"c\\td\\001A\\\"\" ]\n"
      "  \"none\" \"int\" 0 [ ]\n"
      "  \"name\" \"string\" 1 [ \"lua\" ]\n"
      "Connect \"mirror\" \"\" \"ghost\" \"visibility\"\n"
      "  \"value\" \"int\" 1 [ 1 ]\n"
      "  \"priority\" \"int\" 1 [ 2 ]\n"
      "Disconnect \".all\" \"\" \".root\" \"objects\"\n"
      "DeleteAttribute \"xf\" \"transformationmatrix\"\n");
}

TEST_F(Stream, CountIsAuthoritative)
{
  const std::string source = writeFile("counts.nsi",
      "SetAttribute \"a\" \"more\" \"float\" 2 [ 1 2 3 ] \"fewer\" \"point\" 2 "
      "[ 1 2 3 ]\n"
      "  \"after\" \"int\" 1 7\n");
  const std::string out = body(rewrite(source, "out.nsi"));
  auto messages = m_messages.take();
  ASSERT_EQ(messages.size(), 2u);
  EXPECT_EQ(messages[0].level, NSIErrWarning);
  EXPECT_NE(messages[0].text.find("'more' has more values"), std::string::npos);
  EXPECT_EQ(messages[1].level, NSIErrError);
  EXPECT_NE(
      messages[1].text.find(
          "counts.nsi:1: parameter 'fewer' has 3 values, count asks for 6"),
      std::string::npos)
      << messages[1].text;
  EXPECT_EQ(out,
      "SetAttribute \"a\"\n"
      "  \"more\" \"float\" 2 [ 1 2 ]\n"
      "  \"after\" \"int\" 1 [ 7 ]\n");
}

TEST_F(Stream, BadTextIsReportedAndSkipped)
{
  const std::string source = writeFile("bad.nsi",
      "Create \"a\" \"transform\"\n"
      "Frobnicate \"x\" 1 2 3\n"
      "SetAttribute \"a\" \"x\" \"quaternion\" 1 [ 1 ]\n"
      "SetAttribute \"a\" \"y\" \"int\" 1 [ 1.5 ]\n"
      "Connect \"a\"\n"
      "Create \"b\" \"transform\"\n"
      "SetAttribute \"b\" \"s\" \"string\" 1 \"unterminated\n");
  const std::string out = body(rewrite(source, "out.nsi"));
  const std::string problems = m_messages.problems(NSIErrError);
  for (const char *expected :
      {"bad.nsi:2: expected a statement, found 'Frobnicate'",
          "bad.nsi:3: parameter 'x' has unknown type 'quaternion'",
          "bad.nsi:4: parameter 'y': '1.5' is not a number of its type",
          "Connect is missing its operands",
          "unterminated string"})
    EXPECT_NE(problems.find(expected), std::string::npos) << expected << "\n"
                                                          << problems;
  EXPECT_NE(out.find("Create \"a\" \"transform\"\n"), std::string::npos) << out;
  EXPECT_NE(out.find("Create \"b\" \"transform\"\n"), std::string::npos) << out;
}

TEST_F(Stream, IncludesExpandVariablesAndStopCycles)
{
  // A render context reads includes; an unknown handle in the included
  // file proves it was read.
  writeFile("inner.nsi",
      "SetAttribute \"from-inner\" \"x\" \"int\" 1 1\n"
      "Evaluate \"type\" \"string\" 1 \"apistream\" \"filename\" \"string\" 1 "
      "\"${PRISM_NSI_TEST_DIR}/outer.nsi\"\n");
  const std::string outer = writeFile("outer.nsi",
      "Evaluate \"type\" \"string\" 1 \"apistream\" \"filename\" \"string\" 1 "
      "\"${PRISM_NSI_TEST_DIR}/inner.nsi\"\n");
  ::setenv("PRISM_NSI_TEST_DIR", m_dir.c_str(), 1);
  NSIContext_t ctx = beginRender();
  include(ctx, outer);
  NSIEnd(ctx);
  ::unsetenv("PRISM_NSI_TEST_DIR");
  const std::string problems = m_messages.problems(NSIErrError);
  EXPECT_NE(problems.find("unknown handle 'from-inner'"), std::string::npos)
      << problems;
  EXPECT_NE(problems.find("outer.nsi' includes itself"), std::string::npos)
      << problems;
  // Read once each: one unknown-handle message, one cycle message.
  EXPECT_EQ(std::count(problems.begin(), problems.end(), '\n'), 2) << problems;
}

TEST_F(Stream, UnsetVariablesStayLiteral)
{
  ::unsetenv("PRISM_NSI_SURELY_UNSET");
  NSIContext_t ctx = beginRender();
  NSI::ArgumentList args;
  args.addString("type", "apistream")
      .addString("filename", "${PRISM_NSI_SURELY_UNSET}/a.nsi");
  NSIEvaluate(ctx, args.size(), args.data());
  NSIEnd(ctx);
  EXPECT_NE(m_messages.problems().find("'${PRISM_NSI_SURELY_UNSET}/a.nsi'"),
      std::string::npos);
}

TEST_F(Stream, GzipStreamsAreInflated)
{
  const std::string text =
      "Create \"z\" \"transform\"\nSetAttribute \"z\" \"v\" \"double\" 1 0.5\n";
  const std::string compressed = path("scene.nsi.gz");
  gzFile file = gzopen(compressed.c_str(), "wb");
  ASSERT_NE(file, nullptr);
  gzwrite(file, text.data(), unsigned(text.size()));
  gzclose(file);
  EXPECT_EQ(body(rewrite(compressed, "out.nsi")),
      "Create \"z\" \"transform\"\nSetAttribute \"z\"\n  \"v\" \"double\" 1 [ "
      "0.5 ]\n");
  EXPECT_EQ(m_messages.problems(), "");
}

TEST_F(Stream, GzipStreamsAreWrittenAndReadBack)
{
  const std::string compressed = path("written.nsi.gz");
  NSI::ArgumentList begin;
  begin.addString("type", "apistream")
      .addString("streamfilename", compressed.c_str())
      .addString("streamcompression", "gzip");
  NSIContext_t ctx = NSIBegin(begin.size(), begin.data());
  ASSERT_NE(ctx, NSI_BAD_CONTEXT);
  NSICreate(ctx, "g", "transform", 0, nullptr);
  NSIEnd(ctx);
  const std::string bytes = readFile(compressed);
  ASSERT_GE(bytes.size(), 2u);
  EXPECT_EQ(uint8_t(bytes[0]), 0x1f);
  EXPECT_EQ(uint8_t(bytes[1]), 0x8b);
  EXPECT_EQ(
      body(rewrite(compressed, "out.nsi")), "Create \"g\" \"transform\"\n");
  EXPECT_EQ(m_messages.problems(), "");
}

} // namespace
