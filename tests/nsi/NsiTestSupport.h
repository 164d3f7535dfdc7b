// Shared pieces of the NSI tests: an error handler that records messages, a
// fresh temporary folder per test, and files written from text.
#pragma once

#include <nsi.hpp>

#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

struct NsiMessage
{
  int level;
  std::string text;
};

class MessageRecorder
{
 public:
  static void handler(void *userdata, int level, int, const char *message)
  {
    auto *self = static_cast<MessageRecorder *>(userdata);
    std::lock_guard lock(self->m_mutex);
    self->m_messages.push_back({level, message ? message : ""});
  }
  std::vector<NsiMessage> take()
  {
    std::lock_guard lock(m_mutex);
    return std::exchange(m_messages, {});
  }
  // The messages at `level` or above, one per line, for assertion output.
  std::string problems(int level = NSIErrWarning)
  {
    std::ostringstream out;
    for (auto &m : take()) {
      if (m.level >= level)
        out << m.level << ": " << m.text << "\n";
    }
    return out.str();
  }

 private:
  std::mutex m_mutex;
  std::vector<NsiMessage> m_messages;
};

// Exactly one message at NSIErrError, containing every fragment.
inline ::testing::AssertionResult reportedOnce(
    MessageRecorder &recorder, std::initializer_list<const char *> fragments)
{
  auto messages = recorder.take();
  std::ostringstream all;
  int errors = 0;
  const NsiMessage *error = nullptr;
  for (auto &m : messages) {
    all << "[" << m.level << "] " << m.text << "\n";
    if (m.level == NSIErrError) {
      ++errors;
      error = &m;
    }
  }
  bool ok = errors == 1;
  for (const char *f : fragments)
    ok = ok && error->text.find(f) != std::string::npos;
  if (ok)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "expected one error with the fragments, got:\n"
         << all.str();
}

class NsiTest : public ::testing::Test
{
 protected:
  void SetUp() override
  {
    const auto *info = ::testing::UnitTest::GetInstance()->current_test_info();
    m_dir = std::filesystem::temp_directory_path()
            / ("prism-nsi-" + std::to_string(::getpid()) + "-"
                + info->test_suite_name() + "-" + info->name());
    std::filesystem::remove_all(m_dir);
    std::filesystem::create_directories(m_dir);
  }
  void TearDown() override
  {
    if (!HasFailure())
      std::filesystem::remove_all(m_dir);
  }

  std::string path(const std::string &name) const
  {
    return (m_dir / name).string();
  }
  std::string writeFile(const std::string &name, const std::string &text) const
  {
    std::ofstream(path(name), std::ios::binary) << text;
    return path(name);
  }
  static std::string readFile(const std::string &file)
  {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
  }

  // A render context reporting to m_messages.
  NSIContext_t beginRender()
  {
    NSI::ArgumentList args;
    args.addPointer("errorhandler",
        reinterpret_cast<const void *>(&MessageRecorder::handler));
    args.addPointer("errorhandlerdata", &m_messages);
    return NSIBegin(args.size(), args.data());
  }
  // A context writing the calls it gets to `file`; the Evaluate types in
  // `executed` ("apistream", "lua" ...) are run and their calls written.
  NSIContext_t beginStream(
      const std::string &file, const char *executed = nullptr)
  {
    NSI::ArgumentList args;
    args.addString("type", "apistream")
        .addString("streamfilename", file.c_str());
    if (executed)
      args.addString("executeprocedurals", executed);
    args.addPointer("errorhandler",
        reinterpret_cast<const void *>(&MessageRecorder::handler));
    args.addPointer("errorhandlerdata", &m_messages);
    return NSIBegin(args.size(), args.data());
  }
  // Reads stream `file` into `ctx`.
  static void include(NSIContext_t ctx, const std::string &file)
  {
    NSI::ArgumentList args;
    args.addString("type", "apistream").addString("filename", file.c_str());
    NSIEvaluate(ctx, args.size(), args.data());
  }

  std::filesystem::path m_dir;
  MessageRecorder m_messages;
};
