// Leaks at device release, the choice of the wrapped library, wrapping by
// environment variable, and many threads on one layer.
#include "DebugLayerTestSupport.h"

#include <cstdlib>
#include <thread>

using DebugLifetime = DebugLayerTest;

TEST_F(DebugLifetime, LeaksListedAtDeviceRelease)
{
  ANARIDevice device = anariNewDevice(m_library, "default");
  ASSERT_NE(device, nullptr);
  ANARIWorld released = anariNewWorld(device);
  anariRelease(device, released);
  ANARIGeometry geometry = anariNewGeometry(device, "sphere");
  ANARIMaterial material = anariNewMaterial(device, "matte");
  anariSetParameter(device, material, "name", ANARI_STRING, "shiny");
  (void)geometry;
  anariRelease(device, device);

  std::vector<std::string> layer;
  for (auto &m : takeProblems(m_status)) {
    if (fromLayer(m)) {
      EXPECT_EQ(m.severity, ANARI_SEVERITY_WARNING);
      EXPECT_EQ(m.code, ANARI_STATUS_NO_ERROR);
      layer.push_back(m.text);
    }
  }
  ASSERT_EQ(layer.size(), 3u);
  EXPECT_NE(
      layer[0].find("device released with 2 object(s)"), std::string::npos);
  EXPECT_NE(layer[1].find("leaked geometry sphere #2, created by "
                          "anariNewGeometry (API call 3)"),
      std::string::npos)
      << layer[1];
  EXPECT_NE(layer[2].find("leaked material matte #3 \"shiny\", created by "
                          "anariNewMaterial (API call 4)"),
      std::string::npos)
      << layer[2];
}

TEST_F(DebugLifetime, NoLeakReportWhenAllIsReleased)
{
  ANARIDevice device = anariNewDevice(m_library, "default");
  ANARIGeometry geometry = anariNewGeometry(device, "sphere");
  anariRelease(device, geometry);
  anariRelease(device, device);
  EXPECT_TRUE(silent());
}

TEST_F(DebugLifetime, WrappedLibraryParameter)
{
  anariSetParameter(
      m_device, m_device, "wrappedLibrary", ANARI_STRING, "nosuch");
  anariCommitParameters(m_device, m_device);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "cannot load the wrapped library 'nosuch'"));
  // Still wrapping prism.
  ANARIGeometry geometry = anariNewGeometry(m_device, "triangle");
  EXPECT_TRUE(silent());
  anariSetParameter(
      m_device, m_device, "wrappedLibrary", ANARI_STRING, "prism");
  anariSetParameter(
      m_device, m_device, "wrappedLibrary", ANARI_STRING, "recording");
  anariCommitParameters(m_device, m_device);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "'wrappedLibrary' and 'wrappedDevice' can change only before the first "
      "object"));
  anariRelease(m_device, geometry);

  // Chosen at creation instead.
  const char *prism = "prism";
  ANARIParameterValue initial[] = {{"wrappedLibrary", ANARI_STRING, prism},
      {nullptr, ANARI_UNKNOWN, nullptr}};
  ANARIDevice device = anariNewInitializedDevice(m_library, "default", initial);
  ASSERT_NE(device, nullptr);
  ANARIWorld world = anariNewWorld(device);
  anariCommitParameters(device, world);
  anariRelease(device, world);
  anariRelease(device, device);
  EXPECT_TRUE(silent());
}

TEST_F(DebugLifetime, WrappedDeviceParameter)
{
  // The device subtype of the wrapped library, as wrappedLibrary.
  anariSetParameter(
      m_device, m_device, "wrappedDevice", ANARI_STRING, "nosuch");
  anariCommitParameters(m_device, m_device);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "created no device of subtype 'nosuch'; keeping 'prism' device "
      "'default'"));
  anariSetParameter(m_device, m_device, "wrappedDevice", ANARI_STRING, "prism");
  anariCommitParameters(m_device, m_device);
  EXPECT_TRUE(silent());
  ANARIWorld world = anariNewWorld(m_device);
  anariSetParameter(
      m_device, m_device, "wrappedDevice", ANARI_STRING, "default");
  anariCommitParameters(m_device, m_device);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "can change only before the first object is created; keeping 'prism' "
      "device 'prism'"));
  anariRelease(m_device, world);

  // At creation, and by environment variable: the layer's device subtype
  // need not be the wrapped library's.
  ANARIParameterValue initial[] = {{"wrappedDevice", ANARI_STRING, "prism"},
      {nullptr, ANARI_UNKNOWN, nullptr}};
  ANARIDevice device = anariNewInitializedDevice(m_library, "mine", initial);
  ASSERT_NE(device, nullptr);
  anariRelease(device, device);
  EXPECT_EQ(anariNewDevice(m_library, "mine"), nullptr);
  m_status.take();
  ASSERT_EQ(setenv("ANARI_DEBUG_WRAPPED_DEVICE", "prism", 1), 0);
  device = anariNewDevice(m_library, "mine");
  unsetenv("ANARI_DEBUG_WRAPPED_DEVICE");
  ASSERT_NE(device, nullptr);
  anariRelease(device, device);
  EXPECT_TRUE(silent());
}

TEST_F(DebugLifetime, ExtensionFunctionsAreNotHandedOut)
{
  // Prism has none; the layer hands out none, and says nothing of it.
  EXPECT_EQ(anariDeviceGetProcAddress(m_device, "anariNewSomething"), nullptr);
  EXPECT_TRUE(silent());
}

TEST(DebugLayerEnvironment, WrapsWhateverTheApplicationLoads)
{
  StatusRecorder status;
  ASSERT_EQ(setenv("ANARI_DEBUG_LAYER", "1", 1), 0);
  ANARILibrary library =
      anariLoadLibrary("prism", StatusRecorder::callback, &status);
  unsetenv("ANARI_DEBUG_LAYER");
  ASSERT_NE(library, nullptr);
  ANARIDevice device = anariNewDevice(library, "default");
  ASSERT_NE(device, nullptr);
  anariCommitParameters(device, nullptr);
  auto problems = takeProblems(status);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].text, "anariCommitParameters(): object handle is NULL");
  anariRelease(device, device);
  anariUnloadLibrary(library);

  // Without the variable, prism itself answers, in its own words.
  library = anariLoadLibrary("prism", StatusRecorder::callback, &status);
  device = anariNewDevice(library, "default");
  anariCommitParameters(device, nullptr);
  problems = takeProblems(status);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_FALSE(fromLayer(problems[0])) << problems[0].text;
  anariRelease(device, device);
  anariUnloadLibrary(library);
}

TEST_F(DebugLifetime, ManyThreadsOnOneDevice)
{
  const float sphere[3] = {0, 0, 0};
  auto work = [&] {
    for (int i = 0; i < 200; ++i) {
      ANARIGeometry geometry = anariNewGeometry(m_device, "sphere");
      ANARIArray1D positions = anariNewArray1D(
          m_device, sphere, nullptr, nullptr, ANARI_FLOAT32_VEC3, 1);
      anariSetParameter(
          m_device, geometry, "vertex.position", ANARI_ARRAY1D, &positions);
      anariCommitParameters(m_device, geometry);
      anariRelease(m_device, positions);
      anariRelease(m_device, geometry);
    }
  };
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back(work);
  for (auto &t : threads)
    t.join();
  EXPECT_TRUE(silent());
}

namespace {

struct Completion
{
  const void *userData = &userData; // not NULL until a call sets it
  ANARIFrame frame = nullptr;
  int calls = 0;
};
Completion g_completion;

void onFrameDone(const void *userData, ANARIDevice, ANARIFrame frame)
{
  g_completion.userData = userData;
  g_completion.frame = frame;
  g_completion.calls++;
}

} // namespace

// Found by fuzzing through the layer: a completion callback set with no
// user data (or its user data unset) reached the layer's trampoline with
// NULL for the layer.
TEST_F(DebugLifetime, CompletionCallbackWithoutUserData)
{
  ANARIWorld world = anariNewWorld(m_device);
  ANARICamera camera = anariNewCamera(m_device, "perspective");
  ANARIRenderer renderer = anariNewRenderer(m_device, "default");
  for (ANARIObject o :
      {(ANARIObject)world, (ANARIObject)camera, (ANARIObject)renderer})
    anariCommitParameters(m_device, o);
  ANARIFrame frame = anariNewFrame(m_device);
  const uint32_t size[2] = {4, 4};
  anariSetParameter(m_device, frame, "world", ANARI_WORLD, &world);
  anariSetParameter(m_device, frame, "camera", ANARI_CAMERA, &camera);
  anariSetParameter(m_device, frame, "renderer", ANARI_RENDERER, &renderer);
  anariSetParameter(m_device, frame, "size", ANARI_UINT32_VEC2, size);
  ANARIFrameCompletionCallback callback = onFrameDone;
  anariSetParameter(m_device,
      frame,
      "frameCompletionCallback",
      ANARI_FRAME_COMPLETION_CALLBACK,
      &callback);
  anariCommitParameters(m_device, frame);
  g_completion = {};
  anariRenderFrame(m_device, frame);
  anariFrameReady(m_device, frame, ANARI_WAIT);
  EXPECT_EQ(g_completion.calls, 1);
  EXPECT_EQ(g_completion.userData, nullptr);
  EXPECT_EQ(g_completion.frame, frame);

  int mine = 0;
  anariSetParameter(m_device,
      frame,
      "frameCompletionCallbackUserData",
      ANARI_VOID_POINTER,
      &mine);
  anariUnsetParameter(m_device, frame, "frameCompletionCallbackUserData");
  anariCommitParameters(m_device, frame);
  anariRenderFrame(m_device, frame);
  anariFrameReady(m_device, frame, ANARI_WAIT);
  EXPECT_EQ(g_completion.calls, 2);
  EXPECT_EQ(g_completion.userData, nullptr);
  for (ANARIObject o : {(ANARIObject)frame,
           (ANARIObject)renderer,
           (ANARIObject)camera,
           (ANARIObject)world})
    anariRelease(m_device, o);
  EXPECT_TRUE(silent());
}
