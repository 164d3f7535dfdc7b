// The debug layer wrapped around prism, loaded through libanari, with every
// status message kept (and its source object) for assertions.
#pragma once

#include "DeviceTestSupport.h"
#include "StatusRecorder.h"

#include <anari/anari.h>
#include <gtest/gtest.h>

#include <cctype>
#include <sstream>
#include <string>
#include <vector>

using LayerMessage = StatusMessage;

// Messages at warning severity or worse, taken from the recorder.
inline std::vector<LayerMessage> takeProblems(StatusRecorder &recorder)
{
  std::vector<LayerMessage> out;
  for (auto &m : recorder.take()) {
    if (m.severity <= ANARI_SEVERITY_WARNING)
      out.push_back(m);
  }
  return out;
}

// The layer's own messages name the call: "anariSetParameter(...): ...".
inline bool fromLayer(const LayerMessage &m)
{
  const std::string &t = m.text;
  if (t.rfind("anari", 0) != 0)
    return false;
  size_t i = 5;
  while (i < t.size() && std::isalnum((unsigned char)t[i]))
    ++i;
  return i > 5 && i < t.size() && t[i] == '(';
}

class DebugLayerTest : public LibraryDeviceTest
{
 protected:
  DebugLayerTest() : LibraryDeviceTest("debug") {}

  // Exactly one of the layer's messages since the last call, with this
  // severity and code and a text containing `fragment` (the wrapped
  // device's own messages about the same call are left aside).
  // Exactly one problem at all: the layer's. A call the layer refused
  // never reaches the wrapped device, and the wrapped device's own report
  // of a problem the layer reported is withheld (WithheldReports).
  ::testing::AssertionResult onlyLayerReported(ANARIStatusSeverity severity,
      ANARIStatusCode code,
      const std::string &fragment)
  {
    auto problems = takeProblems(m_status);
    std::ostringstream all;
    for (auto &m : problems)
      all << "[" << m.severity << "/" << m.code << "] " << m.text << "\n";
    if (problems.size() == 1 && fromLayer(problems[0])
        && problems[0].severity == severity && problems[0].code == code
        && problems[0].text.find(fragment) != std::string::npos)
      return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "expected only one layer message containing '" << fragment
           << "', got:\n"
           << all.str();
  }
  // No problem reported since the last call.
  ::testing::AssertionResult silent()
  {
    auto problems = takeProblems(m_status);
    if (problems.empty())
      return ::testing::AssertionSuccess();
    std::ostringstream all;
    for (auto &m : problems)
      all << "[" << m.severity << "/" << m.code << "] " << m.text << "\n";
    return ::testing::AssertionFailure() << "unexpected:\n" << all.str();
  }

  ANARIArray1D floatArray(ANARIDataType type, const float *data, uint64_t n)
  {
    return anariNewArray1D(m_device, data, nullptr, nullptr, type, n);
  }
};
