// Image tests: a scene built through the public C API on the prism device
// (loaded by libanari), rendered small and compared with the committed
// reference references/<Scene>.<Renderer>.png under the tolerance that
// tolerances.txt gives it. See README.md.
#pragma once

#include "ImageIO.h"
#include "StatusRecorder.h"

#include <anari/anari.h>
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

// The fixture of every render test: TEST_F(<Scene>, <Renderer>) with
// `using <Scene> = RenderTest;`, so ctest names it render::<Scene>.<Renderer>.
class RenderTest : public ::testing::Test
{
 protected:
  void SetUp() override;
  // Releases the objects the fixture owns and fails on device problems.
  void TearDown() override;

  ANARIDevice device() const
  {
    return m_device;
  }

  // New objects, owned by the fixture and released in TearDown.
  ANARIWorld newWorld();
  // `subtype` empty: the renderer the test is named for ("PathTracer" ->
  // "pathTracer").
  ANARIRenderer newRenderer(const std::string &subtype = {});
  // A committed perspective camera; positions in world space, fovy in radians.
  ANARICamera newPerspectiveCamera(const std::array<float, 3> &position,
      const std::array<float, 3> &direction,
      const std::array<float, 3> &up,
      float aspect,
      float fovy = 3.14159265f / 3.f);
  // Managed arrays holding a copy of `data` (elements of `type`).
  ANARIArray1D newArray1D(ANARIDataType type, const void *data, uint64_t count);
  ANARIArray2D newArray2D(
      ANARIDataType type, const void *data, uint64_t width, uint64_t height);
  // Hands any object to the fixture, to be released in TearDown.
  template <typename T>
  T keep(T object)
  {
    m_objects.push_back(object);
    return object;
  }

  // One frame's channel.color as linear float RGBA, row 0 at the bottom;
  // empty (after a test failure) when the device does not deliver it.
  prism::image::Image render(ANARIWorld world,
      ANARICamera camera,
      ANARIRenderer renderer,
      uint32_t width,
      uint32_t height);

  // Renders (width, height <= 256) and compares with the reference `name`
  // (empty: "<Scene>.<Renderer>" of this test); every mismatch, missing
  // reference or device warning is a test failure. With
  // PRISM_UPDATE_REFERENCES=1 it rewrites the reference instead.
  bool renderAndCompare(ANARIWorld world,
      ANARICamera camera,
      ANARIRenderer renderer,
      uint32_t width,
      uint32_t height,
      const std::string &name = {});

 private:
  // Fails the test for each message of warning severity or worse so far.
  void expectNoDeviceProblems(const char *when);

  StatusRecorder m_status;
  ANARILibrary m_library{nullptr};
  ANARIDevice m_device{nullptr};
  std::vector<ANARIObject> m_objects;
};
