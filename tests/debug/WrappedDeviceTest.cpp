// The layer as VTK wires it: the application creates the device and hands
// it to the layer as the `wrappedDevice` ANARI_DEVICE parameter, with the
// ANARI-SDK debug device's `traceDir`/`traceMode`. The layer renders
// through that device, reports as it does around a device of its own,
// writes its trace into traceDir, and never releases the device it did not
// create; bad handles and values are reported.
#include "DebugLayerTestSupport.h"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

class WrappedDevice : public DebugLayerTest
{
 protected:
  void TearDown() override
  {
    DebugLayerTest::TearDown();
    if (m_appDevice)
      anariRelease(m_appDevice, m_appDevice);
    if (m_appLibrary)
      anariUnloadLibrary(m_appLibrary);
  }
  // The application's own device of `library`, its messages kept apart.
  ANARIDevice appDevice(const char *library)
  {
    m_appLibrary =
        anariLoadLibrary(library, StatusRecorder::callback, &m_appStatus);
    m_appDevice =
        m_appLibrary ? anariNewDevice(m_appLibrary, "default") : nullptr;
    return m_appDevice;
  }
  void handOver(ANARIDevice device)
  {
    anariSetParameter(
        m_device, m_device, "wrappedDevice", ANARI_DEVICE, &device);
    anariCommitParameters(m_device, m_device);
  }
  // A unit sphere seen from z = 3, raycast at 16x16 on `device`; the
  // center pixel's red (the background is black).
  float renderSphere(ANARIDevice device)
  {
    ANARIGeometry sphere = anariNewGeometry(device, "sphere");
    const float center[3] = {0, 0, 0}, radius = 1.f;
    ANARIArray1D positions = anariNewArray1D(
        device, center, nullptr, nullptr, ANARI_FLOAT32_VEC3, 1);
    anariSetParameter(
        device, sphere, "vertex.position", ANARI_ARRAY1D, &positions);
    anariSetParameter(device, sphere, "radius", ANARI_FLOAT32, &radius);
    anariCommitParameters(device, sphere);
    ANARIMaterial matte = anariNewMaterial(device, "matte");
    anariCommitParameters(device, matte);
    ANARISurface surface = anariNewSurface(device);
    anariSetParameter(device, surface, "geometry", ANARI_GEOMETRY, &sphere);
    anariSetParameter(device, surface, "material", ANARI_MATERIAL, &matte);
    anariCommitParameters(device, surface);
    ANARIArray1D surfaces =
        anariNewArray1D(device, &surface, nullptr, nullptr, ANARI_SURFACE, 1);
    ANARIWorld world = anariNewWorld(device);
    anariSetParameter(device, world, "surface", ANARI_ARRAY1D, &surfaces);
    anariCommitParameters(device, world);
    ANARICamera camera = anariNewCamera(device, "perspective");
    const float eye[3] = {0, 0, 3};
    anariSetParameter(device, camera, "position", ANARI_FLOAT32_VEC3, eye);
    anariCommitParameters(device, camera);
    ANARIRenderer renderer = anariNewRenderer(device, "raycast");
    anariCommitParameters(device, renderer);
    ANARIFrame frame = anariNewFrame(device);
    const uint32_t size[2] = {16, 16};
    const ANARIDataType color = ANARI_FLOAT32_VEC4;
    anariSetParameter(device, frame, "size", ANARI_UINT32_VEC2, size);
    anariSetParameter(device, frame, "channel.color", ANARI_DATA_TYPE, &color);
    anariSetParameter(device, frame, "world", ANARI_WORLD, &world);
    anariSetParameter(device, frame, "camera", ANARI_CAMERA, &camera);
    anariSetParameter(device, frame, "renderer", ANARI_RENDERER, &renderer);
    anariCommitParameters(device, frame);
    anariRenderFrame(device, frame);
    anariFrameReady(device, frame, ANARI_WAIT);
    uint32_t width = 0, height = 0;
    ANARIDataType type = ANARI_UNKNOWN;
    const auto *pixels = (const float *)anariMapFrame(
        device, frame, "channel.color", &width, &height, &type);
    const float red =
        pixels && width == 16 && height == 16 ? pixels[4 * (8 * 16 + 8)] : -1.f;
    anariUnmapFrame(device, frame, "channel.color");
    for (ANARIObject o : {(ANARIObject)frame,
             (ANARIObject)renderer,
             (ANARIObject)camera,
             (ANARIObject)world,
             (ANARIObject)surfaces,
             (ANARIObject)surface,
             (ANARIObject)matte,
             (ANARIObject)positions,
             (ANARIObject)sphere})
      anariRelease(device, o);
    return red;
  }
  // A fresh, empty folder for a trace.
  std::string traceFolder()
  {
    char pattern[] = "/tmp/prism-debug-trace-XXXXXX";
    const char *made = mkdtemp(pattern);
    return made ? made : "";
  }

  StatusRecorder m_appStatus;
  ANARILibrary m_appLibrary{nullptr};
  ANARIDevice m_appDevice{nullptr};
};

TEST_F(WrappedDevice, RendersThroughTheApplicationsDeviceAndTracesToTraceDir)
{
  ANARIDevice app = appDevice("prism");
  ASSERT_NE(app, nullptr);
  const std::string folder = traceFolder();
  ASSERT_FALSE(folder.empty());
  anariSetParameter(
      m_device, m_device, "traceDir", ANARI_STRING, folder.c_str());
  anariSetParameter(m_device, m_device, "traceMode", ANARI_STRING, "prism");
  handOver(app);
  EXPECT_TRUE(silent());

  EXPECT_GT(renderSphere(m_device), 0.1f);
  EXPECT_TRUE(silent());
  // Reports as before: a value of the wrong type, the layer's words.
  ANARICamera camera = anariNewCamera(m_device, "perspective");
  const float notAVector = 1.f;
  anariSetParameter(m_device, camera, "position", ANARI_FLOAT32, &notAVector);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "anariSetParameter(camera perspective"));
  anariRelease(m_device, camera);
  // The objects live in the application's device: its own messages reach
  // the application's callback (prism's, of a value the layer does not
  // range-check, told when the device next flushes its commits).
  ANARIRenderer renderer = anariNewRenderer(m_device, "raycast");
  const int32_t negative = -1;
  anariSetParameter(m_device, renderer, "sampleLimit", ANARI_INT32, &negative);
  anariCommitParameters(m_device, renderer);
  anariRelease(m_device, renderer);

  // Releasing the layer leaves the application's device alive and usable.
  anariRelease(m_device, m_device);
  m_device = nullptr;
  EXPECT_GT(renderSphere(app), 0.1f);
  std::vector<std::string> problems;
  for (const StatusMessage &m : m_appStatus.take()) {
    if (m.severity <= ANARI_SEVERITY_WARNING)
      problems.push_back(m.text);
  }
  ASSERT_EQ(problems.size(), 1u)
      << (problems.empty() ? std::string("none") : problems[0]);
  EXPECT_NE(
      problems[0].find("'sampleLimit' (-1) must be >= 0"), std::string::npos)
      << problems[0];

  std::ifstream file(folder + "/anari.trace");
  ASSERT_TRUE(file.good()) << folder;
  std::stringstream text;
  text << file.rdbuf();
  EXPECT_NE(text.str().find("New o1 GEOMETRY \"sphere\""), std::string::npos)
      << text.str().substr(0, 400);
  EXPECT_NE(text.str().find("Render o"), std::string::npos);
  EXPECT_NE(text.str().find("the application created and handed over"),
      std::string::npos);
  std::remove((folder + "/anari.trace").c_str());
  std::remove((folder + "/anari.trace.bin").c_str());
  rmdir(folder.c_str());
}

// The recording device counts its live devices and logs its last call: the
// layer's release neither releases it nor calls it at all.
TEST_F(WrappedDevice, TheApplicationsDeviceIsNeverReleasedByTheLayer)
{
  ANARIDevice app = appDevice("recording");
  ASSERT_NE(app, nullptr);
  auto liveDevices =
      (int (*)(void))anariDeviceGetProcAddress(app, "recordingLiveDevices");
  auto lastCall = (const char *(*)(void))anariDeviceGetProcAddress(
      app, "recordingLastCall");
  ASSERT_TRUE(liveDevices && lastCall);
  const int live = liveDevices();
  handOver(app);
  EXPECT_TRUE(silent());
  ANARIWorld world = anariNewWorld(m_device);
  EXPECT_NE(std::string(lastCall()).find("newWorld"), std::string::npos)
      << lastCall();
  anariRelease(m_device, world);
  anariRelease(m_device, m_device);
  m_device = nullptr;
  EXPECT_EQ(liveDevices(), live);
  char device[32];
  std::snprintf(device, sizeof(device), "release(%p)", (void *)app);
  EXPECT_EQ(std::string(lastCall()).find(device), std::string::npos)
      << lastCall();
  anariRelease(app, app);
  m_appDevice = nullptr;
  EXPECT_EQ(liveDevices(), live - 1);
}

TEST_F(WrappedDevice, BadHandlesAndValuesAreReported)
{
  const int32_t number = 3;
  anariSetParameter(m_device, m_device, "wrappedDevice", ANARI_INT32, &number);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "type must be ANARI_STRING (a device subtype) or ANARI_DEVICE"));
  handOver(nullptr);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "the device handle is NULL"));
  handOver(m_device);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "the device handle is this debug device itself"));
  // A device the application already released: libanari knows it is gone.
  ANARIDevice gone = appDevice("prism");
  ASSERT_NE(gone, nullptr);
  anariRelease(gone, gone);
  m_appDevice = nullptr;
  handOver(gone);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "is not a live device (released, or never created)"));
  // The layer still wraps its own prism device.
  ANARIWorld world = anariNewWorld(m_device);
  EXPECT_NE(world, nullptr);
  anariRelease(m_device, world);
  EXPECT_TRUE(silent());

  anariSetParameter(m_device, m_device, "traceMode", ANARI_STRING, "code");
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_WARNING,
      ANARI_STATUS_INVALID_ARGUMENT,
      "C-code traces are not written"));
  anariSetParameter(m_device, m_device, "traceDir", ANARI_FLOAT32, &number);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "type must be ANARI_STRING"));
  anariSetParameter(
      m_device, m_device, "traceDir", ANARI_STRING, "/nonexistent/folder");
  anariCommitParameters(m_device, m_device);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "cannot write the trace '/nonexistent/folder/anari.trace'"));
}

// Once objects exist, the device wrapped stays.
TEST_F(WrappedDevice, HandedOverOnlyBeforeTheFirstObject)
{
  ANARIDevice app = appDevice("prism");
  ASSERT_NE(app, nullptr);
  ANARIWorld world = anariNewWorld(m_device);
  handOver(app);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "'wrappedDevice' can change only before the first object"));
  anariRelease(m_device, world);
}

} // namespace
