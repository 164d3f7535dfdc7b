// Bad geometry input is reported, the geometry becomes invalid, and the
// rest of the scene still renders.
#include "AnalyticScene.h"

#include <cmath>

namespace {

const float kEye[3] = {0, 0, 5};
const float kDown[3] = {0, 0, -1};

class GeometryBadInput : public AnalyticTest
{
 protected:
  // Renders `bad` beside a good unit sphere at the origin; the sphere must
  // still show at the centre.
  void expectOthersStillRender(ANARIGeometry bad)
  {
    ANARISurface good = surface(geometry("sphere", {0, 0, 0}), matte(1, 1, 1));
    ANARIWorld w = world({good, surface(bad, matte(1, 0, 0))});
    ANARICamera c = orthographic(kEye, kDown, 4.f);
    ANARIRenderer r = renderer("raycast");
    RenderedImage image = render(w, c, r, 33, 33);
    EXPECT_NEAR(image.depthAt(16, 16), 4.f, 1e-4f);
    anariRelease(m_device, w);
    anariRelease(m_device, c);
    anariRelease(m_device, r);
  }
  // The one error the bad geometry produced (warnings about the surface
  // being invalid are not counted).
  ::testing::AssertionResult reportedError(const std::string &fragment)
  {
    std::string all;
    int matches = 0;
    for (auto &m : problems()) {
      all += m.text + "\n";
      if (m.severity == ANARI_SEVERITY_ERROR
          && m.code == ANARI_STATUS_INVALID_ARGUMENT
          && m.text.find(fragment) != std::string::npos)
        matches++;
    }
    if (matches == 1)
      return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "expected one error with '" << fragment << "', got:\n"
           << all;
  }
};

TEST_F(GeometryBadInput, IndexOutOfRange)
{
  ANARIGeometry g = geometry("triangle", {0, 0, 0, 1, 0, 0, 0, 1, 0});
  setArray(g,
      "primitive.index",
      array1D(std::vector<uint32_t>{0, 1, 3}, ANARI_UINT32_VEC3));
  expectOthersStillRender(g);
  EXPECT_TRUE(reportedError("refers to vertex 3 but there are only 3"));
}

TEST_F(GeometryBadInput, SixtyFourBitIndexBeyondTheLimit)
{
  ANARIGeometry g = geometry("sphere", {0, 0, 0});
  setArray(g,
      "primitive.index",
      array1D(std::vector<uint64_t>{1ull << 40}, ANARI_UINT64));
  expectOthersStillRender(g);
  EXPECT_TRUE(reportedError("above geometryMaxIndex"));
}

TEST_F(GeometryBadInput, MissingVertexPosition)
{
  ANARIGeometry g = anariNewGeometry(m_device, "triangle");
  expectOthersStillRender(g);
  EXPECT_TRUE(reportedError("required parameter 'vertex.position' is not set"));
}

TEST_F(GeometryBadInput, MismatchedAttributeArraySize)
{
  ANARIGeometry g = geometry("quad", {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
  setArray(g,
      "vertex.color",
      array1D(std::vector<float>{1, 0, 0, 0, 1, 0}, ANARI_FLOAT32_VEC3));
  expectOthersStillRender(g);
  EXPECT_TRUE(reportedError("'vertex.color' has 2 elements but 4 are needed"));
}

TEST_F(GeometryBadInput, WrongPositionElementType)
{
  ANARIGeometry g = anariNewGeometry(m_device, "sphere");
  setArray(g,
      "vertex.position",
      array1D(std::vector<float>{0, 0, 0, 1}, ANARI_FLOAT32_VEC4));
  expectOthersStillRender(g);
  EXPECT_TRUE(
      reportedError("'vertex.position' has element type "
                    "ANARI_FLOAT32_VEC4; accepted: ANARI_FLOAT32_VEC3"));
}

TEST_F(GeometryBadInput, TooFewVertices)
{
  ANARIGeometry g = geometry("triangle", {0, 0, 0, 1, 0, 0});
  expectOthersStillRender(g);
  EXPECT_TRUE(reportedError("'vertex.position' has 2 elements; at least 3"));
}

TEST_F(GeometryBadInput, CurveIndexWhoseSegmentLeavesTheVertices)
{
  ANARIGeometry g = geometry("curve", {0, 0, 0, 1, 0, 0});
  setArray(
      g, "primitive.index", array1D(std::vector<uint32_t>{1}, ANARI_UINT32));
  expectOthersStillRender(g);
  EXPECT_TRUE(reportedError("refers to vertex 1"));
}

TEST_F(GeometryBadInput, NonInvertibleInstanceTransformIsSkipped)
{
  ANARIGroup group = anariNewGroup(m_device);
  ANARISurface s = surface(geometry("sphere", {0, 0, 0}), matte(1, 1, 1));
  setArray(group,
      "surface",
      anariNewArray1D(m_device, &s, nullptr, nullptr, ANARI_SURFACE, 1));
  anariRelease(m_device, s);
  anariCommitParameters(m_device, group);
  ANARIInstance instance = anariNewInstance(m_device, "transform");
  anariSetParameter(m_device, instance, "group", ANARI_GROUP, &group);
  const float zeroScale[16] = {0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  anariSetParameter(
      m_device, instance, "transform", ANARI_FLOAT32_MAT4, zeroScale);
  anariCommitParameters(m_device, instance);
  anariRelease(m_device, group);
  ANARIWorld w = anariNewWorld(m_device);
  setArray(w,
      "instance",
      anariNewArray1D(
          m_device, &instance, nullptr, nullptr, ANARI_INSTANCE, 1));
  anariRelease(m_device, instance);
  anariCommitParameters(m_device, w);
  ANARICamera c = orthographic(kEye, kDown, 4.f);
  ANARIRenderer r = renderer("raycast");
  RenderedImage image = render(w, c, r, 8, 8);
  EXPECT_TRUE(std::isinf(image.depthAt(4, 4)));
  auto messages = problems();
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_NE(messages[0].text.find("not invertible"), std::string::npos);
  for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
    anariRelease(m_device, o);
}

TEST_F(GeometryBadInput, CameraFarBeyondFloatRangeRendersNothing)
{
  ANARIWorld w =
      world({surface(geometry("sphere", {0, 0, 0}), matte(1, 1, 1))});
  const float far[3] = {1e30f, 0, 5};
  ANARICamera c = orthographic(far, kDown, 4.f);
  ANARIRenderer r = renderer("raycast");
  RenderedImage image = render(w, c, r, 8, 8);
  EXPECT_TRUE(std::isinf(image.depthAt(4, 4)));
  for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
    anariRelease(m_device, o);
}

} // namespace
