// Required parameters, vertex array sizes and index ranges at
// anariCommitParameters; complete, committed frames at anariRenderFrame.
#include "DebugLayerTestSupport.h"

namespace {

const float kTriangle[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};

} // namespace

using DebugCommit = DebugLayerTest;

TEST_F(DebugCommit, RequiredParameterMissing)
{
  ANARIGeometry geometry = anariNewGeometry(m_device, "triangle");
  anariCommitParameters(m_device, geometry);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "anariCommitParameters(geometry triangle #1): required parameter "
      "'vertex.position' is not set"));
  ANARISurface surface = anariNewSurface(m_device);
  anariSetParameter(m_device, surface, "geometry", ANARI_GEOMETRY, &geometry);
  anariCommitParameters(m_device, surface);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "required parameter 'material' is not set"));

  ANARIArray1D positions = anariNewArray1D(
      m_device, kTriangle, nullptr, nullptr, ANARI_FLOAT32_VEC3, 3);
  anariSetParameter(
      m_device, geometry, "vertex.position", ANARI_ARRAY1D, &positions);
  anariCommitParameters(m_device, geometry);
  ANARIMaterial material = anariNewMaterial(m_device, "matte");
  anariCommitParameters(m_device, material);
  anariSetParameter(m_device, surface, "material", ANARI_MATERIAL, &material);
  anariCommitParameters(m_device, surface);
  for (ANARIObject o : {(ANARIObject)surface,
           (ANARIObject)material,
           (ANARIObject)positions,
           (ANARIObject)geometry})
    anariRelease(m_device, o);
  EXPECT_TRUE(silent());
}

TEST_F(DebugCommit, PackedPositionsStandInForPositions)
{
  // PRISM_GEOMETRY_POSITION_RADIUS's vertex.positionRadius holds the
  // sphere's positions: no "required" error, and vertex attributes are
  // counted against it.
  const float packed[8] = {0, 0, 0, 0.5f, 1, 0, 0, 0.5f};
  ANARIGeometry spheres = anariNewGeometry(m_device, "sphere");
  ANARIArray1D positionRadius = anariNewArray1D(
      m_device, packed, nullptr, nullptr, ANARI_FLOAT32_VEC4, 2);
  anariSetParameter(m_device,
      spheres,
      "vertex.positionRadius",
      ANARI_ARRAY1D,
      &positionRadius);
  anariCommitParameters(m_device, spheres);
  EXPECT_TRUE(silent());
  const float colors[12] = {};
  ANARIArray1D three = anariNewArray1D(
      m_device, colors, nullptr, nullptr, ANARI_FLOAT32_VEC4, 3);
  anariSetParameter(m_device, spheres, "vertex.color", ANARI_ARRAY1D, &three);
  anariCommitParameters(m_device, spheres);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "'vertex.color' has 3 elements but 'vertex.positionRadius' has 2"));
  for (ANARIObject o :
      {(ANARIObject)spheres, (ANARIObject)positionRadius, (ANARIObject)three})
    anariRelease(m_device, o);
}

TEST_F(DebugCommit, IndexOutOfRange)
{
  ANARIGeometry geometry = anariNewGeometry(m_device, "triangle");
  ANARIArray1D positions = anariNewArray1D(
      m_device, kTriangle, nullptr, nullptr, ANARI_FLOAT32_VEC3, 3);
  anariSetParameter(
      m_device, geometry, "vertex.position", ANARI_ARRAY1D, &positions);
  const uint32_t wrong[3] = {0, 1, 3};
  ANARIArray1D index =
      anariNewArray1D(m_device, wrong, nullptr, nullptr, ANARI_UINT32_VEC3, 1);
  anariSetParameter(
      m_device, geometry, "primitive.index", ANARI_ARRAY1D, &index);
  anariCommitParameters(m_device, geometry);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "'primitive.index' (array1d #3) refers to vertex 3 but "
      "'vertex.position' has 3 vertices"));

  // Corrected through a map: the layer reads the indices anew at unmap.
  auto *indices = (uint32_t *)anariMapArray(m_device, index);
  ASSERT_NE(indices, nullptr);
  indices[2] = 2;
  anariUnmapArray(m_device, index);
  anariCommitParameters(m_device, geometry);
  anariRelease(m_device, index);
  anariRelease(m_device, positions);
  anariRelease(m_device, geometry);
  EXPECT_TRUE(silent());
}

TEST_F(DebugCommit, VertexArraysOfDifferentSizes)
{
  ANARIGeometry geometry = anariNewGeometry(m_device, "triangle");
  ANARIArray1D positions = anariNewArray1D(
      m_device, kTriangle, nullptr, nullptr, ANARI_FLOAT32_VEC3, 3);
  ANARIArray1D colors = anariNewArray1D(
      m_device, kTriangle, nullptr, nullptr, ANARI_FLOAT32_VEC3, 2);
  anariSetParameter(
      m_device, geometry, "vertex.position", ANARI_ARRAY1D, &positions);
  anariSetParameter(m_device, geometry, "vertex.color", ANARI_ARRAY1D, &colors);
  anariCommitParameters(m_device, geometry);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_ARGUMENT,
      "'vertex.color' has 2 elements but 'vertex.position' has 3"));

  anariSetParameter(
      m_device, geometry, "vertex.color", ANARI_ARRAY1D, &positions);
  anariCommitParameters(m_device, geometry);
  anariRelease(m_device, colors);
  anariRelease(m_device, positions);
  anariRelease(m_device, geometry);
  EXPECT_TRUE(silent());
}

TEST_F(DebugCommit, IncompleteFrame)
{
  ANARIFrame frame = anariNewFrame(m_device);
  const uint32_t size[2] = {4, 4};
  anariSetParameter(m_device, frame, "size", ANARI_UINT32_VEC2, size);
  anariCommitParameters(m_device, frame);
  EXPECT_TRUE(silent()); // a frame is checked when rendered
  anariRenderFrame(m_device, frame);
  anariFrameReady(m_device, frame, ANARI_WAIT);
  std::vector<std::string> missing;
  for (auto &m : takeProblems(m_status)) {
    if (fromLayer(m))
      missing.push_back(m.text);
  }
  ASSERT_EQ(missing.size(), 3u);
  EXPECT_NE(missing[0].find("anariRenderFrame(frame #1): required parameter "
                            "'world' is not set"),
      std::string::npos);
  anariRelease(m_device, frame);
}

TEST_F(DebugCommit, CompleteFrameRendersSilently)
{
  ANARIWorld world = anariNewWorld(m_device);
  ANARICamera camera = anariNewCamera(m_device, "perspective");
  ANARIRenderer renderer = anariNewRenderer(m_device, "default");
  ANARIFrame frame = anariNewFrame(m_device);
  for (ANARIObject o :
      {(ANARIObject)world, (ANARIObject)camera, (ANARIObject)renderer})
    anariCommitParameters(m_device, o);
  const uint32_t size[2] = {8, 8};
  const ANARIDataType color = ANARI_FLOAT32_VEC4;
  anariSetParameter(m_device, frame, "world", ANARI_WORLD, &world);
  anariSetParameter(m_device, frame, "camera", ANARI_CAMERA, &camera);
  anariSetParameter(m_device, frame, "renderer", ANARI_RENDERER, &renderer);
  anariSetParameter(m_device, frame, "size", ANARI_UINT32_VEC2, size);
  anariSetParameter(m_device, frame, "channel.color", ANARI_DATA_TYPE, &color);
  anariRenderFrame(m_device, frame);
  EXPECT_TRUE(onlyLayerReported(ANARI_SEVERITY_ERROR,
      ANARI_STATUS_INVALID_OPERATION,
      "anariRenderFrame(frame #4): the frame was never committed"));
  anariFrameReady(m_device, frame, ANARI_WAIT);

  anariCommitParameters(m_device, frame);
  anariRenderFrame(m_device, frame);
  anariFrameReady(m_device, frame, ANARI_WAIT);
  uint32_t w = 0, h = 0;
  ANARIDataType type = ANARI_UNKNOWN;
  EXPECT_NE(
      anariMapFrame(m_device, frame, "channel.color", &w, &h, &type), nullptr);
  EXPECT_EQ(w, 8u);
  anariUnmapFrame(m_device, frame, "channel.color");
  for (ANARIObject o : {(ANARIObject)frame,
           (ANARIObject)renderer,
           (ANARIObject)camera,
           (ANARIObject)world})
    anariRelease(m_device, o);
  EXPECT_TRUE(silent());
}
