// Bad motion blur input is reported through the status callback and the
// object falls back: instances to 'transform', cameras to their static
// pose, deforming meshes to 'vertex.position' (or become invalid without
// it), unusable normal keys are ignored.
#include "AnalyticScene.h"

#include <cmath>

namespace {

const float kEye[3] = {0, 0, 5};
const float kDown[3] = {0, 0, -1};

using Mat4 = std::array<float, 16>;

Mat4 translation(float x)
{
  return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, x, 0, 0, 1};
}

class MotionBadInput : public AnalyticTest
{
 protected:
  // A unit square centred at the origin, facing +z.
  static std::vector<float> square(float offsetX = 0.f)
  {
    return {-0.5f + offsetX,
        -0.5f,
        0,
        0.5f + offsetX,
        -0.5f,
        0,
        0.5f + offsetX,
        0.5f,
        0,
        -0.5f + offsetX,
        0.5f,
        0};
  }
  ANARIArray1D matrices(const std::vector<Mat4> &keys)
  {
    std::vector<float> flat;
    for (const Mat4 &m : keys)
      flat.insert(flat.end(), m.begin(), m.end());
    return array1D(flat, ANARI_FLOAT32_MAT4);
  }
  ANARIArray1D arrayOfArrays(const std::vector<ANARIArray1D> &keys)
  {
    ANARIArray1D out = anariNewArray1D(
        m_device, keys.data(), nullptr, nullptr, ANARI_ARRAY1D, keys.size());
    for (ANARIArray1D a : keys)
      anariRelease(m_device, a);
    return out;
  }
  // An uncommitted instance of the unit square's group.
  ANARIInstance squareInstance(const char *subtype)
  {
    ANARISurface s = surface(geometry("quad", square()), matte(1, 1, 1));
    ANARIGroup g = anariNewGroup(m_device);
    setArray(g,
        "surface",
        anariNewArray1D(m_device, &s, nullptr, nullptr, ANARI_SURFACE, 1));
    anariCommitParameters(m_device, g);
    anariRelease(m_device, s);
    ANARIInstance i = anariNewInstance(m_device, subtype);
    anariSetParameter(m_device, i, "group", ANARI_GROUP, &g);
    anariRelease(m_device, g);
    return i;
  }
  // The x of the covered pixels' centre, rendering `world` (released) at
  // shutter time `time` with `camera` (NULL: an orthographic one looking
  // down); NaN if nothing shows.
  float coveredCentreX(ANARIWorld w, float time, ANARICamera c = nullptr)
  {
    if (!c)
      c = orthographic(kEye, kDown, 4.f);
    const float shutter[2] = {time, time};
    anariSetParameter(m_device, c, "shutter", ANARI_FLOAT32_BOX1, shutter);
    anariCommitParameters(m_device, c);
    ANARIRenderer r = renderer("raycast");
    RenderedImage image = render(w, c, r, 32, 32);
    anariRelease(m_device, w);
    anariRelease(m_device, c);
    anariRelease(m_device, r);
    double sum = 0.0;
    int count = 0;
    for (uint32_t y = 0; y < 32; y++) {
      for (uint32_t x = 0; x < 32; x++) {
        if (image.pixel(x, y)[0] > 0.5f) {
          sum += -2.0 + 0.125 * (x + 0.5);
          count++;
        }
      }
    }
    return count ? float(sum / count) : NAN;
  }
  ANARIWorld worldOf(ANARIInstance i)
  {
    anariCommitParameters(m_device, i);
    ANARIWorld w = anariNewWorld(m_device);
    setArray(w,
        "instance",
        anariNewArray1D(m_device, &i, nullptr, nullptr, ANARI_INSTANCE, 1));
    anariRelease(m_device, i);
    anariCommitParameters(m_device, w);
    return w;
  }
  // One error naming the problem (the invalid surface's own warnings are
  // not counted).
  ::testing::AssertionResult reportedError(const std::string &fragment)
  {
    std::string all;
    int matches = 0;
    for (auto &m : problems()) {
      all += m.text + "\n";
      matches += m.severity == ANARI_SEVERITY_ERROR
                 && m.code == ANARI_STATUS_INVALID_ARGUMENT
                 && m.text.find(fragment) != std::string::npos;
    }
    if (matches == 1)
      return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "expected one error with '" << fragment << "', got:\n"
           << all;
  }
  ::testing::AssertionResult warned(const std::string &fragment)
  {
    return reported(
        ANARI_SEVERITY_WARNING, ANARI_STATUS_INVALID_ARGUMENT, fragment);
  }
};

TEST_F(MotionBadInput, MotionTransformOfTheWrongElementType)
{
  ANARIInstance i = squareInstance("motionTransform");
  const Mat4 fallback = translation(1.f);
  anariSetParameter(
      m_device, i, "transform", ANARI_FLOAT32_MAT4, fallback.data());
  setArray(i,
      "motion.transform",
      array1D(std::vector<float>{1, 2, 3}, ANARI_FLOAT32_VEC3));
  EXPECT_NEAR(coveredCentreX(worldOf(i), 0.5f), 1.f, 1e-3f);
  EXPECT_TRUE(warned("'motion.transform' has element type"));
}

TEST_F(MotionBadInput, NonInvertibleKeyDropsTheMotion)
{
  ANARIInstance i = squareInstance("motionTransform");
  Mat4 flat = translation(1.f);
  flat[10] = 0.f; // z scaled to nothing
  setArray(i, "motion.transform", matrices({translation(-1.f), flat}));
  EXPECT_NEAR(coveredCentreX(worldOf(i), 0.5f), 0.f, 1e-3f);
  EXPECT_TRUE(warned("motion key 1 is not finite or not invertible"));
}

TEST_F(MotionBadInput, ReversedTimeUsesTheWholeShutter)
{
  ANARIInstance i = squareInstance("motionTransform");
  setArray(
      i, "motion.transform", matrices({translation(-1.f), translation(1.f)}));
  const float reversed[2] = {1.f, 0.f};
  anariSetParameter(m_device, i, "time", ANARI_FLOAT32_BOX1, reversed);
  EXPECT_NEAR(coveredCentreX(worldOf(i), 1.f), 1.f, 1e-3f);
  EXPECT_TRUE(warned("'time' [1, 0] is not an interval"));
}

TEST_F(MotionBadInput, DecomposedKeysOfDifferentLengthsAreResampled)
{
  ANARIInstance i = squareInstance("motionScaleRotationTranslation");
  // Three translation keys (x = -1, 0, 1) but two scale keys: both span
  // the shutter, so at t = 0.75 the square is at x = 0.5.
  setArray(i,
      "motion.translation",
      array1D(
          std::vector<float>{-1, 0, 0, 0, 0, 0, 1, 0, 0}, ANARI_FLOAT32_VEC3));
  setArray(i,
      "motion.scale",
      array1D(std::vector<float>{1, 1, 1, 1, 1, 1}, ANARI_FLOAT32_VEC3));
  EXPECT_NEAR(coveredCentreX(worldOf(i), 0.75f), 0.5f, 0.07f);
  EXPECT_TRUE(warned("have 2, 0 and 3 keys; each is resampled to 3"));
}

TEST_F(MotionBadInput, ZeroQuaternionDropsTheMotion)
{
  ANARIInstance i = squareInstance("motionScaleRotationTranslation");
  setArray(i,
      "motion.rotation",
      array1D(
          std::vector<float>{0, 0, 0, 1, 0, 0, 0, 0}, ANARI_FLOAT32_QUAT_IJKW));
  EXPECT_NEAR(coveredCentreX(worldOf(i), 0.5f), 0.f, 1e-3f);
  EXPECT_TRUE(warned("motion key 1 is not finite or not invertible"));
}

TEST_F(MotionBadInput, CameraMotionOfTheWrongElementType)
{
  ANARIGeometry g = geometry("quad", square());
  ANARIWorld w = world({surface(g, matte(1, 1, 1))});
  ANARICamera c = orthographic(kEye, kDown, 4.f);
  setArray(c,
      "motion.transform",
      array1D(std::vector<float>{1, 0, 0, 0}, ANARI_FLOAT32_VEC4));
  EXPECT_NEAR(coveredCentreX(w, 0.5f, c), 0.f, 1e-3f);
  EXPECT_TRUE(warned("'motion.transform' has element type"));
}

TEST_F(MotionBadInput, UnknownRollingShutterDirection)
{
  ANARIGeometry g = geometry("quad", square());
  ANARIWorld w = world({surface(g, matte(1, 1, 1))});
  ANARICamera c = orthographic(kEye, kDown, 4.f);
  anariSetParameter(
      m_device, c, "rollingShutterDirection", ANARI_STRING, "sideways");
  EXPECT_NEAR(coveredCentreX(w, 0.5f, c), 0.f, 1e-3f);
  EXPECT_TRUE(
      warned("'rollingShutterDirection' (\"sideways\") must be one of: "
             "none, left, right, down, up"));
}

TEST_F(MotionBadInput, VertexKeysOfDifferentSizesFallBackToVertexPosition)
{
  ANARIGeometry g = geometry("quad", square(1.f));
  std::vector<float> five = square(-1.f);
  five.insert(five.end(), {0, 0, 0});
  setArray(g,
      "motion.vertex.position",
      arrayOfArrays({array1D(square(-1.f), ANARI_FLOAT32_VEC3),
          array1D(five, ANARI_FLOAT32_VEC3)}));
  ANARIWorld w = world({surface(g, matte(1, 1, 1))});
  EXPECT_NEAR(coveredCentreX(w, 0.5f), 1.f, 1e-3f);
  EXPECT_TRUE(warned("key 1 has 5 vertices but key 0 has 4"));
}

TEST_F(MotionBadInput, VertexKeysOfDifferentSizesWithoutFallbackAreInvalid)
{
  ANARIGeometry g = anariNewGeometry(m_device, "triangle");
  setArray(g,
      "motion.vertex.position",
      arrayOfArrays({array1D(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0},
                         ANARI_FLOAT32_VEC3),
          array1D(std::vector<float>{0, 0, 0, 1, 0, 0}, ANARI_FLOAT32_VEC3)}));
  ANARIWorld w = world({surface(g, matte(1, 1, 1))});
  EXPECT_TRUE(std::isnan(coveredCentreX(w, 0.5f)));
  EXPECT_TRUE(reportedError("key 1 has 2 vertices but key 0 has 3"));
}

TEST_F(MotionBadInput, VertexKeysOfTheWrongElementTypeAreInvalid)
{
  ANARIGeometry g = anariNewGeometry(m_device, "quad");
  setArray(g,
      "motion.vertex.position",
      arrayOfArrays({array1D(std::vector<float>{0, 0, 0, 1}, ANARI_FLOAT32)}));
  ANARIWorld w = world({surface(g, matte(1, 1, 1))});
  EXPECT_TRUE(std::isnan(coveredCentreX(w, 0.5f)));
  EXPECT_TRUE(reportedError("'motion.vertex.position' key 0 has element type"));
}

TEST_F(MotionBadInput, ShortNormalKeysAreIgnored)
{
  ANARIGeometry g = anariNewGeometry(m_device, "quad");
  setArray(g,
      "motion.vertex.position",
      arrayOfArrays({array1D(square(-1.f), ANARI_FLOAT32_VEC3),
          array1D(square(1.f), ANARI_FLOAT32_VEC3)}));
  setArray(g,
      "motion.vertex.normal",
      arrayOfArrays(
          {array1D(std::vector<float>{0, 0, 1}, ANARI_FLOAT32_VEC3)}));
  ANARIWorld w = world({surface(g, matte(1, 1, 1))});
  EXPECT_NEAR(coveredCentreX(w, 1.f), 1.f, 1e-3f);
  EXPECT_TRUE(warned("key 0 has 1 normals for 4 vertices"));
}

TEST_F(MotionBadInput, NormalKeysWithoutPositionKeysAreIgnored)
{
  ANARIGeometry g = geometry("quad", square());
  setArray(g,
      "motion.vertex.normal",
      arrayOfArrays({array1D(square(), ANARI_FLOAT32_VEC3)}));
  ANARIWorld w = world({surface(g, matte(1, 1, 1))});
  EXPECT_NEAR(coveredCentreX(w, 0.5f), 0.f, 1e-3f);
  EXPECT_TRUE(warned("ignored without 'motion.vertex.position'"));
}

} // namespace
