// Every C entry point reaches the device with its arguments intact.
#include "StatusRecorder.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace {

class FrontEndDispatch : public ::testing::Test
{
 protected:
  void SetUp() override
  {
    m_library =
        anariLoadLibrary("recording", StatusRecorder::callback, &m_status);
    ASSERT_NE(m_library, nullptr);
    m_device = anariNewDevice(m_library, "default");
    ASSERT_NE(m_device, nullptr);
    m_lastCall = (const char *(*)(void))anariDeviceGetProcAddress(
        m_device, "recordingLastCall");
    ASSERT_NE(m_lastCall, nullptr);
  }
  void TearDown() override
  {
    anariRelease(m_device, m_device);
    anariUnloadLibrary(m_library);
    EXPECT_TRUE(m_status.take().empty());
  }

  std::string last() const
  {
    return m_lastCall();
  }
  static std::string ptr(const void *p)
  {
    char buffer[32];
    std::snprintf(buffer, sizeof(buffer), "%p", p);
    return buffer;
  }

  StatusRecorder m_status;
  ANARILibrary m_library{nullptr};
  ANARIDevice m_device{nullptr};
  const char *(*m_lastCall)(void){nullptr};
};

void deleter(const void *, const void *) {}

TEST_F(FrontEndDispatch, ArraysKeepMemoryDeleterUserPointerTypeAndSizes)
{
  const float data[4] = {};
  const void *user = (const void *)0x77;
  auto d = ptr((const void *)&deleter);
  ANARIArray1D a1 =
      anariNewArray1D(m_device, data, deleter, user, ANARI_FLOAT32, 4);
  EXPECT_EQ(last(),
      "newArray1D(" + ptr(data) + ", " + d + ", " + ptr(user) + ", 1068, 4)");
  EXPECT_EQ(a1, (ANARIArray1D)0x1001);
  ANARIArray2D a2 = anariNewArray2D(
      m_device, nullptr, nullptr, nullptr, ANARI_UFIXED8_VEC4, 3, 5);
  EXPECT_EQ(last(), "newArray2D((nil), (nil), (nil), 1039, 3, 5)");
  EXPECT_EQ(a2, (ANARIArray2D)0x1002);
  ANARIArray3D a3 = anariNewArray3D(
      m_device, nullptr, nullptr, nullptr, ANARI_FLOAT64, 1ull << 33, 2, 9);
  EXPECT_EQ(last(), "newArray3D((nil), (nil), (nil), 1072, 8589934592, 2, 9)");
  EXPECT_EQ(a3, (ANARIArray3D)0x1003);
  EXPECT_NE(anariMapArray(m_device, a1), nullptr);
  EXPECT_EQ(last(), "mapArray(0x1001)");
  anariUnmapArray(m_device, a1);
  EXPECT_EQ(last(), "unmapArray(0x1001)");
}

TEST_F(FrontEndDispatch, ObjectCreationPassesSubtypes)
{
  EXPECT_EQ(anariNewGeometry(m_device, "triangle"), (ANARIGeometry)0x1004);
  EXPECT_EQ(last(), "newGeometry(triangle)");
  EXPECT_EQ(anariNewMaterial(m_device, "matte"), (ANARIMaterial)0x1005);
  EXPECT_EQ(last(), "newMaterial(matte)");
  EXPECT_EQ(anariNewSampler(m_device, "image2D"), (ANARISampler)0x1006);
  EXPECT_EQ(last(), "newSampler(image2D)");
  EXPECT_EQ(anariNewSurface(m_device), (ANARISurface)0x1007);
  EXPECT_EQ(last(), "newSurface()");
  EXPECT_EQ(anariNewSpatialField(m_device, "structuredRegular"),
      (ANARISpatialField)0x1008);
  EXPECT_EQ(last(), "newSpatialField(structuredRegular)");
  EXPECT_EQ(
      anariNewVolume(m_device, "transferFunction1D"), (ANARIVolume)0x1009);
  EXPECT_EQ(last(), "newVolume(transferFunction1D)");
  EXPECT_EQ(anariNewLight(m_device, "point"), (ANARILight)0x100a);
  EXPECT_EQ(last(), "newLight(point)");
  EXPECT_EQ(anariNewGroup(m_device), (ANARIGroup)0x100b);
  EXPECT_EQ(last(), "newGroup()");
  EXPECT_EQ(anariNewInstance(m_device, "transform"), (ANARIInstance)0x100c);
  EXPECT_EQ(last(), "newInstance(transform)");
  EXPECT_EQ(anariNewWorld(m_device), (ANARIWorld)0x100d);
  EXPECT_EQ(last(), "newWorld()");
  EXPECT_EQ(anariNewCamera(m_device, "perspective"), (ANARICamera)0x100e);
  EXPECT_EQ(last(), "newCamera(perspective)");
  EXPECT_EQ(anariNewRenderer(m_device, "raycast"), (ANARIRenderer)0x100f);
  EXPECT_EQ(last(), "newRenderer(raycast)");
  EXPECT_EQ(anariNewFrame(m_device), (ANARIFrame)0x1010);
  EXPECT_EQ(last(), "newFrame()");
  EXPECT_EQ(anariNewObject(m_device, "customType", "sub"), (ANARIObject)0x1011);
  EXPECT_EQ(last(), "newObject(customType, sub)");
}

TEST_F(FrontEndDispatch, ParametersAndCommit)
{
  auto o = (ANARIObject)0x4242;
  const float value = 2.5f;
  anariSetParameter(m_device, o, "radius", ANARI_FLOAT32, &value);
  EXPECT_EQ(last(), "setParameter(0x4242, radius, 1068, 2.5)");
  const void *mem = &value;
  anariSetParameter(m_device, o, "thing", ANARI_VOID_POINTER, &mem);
  EXPECT_EQ(last(), "setParameter(0x4242, thing, 102, " + ptr(&mem) + ")");
  anariUnsetParameter(m_device, o, "radius");
  EXPECT_EQ(last(), "unsetParameter(0x4242, radius)");
  anariUnsetAllParameters(m_device, o);
  EXPECT_EQ(last(), "unsetAllParameters(0x4242)");
  anariCommitParameters(m_device, o);
  EXPECT_EQ(last(), "commitParameters(0x4242)");
  anariRetain(m_device, o);
  EXPECT_EQ(last(), "retain(0x4242)");
  anariRelease(m_device, o);
  EXPECT_EQ(last(), "release(0x4242)");
}

TEST_F(FrontEndDispatch, MappedParameterArrays)
{
  auto o = (ANARIObject)0x99;
  uint64_t stride = 0;
  auto s = ptr(&stride);
  EXPECT_NE(
      anariMapParameterArray1D(
          m_device, o, "vertex.position", ANARI_FLOAT32_VEC3, 10, &stride),
      nullptr);
  EXPECT_EQ(last(),
      "mapParameterArray1D(0x99, vertex.position, 1070, 10, " + s + ")");
  anariMapParameterArray2D(m_device, o, "image", ANARI_UFIXED8, 6, 7, &stride);
  EXPECT_EQ(last(), "mapParameterArray2D(0x99, image, 1036, 6, 7, " + s + ")");
  anariMapParameterArray3D(
      m_device, o, "data", ANARI_FLOAT32, 2, 3, 4, &stride);
  EXPECT_EQ(
      last(), "mapParameterArray3D(0x99, data, 1068, 2, 3, 4, " + s + ")");
  anariUnmapParameterArray(m_device, o, "data");
  EXPECT_EQ(last(), "unmapParameterArray(0x99, data)");
}

TEST_F(FrontEndDispatch, PropertiesAndIntrospection)
{
  int32_t out = 0;
  EXPECT_EQ(anariGetProperty(m_device,
                (ANARIObject)0x55,
                "version",
                ANARI_INT32,
                &out,
                sizeof(out),
                ANARI_WAIT),
      7);
  EXPECT_EQ(
      last(), "getProperty(0x55, version, 1016, " + ptr(&out) + ", 4, 1)");
  const char **subtypes = anariGetObjectSubtypes(m_device, ANARI_GEOMETRY);
  ASSERT_NE(subtypes, nullptr);
  EXPECT_STREQ(subtypes[0], "recorded");
  EXPECT_EQ(last(), "getObjectSubtypes(509)");
  EXPECT_NE(
      anariGetObjectInfo(
          m_device, ANARI_GEOMETRY, "sphere", "description", ANARI_STRING),
      nullptr);
  EXPECT_EQ(last(), "getObjectInfo(509, sphere, description, 101)");
  anariGetParameterInfo(m_device,
      ANARI_GEOMETRY,
      "sphere",
      "radius",
      ANARI_FLOAT32,
      "default",
      ANARI_FLOAT32);
  EXPECT_EQ(
      last(), "getParameterInfo(509, sphere, radius, 1068, default, 1068)");
}

TEST_F(FrontEndDispatch, Frames)
{
  auto f = (ANARIFrame)0x123;
  uint32_t w = 0, h = 0;
  ANARIDataType type = ANARI_UNKNOWN;
  EXPECT_NE(
      anariMapFrame(m_device, f, "channel.color", &w, &h, &type), nullptr);
  EXPECT_EQ(last(), "frameBufferMap(0x123, channel.color)");
  EXPECT_EQ(w, 4u);
  EXPECT_EQ(h, 2u);
  EXPECT_EQ(type, ANARI_UFIXED8_RGBA_SRGB);
  // NULL outputs are tolerated (the device writes to scratch space).
  EXPECT_NE(
      anariMapFrame(m_device, f, "channel.depth", nullptr, nullptr, nullptr),
      nullptr);
  anariUnmapFrame(m_device, f, "channel.color");
  EXPECT_EQ(last(), "frameBufferUnmap(0x123, channel.color)");
  anariRenderFrame(m_device, f);
  EXPECT_EQ(last(), "renderFrame(0x123)");
  EXPECT_EQ(anariFrameReady(m_device, f, ANARI_NO_WAIT), 1);
  EXPECT_EQ(last(), "frameReady(0x123, 0)");
  anariDiscardFrame(m_device, f);
  EXPECT_EQ(last(), "discardFrame(0x123)");
}

TEST_F(FrontEndDispatch, LibraryQueriesAndModules)
{
  const char **subtypes = anariGetDeviceSubtypes(m_library);
  ASSERT_NE(subtypes, nullptr);
  EXPECT_STREQ(subtypes[0], "default");
  EXPECT_STREQ(subtypes[1], "second");
  EXPECT_EQ(subtypes[2], nullptr);
  const char **extensions = anariGetDeviceExtensions(m_library, "default");
  ASSERT_NE(extensions, nullptr);
  EXPECT_STREQ(extensions[0], "ANARI_KHR_RECORDING_TEST");
  anariLoadModule(m_library, "extra");
  EXPECT_EQ(last(), "loadModule(extra)");
  anariUnloadModule(m_library, "extra");
  EXPECT_EQ(last(), "unloadModule(extra)");
  EXPECT_EQ(anariDeviceGetProcAddress(m_device, "noSuchFunction"), nullptr);
}

TEST_F(FrontEndDispatch, InitializedDeviceAndDeviceRefcount)
{
  ANARIParameterValue none[] = {{nullptr, ANARI_UNKNOWN, nullptr}};
  ANARIDevice second = anariNewInitializedDevice(m_library, "second", none);
  ASSERT_NE(second, nullptr);
  auto liveDevices =
      (int (*)(void))anariDeviceGetProcAddress(second, "recordingLiveDevices");
  ASSERT_NE(liveDevices, nullptr);
  EXPECT_EQ(liveDevices(), 2);
  anariRetain(second, second);
  anariRelease(second, second);
  EXPECT_EQ(liveDevices(), 2);
  anariRelease(second, second);
  EXPECT_EQ(liveDevices(), 1);
  // The released device's handle is now refused, not dereferenced.
  anariCommitParameters(second, second);
  EXPECT_TRUE(m_status.tookOne(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "anariCommitParameters: device handle is not a live device"));
}

TEST_F(FrontEndDispatch, DeviceExceptionsAreReportedNotPropagated)
{
  EXPECT_EQ(anariDeviceGetProcAddress(m_device, "recordingThrow"), nullptr);
  EXPECT_TRUE(m_status.tookOne(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_UNKNOWN_ERROR,
      "recording device was asked to throw"));
}

} // namespace
