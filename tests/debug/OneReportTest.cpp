// One report per problem: a call the layer reports about and still forwards
// (the wrapped device behaves as it would without the layer) does not make
// prism report the same problem again.
#include "DebugLayerTestSupport.h"

using DebugOneReport = DebugLayerTest;

TEST_F(DebugOneReport, UnknownSubtype)
{
  ANARIGeometry geometry = anariNewGeometry(m_device, "teapot");
  EXPECT_NE(geometry, nullptr); // forwarded: prism makes an inert object
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "unknown geometry subtype 'teapot'"));
  anariRelease(m_device, geometry);
  geometry = anariNewGeometry(m_device, "sphere");
  anariRelease(m_device, geometry);
  EXPECT_TRUE(silent());
}

TEST_F(DebugOneReport, RequiredParameterMissingAtCommit)
{
  ANARIGeometry geometry = anariNewGeometry(m_device, "sphere");
  anariCommitParameters(m_device, geometry);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "required parameter 'vertex.position'"));
  const float position[3] = {0, 0, 0};
  ANARIArray1D positions = floatArray(ANARI_FLOAT32_VEC3, position, 1);
  anariSetParameter(
      m_device, geometry, "vertex.position", ANARI_ARRAY1D, &positions);
  anariCommitParameters(m_device, geometry);
  anariRelease(m_device, positions);
  anariRelease(m_device, geometry);
  EXPECT_TRUE(silent());
}

TEST_F(DebugOneReport, ParameterOfTheWrongType)
{
  ANARIMaterial material = anariNewMaterial(m_device, "matte");
  const int32_t notAColor = 3;
  anariSetParameter(m_device, material, "color", ANARI_INT32, &notAColor);
  anariCommitParameters(m_device, material);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "anariSetParameter(material matte #1 'color'): type ANARI_INT32"));
  const float red[3] = {1, 0, 0};
  anariSetParameter(m_device, material, "color", ANARI_FLOAT32_VEC3, red);
  anariCommitParameters(m_device, material);
  anariRelease(m_device, material);
  EXPECT_TRUE(silent());
}

TEST_F(DebugOneReport, IndexPastTheLastVertex)
{
  const float position[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const uint32_t past[3] = {0, 1, 3};
  ANARIGeometry geometry = anariNewGeometry(m_device, "triangle");
  ANARIArray1D positions = floatArray(ANARI_FLOAT32_VEC3, position, 3);
  ANARIArray1D indices =
      anariNewArray1D(m_device, past, nullptr, nullptr, ANARI_UINT32_VEC3, 1);
  anariSetParameter(
      m_device, geometry, "vertex.position", ANARI_ARRAY1D, &positions);
  anariSetParameter(
      m_device, geometry, "primitive.index", ANARI_ARRAY1D, &indices);
  anariCommitParameters(m_device, geometry);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "refers to vertex 3"));
  anariUnsetParameter(m_device, geometry, "primitive.index");
  anariCommitParameters(m_device, geometry);
  for (ANARIObject o :
      {(ANARIObject)indices, (ANARIObject)positions, (ANARIObject)geometry})
    anariRelease(m_device, o);
  EXPECT_TRUE(silent());
}
