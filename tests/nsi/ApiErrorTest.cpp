// Every C entry point with bad input: the problem is reported through the
// context's error handler (or stderr without a context), nothing crashes,
// and what was wrong is left out while the rest of the call still applies.
#include "NsiTestSupport.h"

#include <cmath>
#include <thread>

namespace {

class ApiError : public NsiTest
{
 protected:
  void SetUp() override
  {
    NsiTest::SetUp();
    m_ctx = beginRender();
    ASSERT_NE(m_ctx, NSI_BAD_CONTEXT);
  }
  void TearDown() override
  {
    NSIEnd(m_ctx);
    NsiTest::TearDown();
  }
  NSIContext_t m_ctx{NSI_BAD_CONTEXT};
};

TEST_F(ApiError, UnknownContextGoesToStderr)
{
  for (NSIContext_t bad :
      {NSIContext_t(0), NSIContext_t(-3), NSIContext_t(987654)}) {
    ::testing::internal::CaptureStderr();
    NSICreate(bad, "a", "transform", 0, nullptr);
    NSISetAttribute(bad, "a", 0, nullptr);
    NSIRenderControl(bad, 0, nullptr);
    NSIEnd(bad);
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("NSICreate: unknown context " + std::to_string(bad)),
        std::string::npos)
        << err;
    EXPECT_NE(err.find("NSIEnd: unknown context"), std::string::npos) << err;
  }
}

TEST_F(ApiError, EndedContextIsUnknown)
{
  NSIContext_t other = beginRender();
  ASSERT_NE(other, NSI_BAD_CONTEXT);
  EXPECT_NE(other, m_ctx);
  NSIEnd(other);
  ::testing::internal::CaptureStderr();
  NSICreate(other, "a", "transform", 0, nullptr);
  EXPECT_NE(::testing::internal::GetCapturedStderr().find("unknown context"),
      std::string::npos);
}

TEST_F(ApiError, UnknownHandles)
{
  const float one = 1;
  NSIParam_t p{"fov", &one, NSITypeFloat, 0, 1, 0};
  NSISetAttribute(m_ctx, "ghost", 1, &p);
  EXPECT_TRUE(reportedOnce(m_messages, {"NSISetAttribute", "'ghost'"}));
  NSISetAttributeAtTime(m_ctx, "ghost", 0.5, 1, &p);
  EXPECT_TRUE(reportedOnce(m_messages, {"NSISetAttributeAtTime", "'ghost'"}));
  NSIDeleteAttribute(m_ctx, "ghost", "fov");
  EXPECT_TRUE(reportedOnce(m_messages, {"NSIDeleteAttribute", "'ghost'"}));
  NSIDelete(m_ctx, "ghost", 0, nullptr);
  EXPECT_TRUE(reportedOnce(m_messages, {"NSIDelete", "'ghost'"}));
  NSIConnect(m_ctx, "ghost", "", NSI_SCENE_ROOT, "objects", 0, nullptr);
  EXPECT_TRUE(reportedOnce(m_messages, {"NSIConnect", "'ghost'"}));
  NSIDisconnect(m_ctx, NSI_SCENE_ROOT, "", "ghost", "objects");
  EXPECT_TRUE(reportedOnce(m_messages, {"NSIDisconnect", "'ghost'"}));
}

TEST_F(ApiError, NonFiniteSampleTimes)
{
  NSICreate(m_ctx, "xf", "transform", 0, nullptr);
  const double m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  NSIParam_t p{"transformationmatrix", m, NSITypeDoubleMatrix, 0, 1, 0};
  for (double time : {NAN, INFINITY, -INFINITY}) {
    NSISetAttributeAtTime(m_ctx, "xf", time, 1, &p);
    EXPECT_TRUE(reportedOnce(
        m_messages, {"NSISetAttributeAtTime", "'xf'", "not a finite number"}))
        << time;
  }
  NSISetAttributeAtTime(m_ctx, "xf", 0.5, 1, &p);
  EXPECT_EQ(m_messages.problems(), "");
}

TEST_F(ApiError, NullArguments)
{
  NSICreate(m_ctx, nullptr, "mesh", 0, nullptr);
  EXPECT_TRUE(reportedOnce(m_messages, {"NSICreate", "handle"}));
  NSICreate(m_ctx, "m", nullptr, 0, nullptr);
  EXPECT_TRUE(reportedOnce(m_messages, {"NSICreate", "type"}));
  NSIConnect(m_ctx, "a", "", "b", nullptr, 0, nullptr);
  EXPECT_TRUE(reportedOnce(m_messages, {"NSIConnect", "target attribute"}));
  NSICreate(m_ctx, "m", "mesh", 0, nullptr);
  EXPECT_EQ(m_messages.problems(), "");
  NSISetAttribute(m_ctx, "m", 3, nullptr);
  EXPECT_TRUE(reportedOnce(m_messages, {"NSISetAttribute", "3 parameters"}));
  NSIDeleteAttribute(m_ctx, "m", nullptr);
  EXPECT_TRUE(
      reportedOnce(m_messages, {"NSIDeleteAttribute", "attribute name"}));
}

TEST_F(ApiError, BadParametersAreLeftOutOthersKept)
{
  // Written to a stream, what was kept is visible.
  const std::string file = path("kept.nsi");
  NSIContext_t stream = beginStream(file);
  ASSERT_NE(stream, NSI_BAD_CONTEXT);
  const int values[2] = {4, 5};
  NSIParam_t params[] = {
      {"badtype", values, 77, 0, 1, 0},
      {nullptr, values, NSITypeInteger, 0, 1, 0},
      {"nodata", nullptr, NSITypeInteger, 0, 2, 0},
      {"negative", values, NSITypeInteger, -2, 1, NSIParamIsArray},
      {"good", values, NSITypeInteger, 2, 1, NSIParamIsArray},
      // 2^34 arrays of 2^30: a count whose product wraps around to 0.
      {"wraps",
          values,
          NSITypeInteger,
          1 << 30,
          size_t(1) << 34,
          NSIParamIsArray},
  };
  NSISetAttribute(stream, "x", 6, params);
  NSIEnd(stream);
  auto messages = m_messages.take();
  ASSERT_EQ(messages.size(), 5u);
  EXPECT_NE(messages[4].text.find("'wraps' has an absurd count (17179869184 "
                                  "of 1073741824 values, more than the "
                                  "machine's"),
      std::string::npos)
      << messages[4].text;
  EXPECT_NE(messages[0].text.find("unknown type 77"), std::string::npos);
  EXPECT_NE(messages[1].text.find("without a name"), std::string::npos);
  EXPECT_NE(messages[2].text.find("'nodata' has no data"), std::string::npos);
  EXPECT_NE(messages[3].text.find("'negative' has a negative arraylength"),
      std::string::npos);
  for (auto &m : messages)
    EXPECT_EQ(m.level, NSIErrError);
  const std::string text = readFile(file);
  EXPECT_NE(text.find("SetAttribute \"x\"\n  \"good\" \"int[2]\" 1 [ 4 5 ]\n"),
      std::string::npos)
      << text;
  EXPECT_EQ(text.find("badtype"), std::string::npos);
}

TEST_F(ApiError, ConnectionCyclesAreRefused)
{
  NSICreate(m_ctx, "a", "transform", 0, nullptr);
  NSICreate(m_ctx, "b", "transform", 0, nullptr);
  NSICreate(m_ctx, "c", "transform", 0, nullptr);
  NSIConnect(m_ctx, "a", "", "b", "objects", 0, nullptr);
  NSIConnect(m_ctx, "b", "", "c", "objects", 0, nullptr);
  EXPECT_EQ(m_messages.problems(), "");
  NSIConnect(m_ctx, "c", "", "a", "objects", 0, nullptr);
  EXPECT_TRUE(reportedOnce(m_messages, {"cycle", "'c'"}));
  NSIConnect(m_ctx, "a", "", "a", "objects", 0, nullptr);
  EXPECT_TRUE(reportedOnce(m_messages, {"cycle"}));
  // The refused link is not there: rendering walks no loop (and ends).
  NSIConnect(m_ctx, "c", "", NSI_SCENE_ROOT, "objects", 0, nullptr);
  NSI::ArgumentList start;
  start.addString("action", "start");
  NSIRenderControl(m_ctx, start.size(), start.data());
  NSI::ArgumentList wait;
  wait.addString("action", "wait");
  NSIRenderControl(m_ctx, wait.size(), wait.data());
  EXPECT_EQ(m_messages.problems(NSIErrError), "");
}

// A connection's `value` (the spec's cross-hierarchy override, section
// 5.8) is a documented limit: the call is accepted, warned about once, and
// the connection made without the value.
TEST_F(ApiError, ConnectValueOverridesAreWarnedAndConnected)
{
  NSICreate(m_ctx, "ghost", "transform", 0, nullptr);
  NSICreate(m_ctx, "mirror", "attributes", 0, nullptr);
  NSI::ArgumentList args;
  args.addInteger("value", 1).addInteger("priority", 2);
  NSIConnect(
      m_ctx, "mirror", "", "ghost", "visibility", args.size(), args.data());
  const auto messages = m_messages.take();
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0].level, NSIErrWarning);
  EXPECT_NE(messages[0].text.find("'mirror' to 'ghost'.'visibility': 'value' "
                                  "overrides are not supported"),
      std::string::npos)
      << messages[0].text;
  // The connection stands: linking back would close a loop.
  NSIConnect(m_ctx, "ghost", "", "mirror", "objects", 0, nullptr);
  EXPECT_TRUE(reportedOnce(m_messages, {"cycle"}));
}

TEST_F(ApiError, NodeTypesAndBuiltIns)
{
  NSICreate(m_ctx, "n", "transform", 0, nullptr);
  NSICreate(m_ctx, "n", "transform", 0, nullptr); // shared: fine
  EXPECT_EQ(m_messages.problems(), "");
  NSICreate(m_ctx, "n", "mesh", 0, nullptr);
  EXPECT_TRUE(reportedOnce(m_messages, {"'n'", "'transform'", "'mesh'"}));
  NSIDelete(m_ctx, NSI_SCENE_ROOT, 0, nullptr);
  EXPECT_TRUE(reportedOnce(m_messages, {"'.root' cannot be deleted"}));
  NSIDelete(m_ctx, NSI_SCENE_GLOBAL, 0, nullptr);
  EXPECT_TRUE(reportedOnce(m_messages, {"'.global' cannot be deleted"}));
  NSICreate(m_ctx, NSI_ALL_NODES, "transform", 0, nullptr);
  EXPECT_TRUE(reportedOnce(m_messages, {"not a usable handle"}));
}

TEST_F(ApiError, EvaluateAndRenderControl)
{
  NSI::ArgumentList missing;
  missing.addString("type", "apistream")
      .addString("filename", path("absent.nsi").c_str());
  NSIEvaluate(m_ctx, missing.size(), missing.data());
  EXPECT_TRUE(reportedOnce(m_messages, {"cannot read", "absent.nsi"}));
  NSI::ArgumentList library;
  library.addString("type", "dynamiclibrary").addString("filename", "x.so");
  NSIEvaluate(m_ctx, library.size(), library.data());
  EXPECT_TRUE(reportedOnce(m_messages, {"cannot load", "x.so"}));
  NSI::ArgumentList odd;
  odd.addString("action", "dance");
  NSIRenderControl(m_ctx, odd.size(), odd.data());
  EXPECT_TRUE(reportedOnce(m_messages, {"unknown action 'dance'"}));
  // A binary stream is recognised and refused.
  const std::string binary =
      writeFile("binary.nsi", std::string("\x01\x02\x03nsi", 6));
  NSI::ArgumentList args;
  args.addString("type", "apistream").addString("filename", binary.c_str());
  NSIEvaluate(m_ctx, args.size(), args.data());
  EXPECT_TRUE(reportedOnce(m_messages, {"binary NSI"}));
}

TEST_F(ApiError, UnknownBeginTypeFails)
{
  NSI::ArgumentList args;
  args.addString("type", "cloud-of-llamas");
  args.addPointer("errorhandler",
      reinterpret_cast<const void *>(&MessageRecorder::handler));
  args.addPointer("errorhandlerdata", &m_messages);
  EXPECT_EQ(NSIBegin(args.size(), args.data()), NSI_BAD_CONTEXT);
  EXPECT_TRUE(
      reportedOnce(m_messages, {"unknown context type 'cloud-of-llamas'"}));
}

TEST_F(ApiError, SeveralThreadsOnOneContext)
{
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([this, t] {
      for (int i = 0; i < 200; ++i) {
        // A stream, not string concatenation: GCC 12 raises a false
        // -Wrestrict.
        std::ostringstream name;
        name << 'n' << t << '_' << i % 10;
        const std::string handle = name.str();
        NSICreate(m_ctx, handle.c_str(), "transform", 0, nullptr);
        NSIConnect(
            m_ctx, handle.c_str(), "", NSI_SCENE_ROOT, "objects", 0, nullptr);
        NSIDelete(m_ctx, handle.c_str(), 0, nullptr);
      }
    });
  }
  for (auto &t : threads)
    t.join();
  EXPECT_EQ(m_messages.problems(), "");
}

} // namespace
