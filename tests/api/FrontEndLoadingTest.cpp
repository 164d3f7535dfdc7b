// Library loading rules and the front-end's handling of bad handles.
#include "StatusRecorder.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace {

TEST(FrontEndLoading, LoadsByNameAndUnloads)
{
  StatusRecorder status;
  ANARILibrary library =
      anariLoadLibrary("recording", StatusRecorder::callback, &status);
  ASSERT_NE(library, nullptr);
  anariUnloadLibrary(library);
  EXPECT_TRUE(status.take().empty());
}

TEST(FrontEndLoading, LoadsFromAnExplicitDirectory)
{
  StatusRecorder status;
  const std::string spec = std::string("recording,") + PRISM_TEST_LIBRARY_DIR;
  ANARILibrary library =
      anariLoadLibrary(spec.c_str(), StatusRecorder::callback, &status);
  ASSERT_NE(library, nullptr);
  anariUnloadLibrary(library);
  EXPECT_TRUE(status.take().empty());
}

TEST(FrontEndLoading, MissingLibraryReportsDlerror)
{
  StatusRecorder status;
  EXPECT_EQ(anariLoadLibrary("doesnotexist", StatusRecorder::callback, &status),
      nullptr);
  auto messages = status.take();
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0].severity, ANARI_SEVERITY_ERROR);
  EXPECT_EQ(messages[0].code, ANARI_STATUS_INVALID_OPERATION);
  EXPECT_NE(messages[0].text.find("libanari_library_doesnotexist.so"),
      std::string::npos);
  // dlerror's own words are part of the reason.
  EXPECT_NE(messages[0].text.find("cannot open shared object file"),
      std::string::npos);
}

TEST(FrontEndLoading, MissingEntryPointIsReported)
{
  StatusRecorder status;
  EXPECT_EQ(
      anariLoadLibrary("noentry", StatusRecorder::callback, &status), nullptr);
  EXPECT_TRUE(status.tookOne(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "has no entry point 'anari_library_noentry_new_library'"));
}

TEST(FrontEndLoading, EntryPointReturningNullIsReported)
{
  StatusRecorder status;
  EXPECT_EQ(anariLoadLibrary("nulldevice", StatusRecorder::callback, &status),
      nullptr);
  EXPECT_TRUE(status.tookOne(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "failed to initialise"));
}

TEST(FrontEndLoading, EnvironmentWithoutVariableIsReported)
{
  StatusRecorder status;
  unsetenv("ANARI_LIBRARY");
  EXPECT_EQ(anariLoadLibrary("environment", StatusRecorder::callback, &status),
      nullptr);
  EXPECT_TRUE(status.tookOne(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "ANARI_LIBRARY is not set"));
}

TEST(FrontEndLoading, EnvironmentNamesTheLibrary)
{
  StatusRecorder status;
  setenv("ANARI_LIBRARY", "recording", 1);
  ANARILibrary library =
      anariLoadLibrary("environment", StatusRecorder::callback, &status);
  unsetenv("ANARI_LIBRARY");
  ASSERT_NE(library, nullptr);
  const char **subtypes = anariGetDeviceSubtypes(library);
  ASSERT_NE(subtypes, nullptr);
  EXPECT_STREQ(subtypes[1], "second");
  anariUnloadLibrary(library);
  EXPECT_TRUE(status.take().empty());
}

TEST(FrontEndLoading, NullOrEmptyNameIsReported)
{
  StatusRecorder status;
  EXPECT_EQ(
      anariLoadLibrary(nullptr, StatusRecorder::callback, &status), nullptr);
  EXPECT_TRUE(status.tookOne(
      ANARI_SEVERITY_ERROR, ANARI_STATUS_INVALID_OPERATION, "NULL or empty"));
  EXPECT_EQ(anariLoadLibrary("", StatusRecorder::callback, &status), nullptr);
  EXPECT_TRUE(status.tookOne(
      ANARI_SEVERITY_ERROR, ANARI_STATUS_INVALID_OPERATION, "NULL or empty"));
}

// With a live library loaded, bad handles are reported to its callback.
class FrontEndBadHandles : public ::testing::Test
{
 protected:
  void SetUp() override
  {
    m_library =
        anariLoadLibrary("recording", StatusRecorder::callback, &m_status);
    ASSERT_NE(m_library, nullptr);
  }
  void TearDown() override
  {
    anariUnloadLibrary(m_library);
  }
  StatusRecorder m_status;
  ANARILibrary m_library{nullptr};
};

TEST_F(FrontEndBadHandles, NullLibraryHandle)
{
  EXPECT_EQ(anariNewDevice(nullptr, "default"), nullptr);
  EXPECT_TRUE(m_status.tookOne(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "anariNewDevice: library handle is NULL"));
  EXPECT_EQ(anariGetDeviceSubtypes(nullptr), nullptr);
  EXPECT_EQ(anariGetDeviceExtensions(nullptr, "default"), nullptr);
  anariLoadModule(nullptr, "x");
  anariUnloadModule(nullptr, "x");
  anariUnloadLibrary(nullptr);
  EXPECT_EQ(m_status.take().size(), 5u);
}

TEST_F(FrontEndBadHandles, ForeignLibraryHandle)
{
  int notALibrary = 0;
  EXPECT_EQ(anariNewDevice((ANARILibrary)&notALibrary, "default"), nullptr);
  EXPECT_TRUE(m_status.tookOne(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "library handle is not a loaded library"));
}

TEST_F(FrontEndBadHandles, UnknownDeviceSubtype)
{
  EXPECT_EQ(anariNewDevice(m_library, "nosuchdevice"), nullptr);
  EXPECT_TRUE(m_status.tookOne(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_UNSUPPORTED_DEVICE,
      "no device of subtype 'nosuchdevice'"));
}

TEST_F(FrontEndBadHandles, NullDeviceHandleOnEveryEntryPoint)
{
  ANARIDevice d = nullptr;
  uint32_t w, h;
  ANARIDataType t;
  uint64_t stride;
  int value = 0;
  EXPECT_EQ(
      anariNewArray1D(d, nullptr, nullptr, nullptr, ANARI_FLOAT32, 1), nullptr);
  EXPECT_EQ(anariNewArray2D(d, nullptr, nullptr, nullptr, ANARI_FLOAT32, 1, 1),
      nullptr);
  EXPECT_EQ(
      anariNewArray3D(d, nullptr, nullptr, nullptr, ANARI_FLOAT32, 1, 1, 1),
      nullptr);
  EXPECT_EQ(anariMapArray(d, nullptr), nullptr);
  anariUnmapArray(d, nullptr);
  EXPECT_EQ(anariNewLight(d, "point"), nullptr);
  EXPECT_EQ(anariNewCamera(d, "perspective"), nullptr);
  EXPECT_EQ(anariNewGeometry(d, "sphere"), nullptr);
  EXPECT_EQ(anariNewSpatialField(d, "structuredRegular"), nullptr);
  EXPECT_EQ(anariNewVolume(d, "transferFunction1D"), nullptr);
  EXPECT_EQ(anariNewSurface(d), nullptr);
  EXPECT_EQ(anariNewMaterial(d, "matte"), nullptr);
  EXPECT_EQ(anariNewSampler(d, "image1D"), nullptr);
  EXPECT_EQ(anariNewGroup(d), nullptr);
  EXPECT_EQ(anariNewInstance(d, "transform"), nullptr);
  EXPECT_EQ(anariNewWorld(d), nullptr);
  EXPECT_EQ(anariNewObject(d, "x", "y"), nullptr);
  anariSetParameter(d, nullptr, "x", ANARI_INT32, &value);
  anariUnsetParameter(d, nullptr, "x");
  anariUnsetAllParameters(d, nullptr);
  EXPECT_EQ(
      anariMapParameterArray1D(d, nullptr, "x", ANARI_FLOAT32, 1, &stride),
      nullptr);
  EXPECT_EQ(
      anariMapParameterArray2D(d, nullptr, "x", ANARI_FLOAT32, 1, 1, &stride),
      nullptr);
  EXPECT_EQ(anariMapParameterArray3D(
                d, nullptr, "x", ANARI_FLOAT32, 1, 1, 1, &stride),
      nullptr);
  anariUnmapParameterArray(d, nullptr, "x");
  anariCommitParameters(d, nullptr);
  anariRelease(d, nullptr);
  anariRetain(d, nullptr);
  EXPECT_EQ(anariGetObjectSubtypes(d, ANARI_GEOMETRY), nullptr);
  EXPECT_EQ(anariGetObjectInfo(
                d, ANARI_GEOMETRY, "sphere", "description", ANARI_STRING),
      nullptr);
  EXPECT_EQ(anariGetParameterInfo(d,
                ANARI_GEOMETRY,
                "sphere",
                "radius",
                ANARI_FLOAT32,
                "default",
                ANARI_FLOAT32),
      nullptr);
  EXPECT_EQ(anariGetProperty(
                d, nullptr, "version", ANARI_INT32, &value, 4, ANARI_WAIT),
      0);
  EXPECT_EQ(anariNewFrame(d), nullptr);
  EXPECT_EQ(anariMapFrame(d, nullptr, "channel.color", &w, &h, &t), nullptr);
  anariUnmapFrame(d, nullptr, "channel.color");
  EXPECT_EQ(anariNewRenderer(d, "default"), nullptr);
  anariRenderFrame(d, nullptr);
  EXPECT_EQ(anariFrameReady(d, nullptr, ANARI_WAIT), 0);
  anariDiscardFrame(d, nullptr);
  EXPECT_EQ(anariDeviceGetProcAddress(d, "x"), nullptr);

  auto messages = m_status.take();
  EXPECT_EQ(messages.size(), 39u); // 38 device functions + GetProcAddress
  for (auto &m : messages) {
    EXPECT_EQ(m.severity, ANARI_SEVERITY_ERROR);
    EXPECT_EQ(m.code, ANARI_STATUS_INVALID_ARGUMENT);
    EXPECT_NE(m.text.find("device handle is NULL"), std::string::npos)
        << m.text;
  }
}

TEST_F(FrontEndBadHandles, ForeignDeviceHandle)
{
  double notADevice[8] = {};
  EXPECT_EQ(anariNewWorld((ANARIDevice)notADevice), nullptr);
  EXPECT_TRUE(m_status.tookOne(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "anariNewWorld: device handle is not a live device"));
}

TEST_F(FrontEndBadHandles, NullNamesNeverReachTheDevice)
{
  ANARIDevice device = anariNewDevice(m_library, nullptr);
  ASSERT_NE(device, nullptr);
  int value = 1;
  anariSetParameter(device, device, nullptr, ANARI_INT32, &value);
  EXPECT_TRUE(m_status.tookOne(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "anariSetParameter: parameter name is NULL"));
  EXPECT_EQ(anariMapFrame(device, nullptr, nullptr, nullptr, nullptr, nullptr),
      nullptr);
  EXPECT_TRUE(m_status.tookOne(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "anariMapFrame: channel name is NULL"));
  anariRelease(device, device);
}

TEST_F(FrontEndBadHandles, UnloadingWithLiveDevicesKeepsTheirCodeMapped)
{
  StatusRecorder status;
  ANARILibrary library =
      anariLoadLibrary("recording", StatusRecorder::callback, &status);
  ANARIDevice device = anariNewDevice(library, "default");
  ASSERT_NE(device, nullptr);
  anariUnloadLibrary(library);
  // The device still works: its library's code stays loaded until the
  // device's last reference is gone.
  EXPECT_EQ(anariNewWorld(device), (ANARIWorld)0x100d);
  anariRelease(device, device);
  EXPECT_TRUE(status.take().empty());
}

} // namespace
