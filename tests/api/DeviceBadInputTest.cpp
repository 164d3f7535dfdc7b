// Each class of bad input is reported with the right severity and code, and
// the device keeps rendering afterwards.
#include "DeviceTestSupport.h"

#include <cstdio>
#include <cstring>

#include <unistd.h>

namespace {

const float kRed[4] = {1, 0, 0, 1};

class DeviceBadInput : public PrismDeviceTest
{
 protected:
  // After any bad input, a normal render still produces the background.
  void expectStillRenders()
  {
    ANARIRenderer renderer = newRenderer(kRed);
    ANARIFrame frame = newFrame(renderer, 4, 4);
    anariRenderFrame(m_device, frame);
    EXPECT_EQ(firstPixel(frame), std::vector<float>({1, 0, 0, 1}));
    anariRelease(m_device, frame);
    anariRelease(m_device, renderer);
    EXPECT_TRUE(problems().empty());
  }
};

TEST_F(DeviceBadInput, NullObjectHandle)
{
  const float value = 1.f;
  anariSetParameter(m_device, nullptr, "x", ANARI_FLOAT32, &value);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "anariSetParameter: object handle is NULL"));
  anariCommitParameters(m_device, nullptr);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "anariCommitParameters: object handle is NULL"));
  anariRelease(m_device, nullptr); // not an error (spec 3.5)
  EXPECT_TRUE(problems().empty());
  expectStillRenders();
}

TEST_F(DeviceBadInput, ReleasedHandle)
{
  ANARIWorld world = anariNewWorld(m_device);
  anariRelease(m_device, world);
  anariCommitParameters(m_device, world);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "not a live object of this device"));
  anariRelease(m_device, world);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "anariRelease: handle is not a live object"));
  // A new object may reuse the slot; the old handle stays invalid.
  ANARIWorld second = anariNewWorld(m_device);
  EXPECT_NE(second, world);
  anariRetain(m_device, world);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "anariRetain: handle is not a live object"));
  anariRelease(m_device, second);
  expectStillRenders();
}

TEST_F(DeviceBadInput, ForeignHandleFromAnotherDevice)
{
  ANARIDevice other = anariNewDevice(m_library, "default");
  ANARIWorld foreign = anariNewWorld(other);
  anariCommitParameters(m_device, foreign);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "handle belongs to another device"));
  int notAnObject = 0;
  anariCommitParameters(m_device, (ANARIObject)&notAnObject);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "not a live object of this device"));
  anariRelease(other, foreign);
  anariRelease(other, other);
  expectStillRenders();
}

TEST_F(DeviceBadInput, HandleOfTheWrongType)
{
  ANARIWorld world = anariNewWorld(m_device);
  EXPECT_EQ(anariMapArray(m_device, (ANARIArray)world), nullptr);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "is not of the expected type ANARI_ARRAY1D"));
  anariRenderFrame(m_device, (ANARIFrame)world);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "is not of the expected type ANARI_FRAME"));
  // An object parameter whose handle has another type than declared.
  ANARIFrame frame = anariNewFrame(m_device);
  anariSetParameter(m_device, frame, "camera", ANARI_CAMERA, &world);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "set as ANARI_CAMERA but the handle is a ANARI_WORLD"));
  anariRelease(m_device, frame);
  anariRelease(m_device, world);
  expectStillRenders();
}

TEST_F(DeviceBadInput, UnknownSubtypeGivesAnInertObject)
{
  ANARIGeometry geometry = anariNewGeometry(m_device, "teapot");
  ASSERT_NE(geometry, nullptr);
  EXPECT_TRUE(reported(ANARI_SEVERITY_WARNING,
      ANARI_STATUS_INVALID_ARGUMENT,
      "geometry 'teapot': unknown subtype 'teapot'"));
  const float value = 2.f;
  anariSetParameter(m_device, geometry, "radius", ANARI_FLOAT32, &value);
  anariCommitParameters(m_device, geometry);
  ANARIRenderer renderer = anariNewRenderer(m_device, "nosuchrenderer");
  EXPECT_TRUE(reported(ANARI_SEVERITY_WARNING,
      ANARI_STATUS_INVALID_ARGUMENT,
      "unknown subtype 'nosuchrenderer'"));
  // A frame with an inert renderer does not render, and says why.
  ANARIFrame frame = newFrame(renderer, 2, 2);
  anariRenderFrame(m_device, frame);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "it needs a valid 'renderer'"));
  anariRelease(m_device, frame);
  anariRelease(m_device, renderer);
  anariRelease(m_device, geometry);
  expectStillRenders();
}

TEST_F(DeviceBadInput, UnknownParameterWarnsOncePerName)
{
  ANARICamera camera = anariNewCamera(m_device, "perspective");
  const float value = 1.f;
  anariSetParameter(m_device, camera, "fovyy", ANARI_FLOAT32, &value);
  anariSetParameter(m_device, camera, "name", ANARI_STRING, "main camera");
  anariCommitParameters(m_device, camera);
  anariGetProperty(
      m_device, camera, "none", ANARI_INT32, nullptr, 0, ANARI_WAIT);
  EXPECT_TRUE(reported(ANARI_SEVERITY_WARNING,
      ANARI_STATUS_INVALID_ARGUMENT,
      "camera 'perspective' (main camera): unknown parameter 'fovyy'"));
  anariCommitParameters(m_device, camera);
  anariGetProperty(
      m_device, camera, "none", ANARI_INT32, nullptr, 0, ANARI_WAIT);
  EXPECT_TRUE(problems().empty()); // once per object and name
  anariRelease(m_device, camera);
  expectStillRenders();
}

TEST_F(DeviceBadInput, WrongParameterTypeNamesAcceptedTypes)
{
  ANARICamera camera = anariNewCamera(m_device, "perspective");
  const int32_t value = 1;
  anariSetParameter(m_device, camera, "fovy", ANARI_INT32, &value);
  anariCommitParameters(m_device, camera);
  anariGetProperty(
      m_device, camera, "none", ANARI_INT32, nullptr, 0, ANARI_WAIT);
  EXPECT_TRUE(reported(ANARI_SEVERITY_WARNING,
      ANARI_STATUS_INVALID_ARGUMENT,
      "parameter 'fovy' set as ANARI_INT32 is ignored; accepted types: "
      "ANARI_FLOAT32"));
  anariSetParameter(m_device, camera, "fovy", 99999, &value);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "has invalid data type 99999"));
  anariRelease(m_device, camera);
  expectStillRenders();
}

TEST_F(DeviceBadInput, PackedPositionsOfAWrongTypeOrBesideOthers)
{
  // PRISM_GEOMETRY_POSITION_RADIUS: vertex.positionRadius must hold
  // FLOAT32_VEC4 (an error names the accepted type, the geometry is
  // invalid), replaces vertex.position and the radii (each warned about
  // when also set), and a curve needs two vertices.
  // Sets `name` (and commits): the device reports at the next flush.
  auto commitWith = [&](ANARIGeometry geometry,
                        const char *name,
                        ANARIDataType type,
                        const void *value) {
    anariSetParameter(m_device, geometry, name, type, value);
    anariCommitParameters(m_device, geometry);
    uint64_t bytes = 0;
    anariGetProperty(m_device,
        geometry,
        "prism.copiedBytes",
        ANARI_UINT64,
        &bytes,
        sizeof(bytes),
        ANARI_WAIT);
  };
  const float three[6] = {0, 0, 0, 1, 0, 0};
  const float four[8] = {0, 0, 0, 0.5f, 1, 0, 0, 0.5f};
  ANARIArray1D vec3 =
      anariNewArray1D(m_device, three, nullptr, nullptr, ANARI_FLOAT32_VEC3, 2);
  ANARIArray1D vec4 =
      anariNewArray1D(m_device, four, nullptr, nullptr, ANARI_FLOAT32_VEC4, 2);
  ANARIArray1D one =
      anariNewArray1D(m_device, four, nullptr, nullptr, ANARI_FLOAT32_VEC4, 1);

  ANARIGeometry sphere = anariNewGeometry(m_device, "sphere");
  commitWith(sphere, "vertex.positionRadius", ANARI_ARRAY1D, &vec3);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "'vertex.positionRadius' has element type ANARI_FLOAT32_VEC3; "
      "accepted: ANARI_FLOAT32_VEC4"));

  const float radius = 2.f;
  anariSetParameter(
      m_device, sphere, "vertex.positionRadius", ANARI_ARRAY1D, &vec4);
  commitWith(sphere, "radius", ANARI_FLOAT32, &radius);
  EXPECT_TRUE(reported(ANARI_SEVERITY_WARNING,
      ANARI_STATUS_INVALID_ARGUMENT,
      "'radius' is ignored: 'vertex.positionRadius' is set"));

  ANARIGeometry curve = anariNewGeometry(m_device, "curve");
  commitWith(curve, "vertex.positionRadius", ANARI_ARRAY1D, &one);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "'vertex.positionRadius' has 1 elements; at least 2 are needed"));
  anariSetParameter(
      m_device, curve, "vertex.positionRadius", ANARI_ARRAY1D, &vec4);
  commitWith(curve, "vertex.position", ANARI_ARRAY1D, &vec3);
  EXPECT_TRUE(reported(ANARI_SEVERITY_WARNING,
      ANARI_STATUS_INVALID_ARGUMENT,
      "'vertex.position' is ignored: 'vertex.positionRadius' is set"));

  for (ANARIObject o : {(ANARIObject)sphere,
           (ANARIObject)curve,
           (ANARIObject)vec3,
           (ANARIObject)vec4,
           (ANARIObject)one})
    anariRelease(m_device, o);
  expectStillRenders();
}

TEST_F(DeviceBadInput, ArrayMappingMisuse)
{
  ANARIArray1D array =
      anariNewArray1D(m_device, nullptr, nullptr, nullptr, ANARI_FLOAT32, 4);
  anariUnmapArray(m_device, array);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "anariUnmapArray: array is not mapped"));
  ANARIRenderer renderer = anariNewRenderer(m_device, "default");
  uint64_t stride = 0;
  void *texels = anariMapParameterArray2D(
      m_device, renderer, "background", ANARI_FLOAT32_VEC4, 1, 1, &stride);
  ASSERT_NE(texels, nullptr);
  EXPECT_EQ(stride, 16u);
  const float blue[4] = {0, 0, 1, 1};
  anariSetParameter(m_device, renderer, "background", ANARI_FLOAT32_VEC4, blue);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "parameter 'background' is mapped; unmap it first"));
  anariUnsetParameter(m_device, renderer, "background");
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "parameter 'background' is mapped; unmap it first"));
  EXPECT_EQ(
      anariMapParameterArray2D(
          m_device, renderer, "background", ANARI_FLOAT32_VEC4, 1, 1, &stride),
      nullptr);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "parameter 'background' is already mapped"));
  EXPECT_EQ(anariMapParameterArray1D(
                m_device, renderer, "other", ANARI_FLOAT32, 1, nullptr),
      nullptr);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "elementStride must not be NULL"));
  std::memcpy(texels, blue, sizeof(blue));
  anariUnmapParameterArray(m_device, renderer, "background");
  anariUnmapParameterArray(m_device, renderer, "background");
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "parameter 'background' is not mapped"));
  // The mapped array became the parameter: the frame shows it.
  anariCommitParameters(m_device, renderer);
  ANARIFrame frame = newFrame(renderer, 3, 3);
  anariRenderFrame(m_device, frame);
  EXPECT_EQ(firstPixel(frame), std::vector<float>({0, 0, 1, 1}));
  anariRelease(m_device, frame);
  anariRelease(m_device, renderer);
  anariRelease(m_device, array);
  expectStillRenders();
}

TEST_F(DeviceBadInput, ZeroSizedAndInvalidArrays)
{
  float data[4] = {};
  EXPECT_EQ(anariNewArray1D(m_device, data, nullptr, nullptr, ANARI_FLOAT32, 0),
      nullptr);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "array size is zero"));
  EXPECT_EQ(anariNewArray3D(
                m_device, nullptr, nullptr, nullptr, ANARI_FLOAT32, 2, 0, 2),
      nullptr);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "array size is zero"));
  EXPECT_EQ(anariNewArray1D(m_device, data, nullptr, nullptr, ANARI_STRING, 1),
      nullptr);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "not a valid array element type"));
  EXPECT_EQ(anariNewArray2D(m_device,
                nullptr,
                nullptr,
                nullptr,
                ANARI_FLOAT64_VEC4,
                1ull << 40,
                1ull << 40),
      nullptr);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "array size overflows"));
  uint64_t stride;
  ANARIRenderer renderer = anariNewRenderer(m_device, "default");
  EXPECT_EQ(anariMapParameterArray1D(
                m_device, renderer, "x", ANARI_FLOAT32, 0, &stride),
      nullptr);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "array size is zero"));
  anariRelease(m_device, renderer);
  expectStillRenders();
}

// Bytes of this process's memory that are resident (touched).
uint64_t residentBytes()
{
  unsigned long long pages = 0, resident = 0;
  if (FILE *statm = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(statm, "%llu %llu", &pages, &resident) != 2)
      resident = 0;
    std::fclose(statm);
  }
  return uint64_t(resident) * uint64_t(sysconf(_SC_PAGESIZE));
}

TEST_F(DeviceBadInput, ManagedArrayLargerThanMemoryIsRefused)
{
  const uint64_t memory =
      uint64_t(sysconf(_SC_PHYS_PAGES)) * uint64_t(sysconf(_SC_PAGESIZE));
  const uint64_t items = memory / sizeof(float[4]) + 1;
  EXPECT_EQ(anariNewArray1D(
                m_device, nullptr, nullptr, nullptr, ANARI_FLOAT32_VEC4, items),
      nullptr);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_OUT_OF_MEMORY,
      "more than the machine's"));
  // Mapped parameter arrays are managed arrays too.
  uint64_t stride = 0;
  ANARIRenderer renderer = anariNewRenderer(m_device, "default");
  EXPECT_EQ(anariMapParameterArray1D(
                m_device, renderer, "x", ANARI_FLOAT32_VEC4, items, &stride),
      nullptr);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_OUT_OF_MEMORY,
      "more than the machine's"));
  anariRelease(m_device, renderer);
  expectStillRenders();
}

TEST_F(DeviceBadInput, LargeManagedArrayIsNotZeroFilledAtCreation)
{
  // 2^31 elements: memory the machine has, but which the device must not
  // touch (zero-filling it took minutes) until the application writes it.
  constexpr uint64_t kItems = 1ull << 31;
  const uint64_t before = residentBytes();
  ANARIArray1D array =
      anariNewArray1D(m_device, nullptr, nullptr, nullptr, ANARI_UINT8, kItems);
  ASSERT_NE(array, nullptr);
  // Half the array, a margin for sanitizers' shadow memory: zero-filling
  // makes all of it resident.
  EXPECT_LT(residentBytes(), before + kItems / 2);
  auto *bytes = (unsigned char *)anariMapArray(m_device, array);
  ASSERT_NE(bytes, nullptr);
  EXPECT_EQ(bytes[kItems - 1], 0); // zero, as a managed array starts
  bytes[kItems - 1] = 7;
  anariUnmapArray(m_device, array);
  anariRelease(m_device, array);
  expectStillRenders();
}

TEST_F(DeviceBadInput, InvalidChannelTypes)
{
  ANARIRenderer renderer = newRenderer(kRed);
  ANARIFrame frame = newFrame(renderer, 2, 2, ANARI_FLOAT32_VEC3);
  anariRenderFrame(m_device, frame);
  anariFrameReady(m_device, frame, ANARI_WAIT);
  EXPECT_TRUE(reported(ANARI_SEVERITY_WARNING,
      ANARI_STATUS_INVALID_ARGUMENT,
      "'channel.color' cannot be ANARI_FLOAT32_VEC3"));
  uint32_t w = 1, h = 1;
  ANARIDataType type = ANARI_FLOAT32;
  EXPECT_EQ(
      anariMapFrame(m_device, frame, "channel.color", &w, &h, &type), nullptr);
  EXPECT_EQ(w, 0u);
  EXPECT_EQ(type, ANARI_UNKNOWN);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "channel 'channel.color' is not enabled"));
  EXPECT_EQ(anariMapFrame(m_device, frame, "channel.nonsense", &w, &h, &type),
      nullptr);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "channel 'channel.nonsense' is not enabled"));
  anariRelease(m_device, frame);
  anariRelease(m_device, renderer);
  expectStillRenders();
}

TEST_F(DeviceBadInput, FrameMissingRequiredParameters)
{
  ANARIFrame frame = anariNewFrame(m_device);
  anariCommitParameters(m_device, frame);
  anariRenderFrame(m_device, frame);
  EXPECT_TRUE(reported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "it needs a valid 'world', a valid 'camera', a valid 'renderer', a "
      "positive 'size'"));
  // WAIT on a frame that never started returns at once.
  EXPECT_EQ(anariFrameReady(m_device, frame, ANARI_WAIT), 1);
  anariRelease(m_device, frame);
  expectStillRenders();
}

} // namespace
