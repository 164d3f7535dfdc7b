// A device of a library loaded through libanari, with its status messages
// kept: prism's (PrismDeviceTest), or the debug layer's (tests/debug).
#pragma once

#include "StatusRecorder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

class LibraryDeviceTest : public ::testing::Test
{
 protected:
  // `library` as anariLoadLibrary takes it (a string literal).
  explicit LibraryDeviceTest(const char *library) : m_libraryName(library) {}

  void SetUp() override
  {
    m_library =
        anariLoadLibrary(m_libraryName, StatusRecorder::callback, &m_status);
    ASSERT_NE(m_library, nullptr);
    m_device = anariNewDevice(m_library, "default");
    ASSERT_NE(m_device, nullptr);
  }
  void TearDown() override
  {
    if (m_device)
      anariRelease(m_device, m_device);
    anariUnloadLibrary(m_library);
  }

  // Messages at warning severity or worse, taken from the recorder.
  std::vector<StatusMessage> problems()
  {
    std::vector<StatusMessage> out;
    for (auto &m : m_status.take()) {
      if (m.severity <= ANARI_SEVERITY_WARNING)
        out.push_back(m);
    }
    return out;
  }
  // Exactly one problem with this severity and code mentioning `fragment`.
  ::testing::AssertionResult reported(ANARIStatusSeverity severity,
      ANARIStatusCode code,
      const std::string &fragment)
  {
    auto messages = problems();
    // A stream, not string concatenation: GCC 12 raises a false -Wrestrict.
    std::ostringstream all;
    for (auto &m : messages)
      all << "[" << m.severity << "/" << m.code << "] " << m.text << "\n";
    if (messages.size() == 1 && messages[0].severity == severity
        && messages[0].code == code
        && messages[0].text.find(fragment) != std::string::npos)
      return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "expected one message containing '" << fragment << "', got:\n"
           << all.str();
  }

  // A frame over an empty world with a perspective camera.
  ANARIFrame newFrame(ANARIRenderer renderer,
      uint32_t width,
      uint32_t height,
      ANARIDataType colorType = ANARI_FLOAT32_VEC4)
  {
    ANARIWorld world = anariNewWorld(m_device);
    ANARICamera camera = anariNewCamera(m_device, "perspective");
    anariCommitParameters(m_device, world);
    anariCommitParameters(m_device, camera);
    ANARIFrame frame =
        newFrameOf(world, camera, renderer, width, height, colorType);
    anariRelease(m_device, world);
    anariRelease(m_device, camera);
    return frame;
  }

  // A committed frame of these objects with one color channel.
  ANARIFrame newFrameOf(ANARIWorld world,
      ANARICamera camera,
      ANARIRenderer renderer,
      uint32_t width,
      uint32_t height,
      ANARIDataType colorType = ANARI_FLOAT32_VEC4)
  {
    ANARIFrame frame = anariNewFrame(m_device);
    const uint32_t size[2] = {width, height};
    anariSetParameter(m_device, frame, "world", ANARI_WORLD, &world);
    anariSetParameter(m_device, frame, "camera", ANARI_CAMERA, &camera);
    anariSetParameter(m_device, frame, "renderer", ANARI_RENDERER, &renderer);
    anariSetParameter(m_device, frame, "size", ANARI_UINT32_VEC2, size);
    anariSetParameter(
        m_device, frame, "channel.color", ANARI_DATA_TYPE, &colorType);
    anariCommitParameters(m_device, frame);
    return frame;
  }

  ANARIRenderer newRenderer(const float background[4])
  {
    ANARIRenderer renderer = anariNewRenderer(m_device, "default");
    anariSetParameter(
        m_device, renderer, "background", ANARI_FLOAT32_VEC4, background);
    anariCommitParameters(m_device, renderer);
    return renderer;
  }

  // Every pixel of a FLOAT32_VEC4 color channel after waiting (empty if
  // it cannot be mapped as that).
  std::vector<float> colorPixels(ANARIFrame frame)
  {
    anariFrameReady(m_device, frame, ANARI_WAIT);
    uint32_t w = 0, h = 0;
    ANARIDataType type = ANARI_UNKNOWN;
    auto *pixels = (const float *)anariMapFrame(
        m_device, frame, "channel.color", &w, &h, &type);
    std::vector<float> out;
    if (pixels && type == ANARI_FLOAT32_VEC4)
      out.assign(pixels, pixels + size_t(w) * h * 4);
    anariUnmapFrame(m_device, frame, "channel.color");
    return out;
  }
  // The first pixel of it (read alone: tests of large frames copy
  // nothing else).
  std::vector<float> firstPixel(ANARIFrame frame)
  {
    anariFrameReady(m_device, frame, ANARI_WAIT);
    uint32_t w = 0, h = 0;
    ANARIDataType type = ANARI_UNKNOWN;
    auto *pixels = (const float *)anariMapFrame(
        m_device, frame, "channel.color", &w, &h, &type);
    std::vector<float> out;
    if (pixels && type == ANARI_FLOAT32_VEC4)
      out.assign(pixels, pixels + 4);
    anariUnmapFrame(m_device, frame, "channel.color");
    return out;
  }

  const char *m_libraryName;
  StatusRecorder m_status;
  ANARILibrary m_library{nullptr};
  ANARIDevice m_device{nullptr};
};

class PrismDeviceTest : public LibraryDeviceTest
{
 protected:
  PrismDeviceTest() : LibraryDeviceTest("prism") {}
};
