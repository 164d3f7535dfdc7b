// Null, foreign, released and mistyped handles: reported by the layer at the
// call, never forwarded to the wrapped device.
#include "DebugLayerTestSupport.h"

using DebugHandles = DebugLayerTest;

TEST_F(DebugHandles, NullObject)
{
  anariCommitParameters(m_device, nullptr);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "anariCommitParameters(): object handle is NULL"));

  ANARIWorld world = anariNewWorld(m_device);
  anariCommitParameters(m_device, world);
  anariRelease(m_device, world);
  EXPECT_TRUE(silent());
}

TEST_F(DebugHandles, ForeignHandles)
{
  ANARIDevice other = anariNewDevice(m_library, "default");
  ASSERT_NE(other, nullptr);
  ANARIWorld theirs = anariNewWorld(other);
  anariCommitParameters(m_device, theirs);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "is not an object of this device"));
  int notAHandle = 0;
  anariCommitParameters(m_device, (ANARIObject)&notAHandle);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "is not an object of this device"));

  anariCommitParameters(other, theirs);
  anariRelease(other, theirs);
  anariRelease(other, other);
  EXPECT_TRUE(silent());
}

TEST_F(DebugHandles, UseAfterRelease)
{
  ANARIWorld world = anariNewWorld(m_device);
  anariRelease(m_device, world);
  anariCommitParameters(m_device, world);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "object handle is world #1, used after its release"));
  anariRelease(m_device, world);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "anariRelease(): object handle is world #1, used after its release"));

  // Retained once more, one release leaves it alive.
  ANARIWorld kept = anariNewWorld(m_device);
  anariRetain(m_device, kept);
  anariRelease(m_device, kept);
  anariCommitParameters(m_device, kept);
  anariRelease(m_device, kept);
  EXPECT_TRUE(silent());
}

TEST_F(DebugHandles, WrongTypeOfHandle)
{
  ANARIWorld world = anariNewWorld(m_device);
  ANARICamera camera = anariNewCamera(m_device, "perspective");
  ANARIFrame frame = anariNewFrame(m_device);

  anariSetParameter(m_device, frame, "camera", ANARI_CAMERA, &world);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "anariSetParameter(frame #3 'camera'): value is world #1, not camera"));
  EXPECT_EQ(anariMapArray(m_device, (ANARIArray)world), nullptr);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "array is world #1, not array"));
  anariRenderFrame(m_device, (ANARIFrame)camera);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "frame is camera perspective #2, not frame"));

  anariSetParameter(m_device, frame, "camera", ANARI_CAMERA, &camera);
  anariSetParameter(m_device, frame, "world", ANARI_WORLD, &world);
  EXPECT_TRUE(silent());
  anariRelease(m_device, frame);
  anariRelease(m_device, camera);
  anariRelease(m_device, world);
  EXPECT_TRUE(silent());
}

TEST_F(DebugHandles, StaleElementOfAnObjectArray)
{
  ANARISurface surface = anariNewSurface(m_device);
  anariRelease(m_device, surface);
  ANARIArray1D surfaces =
      anariNewArray1D(m_device, nullptr, nullptr, nullptr, ANARI_SURFACE, 1);
  auto *slots = (ANARISurface *)anariMapArray(m_device, surfaces);
  ASSERT_NE(slots, nullptr);
  slots[0] = surface;
  anariUnmapArray(m_device, surfaces);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "element 0: element handle is surface #1, used after its release"));

  ANARISurface live = anariNewSurface(m_device);
  slots = (ANARISurface *)anariMapArray(m_device, surfaces);
  slots[0] = live;
  anariUnmapArray(m_device, surfaces);
  anariRelease(m_device, live);
  anariRelease(m_device, surfaces);
  EXPECT_TRUE(silent());
}

// The wrapped device's own messages name the layer's handles.
TEST_F(DebugHandles, WrappedDeviceMessagesNameLayerHandles)
{
  ANARICamera camera = anariNewCamera(m_device, "perspective");
  const float fovy = 1.f;
  anariSetParameter(m_device, camera, "fovyy", ANARI_FLOAT32, &fovy);
  anariCommitParameters(m_device, camera);
  // A waiting query applies prism's deferred commit, which warns.
  int unused = 0;
  anariGetProperty(m_device,
      camera,
      "none",
      ANARI_INT32,
      &unused,
      sizeof(unused),
      ANARI_WAIT);
  bool sawWrapped = false;
  for (auto &m : takeProblems(m_status)) {
    if (!fromLayer(m) && m.text.find("fovyy") != std::string::npos) {
      sawWrapped = true;
      EXPECT_EQ(m.source, (ANARIObject)camera) << m.text;
    }
  }
  EXPECT_TRUE(sawWrapped);
  anariRelease(m_device, camera);
}

// Object values set on the device itself are checked like any other.
TEST_F(DebugHandles, StaleObjectValueOfADeviceParameter)
{
  ANARIWorld world = anariNewWorld(m_device);
  anariRelease(m_device, world);
  anariSetParameter(m_device, m_device, "someWorld", ANARI_WORLD, &world);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "anariSetParameter(device 'someWorld'): value handle is world #1, used "
      "after its release"));
}
