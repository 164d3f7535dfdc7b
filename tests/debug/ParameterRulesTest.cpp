// Subtypes, parameter names, types, values and array element types, checked
// at anariNew* and anariSetParameter against the API definitions.
#include "DebugLayerTestSupport.h"

namespace {

const float kTriangle[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
const float kTriangleVec4[12] = {0, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0, 1};

} // namespace

using DebugParameters = DebugLayerTest;

TEST_F(DebugParameters, UnknownSubtype)
{
  ANARIGeometry teapot = anariNewGeometry(m_device, "teapot");
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "anariNewGeometry(): unknown geometry subtype 'teapot'"));
  anariRelease(m_device, teapot);

  ANARIGeometry triangle = anariNewGeometry(m_device, "triangle");
  ANARILight light = anariNewLight(m_device, "directional");
  anariRelease(m_device, light);
  anariRelease(m_device, triangle);
  EXPECT_TRUE(silent());
}

TEST_F(DebugParameters, UnknownParameterName)
{
  ANARICamera camera = anariNewCamera(m_device, "perspective");
  const float fovy = 1.f;
  anariSetParameter(m_device, camera, "fovyy", ANARI_FLOAT32, &fovy);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_WARNING,
      ANARI_STATUS_INVALID_ARGUMENT,
      "anariSetParameter(camera perspective #1 'fovyy'): unknown parameter"));

  anariSetParameter(m_device, camera, "fovy", ANARI_FLOAT32, &fovy);
  anariSetParameter(m_device, camera, "name", ANARI_STRING, "main");
  anariCommitParameters(m_device, camera);
  anariRelease(m_device, camera);
  EXPECT_TRUE(silent());
}

TEST_F(DebugParameters, TypeMismatch)
{
  ANARICamera camera = anariNewCamera(m_device, "perspective");
  const int32_t notAFloat = 1;
  anariSetParameter(m_device, camera, "fovy", ANARI_INT32, &notAFloat);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "anariSetParameter(camera perspective #1 'fovy'): type ANARI_INT32 is "
      "not accepted (expected ANARI_FLOAT32)"));
  anariRelease(m_device, camera);
  EXPECT_TRUE(silent());
}

TEST_F(DebugParameters, ValueNotAmongTheAcceptedOnes)
{
  ANARIFrame frame = anariNewFrame(m_device);
  ANARIDataType rgb = ANARI_FLOAT32_VEC3;
  anariSetParameter(m_device, frame, "channel.color", ANARI_DATA_TYPE, &rgb);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "data type ANARI_FLOAT32_VEC3 is not accepted"));

  ANARIDataType rgba = ANARI_FLOAT32_VEC4;
  anariSetParameter(m_device, frame, "channel.color", ANARI_DATA_TYPE, &rgba);
  anariRelease(m_device, frame);
  EXPECT_TRUE(silent());
}

TEST_F(DebugParameters, ArrayElementType)
{
  ANARIGeometry geometry = anariNewGeometry(m_device, "triangle");
  ANARIArray1D vec4 = floatArray(ANARI_FLOAT32_VEC4, kTriangleVec4, 3);
  anariSetParameter(
      m_device, geometry, "vertex.position", ANARI_ARRAY1D, &vec4);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "anariSetParameter(geometry triangle #1 'vertex.position'): array1d #2 "
      "has elements of type ANARI_FLOAT32_VEC4, expected ANARI_FLOAT32_VEC3"));

  ANARIArray1D vec3 = floatArray(ANARI_FLOAT32_VEC3, kTriangle, 3);
  anariSetParameter(
      m_device, geometry, "vertex.position", ANARI_ARRAY1D, &vec3);
  anariCommitParameters(m_device, geometry);
  anariRelease(m_device, vec4);
  anariRelease(m_device, vec3);
  anariRelease(m_device, geometry);
  EXPECT_TRUE(silent());
}

TEST_F(DebugParameters, MappedParameterArrayElementType)
{
  ANARIGeometry geometry = anariNewGeometry(m_device, "triangle");
  uint64_t stride = 0;
  void *memory = anariMapParameterArray1D(
      m_device, geometry, "vertex.position", ANARI_UINT8, 3, &stride);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "element type ANARI_UINT8 is not accepted"));
  if (memory)
    anariUnmapParameterArray(m_device, geometry, "vertex.position");
  takeProblems(m_status);

  auto *positions = (float *)anariMapParameterArray1D(
      m_device, geometry, "vertex.position", ANARI_FLOAT32_VEC3, 3, &stride);
  ASSERT_NE(positions, nullptr);
  for (int i = 0; i < 9; ++i)
    positions[i] = kTriangle[i];
  anariUnmapParameterArray(m_device, geometry, "vertex.position");
  anariCommitParameters(m_device, geometry);
  anariRelease(m_device, geometry);
  EXPECT_TRUE(silent());
}

TEST_F(DebugParameters, InvalidArrays)
{
  EXPECT_EQ(
      anariNewArray1D(m_device, nullptr, nullptr, nullptr, ANARI_STRING, 4),
      nullptr);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "element type ANARI_STRING (101) cannot be an array element"));
  EXPECT_EQ(
      anariNewArray2D(m_device, nullptr, nullptr, nullptr, ANARI_FLOAT32, 4, 0),
      nullptr);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "the array has no elements (dimension 2 is 0)"));

  ANARIArray2D fine =
      anariNewArray2D(m_device, nullptr, nullptr, nullptr, ANARI_FLOAT32, 4, 4);
  EXPECT_NE(fine, nullptr);
  anariRelease(m_device, fine);
  EXPECT_TRUE(silent());
}
