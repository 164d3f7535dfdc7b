// Motion blur with known answers: a white unit-wide strip moving along x
// seen straight on by an orthographic camera (the raycast renderer then
// shows coverage exactly). Accumulated over the shutter, a point the strip
// passes is covered for the fraction of the shutter the strip spends over
// it: instance motion (both subtypes), mesh deformation (triangles and
// quads) and camera motion all give that fraction; a closed shutter, the
// first sample and keys outside their time give sharp images; a rolling
// shutter shears the strip; moving instances shade with their normal at
// the ray's time; path-traced bounces see the scene at the ray's time.
#include "AnalyticScene.h"

#include <array>
#include <cmath>
#include <functional>
#include <string>

namespace {

// The image covers x in [-4, 4] and y in [-1, 1] with pixels 0.125 wide.
constexpr uint32_t kWidth = 64, kHeight = 16;
constexpr float kPixel = 8.f / float(kWidth);

float pixelCentreX(uint32_t column)
{
  return -4.f + kPixel * (float(column) + 0.5f);
}

// The strip's centre at time t when it moves from x = -2 to x = 2 over
// [0, 1]: every point with |x| <= 1.5 is covered a quarter of the time.
float stripCentre(float t)
{
  return -2.f + 4.f * t;
}

using Mat4 = std::array<float, 16>;
using Box1 = std::array<float, 2>;

Mat4 translation(float x, float y = 0.f, float z = 0.f)
{
  return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, x, y, z, 1};
}

class MotionBlur : public AnalyticTest
{
 protected:
  void TearDown() override
  {
    for (ANARIObject o : m_objects)
      anariRelease(m_device, o);
    m_objects.clear();
    // Every test here is valid input: the device must not complain.
    for (auto &m : problems())
      ADD_FAILURE() << "device problem: " << m.text;
    AnalyticTest::TearDown();
  }
  template <typename T>
  T keep(T object)
  {
    m_objects.push_back(object);
    return object;
  }

  // The strip at rest: x in [-0.5, 0.5], y in [-10, 10], facing +z.
  static std::vector<float> stripCorners(float offsetX = 0.f)
  {
    return {-0.5f + offsetX,
        -10,
        0,
        0.5f + offsetX,
        -10,
        0,
        0.5f + offsetX,
        10,
        0,
        -0.5f + offsetX,
        10,
        0};
  }
  ANARISurface strip()
  {
    return surface(geometry("quad", stripCorners()), matte(1, 1, 1));
  }
  ANARIGroup group(ANARISurface s)
  {
    ANARIGroup g = anariNewGroup(m_device);
    setArray(g,
        "surface",
        anariNewArray1D(m_device, &s, nullptr, nullptr, ANARI_SURFACE, 1));
    anariCommitParameters(m_device, g);
    anariRelease(m_device, s);
    return g;
  }
  ANARIArray1D matrices(const std::vector<Mat4> &keys)
  {
    std::vector<float> flat;
    for (const Mat4 &m : keys)
      flat.insert(flat.end(), m.begin(), m.end());
    return array1D(flat, ANARI_FLOAT32_MAT4);
  }
  // A committed instance of `subtype` holding the group of `s`, after
  // `configure` set its motion parameters.
  ANARIInstance instance(const char *subtype,
      ANARISurface s,
      const std::function<void(ANARIInstance)> &configure)
  {
    ANARIInstance i = anariNewInstance(m_device, subtype);
    ANARIGroup g = group(s);
    anariSetParameter(m_device, i, "group", ANARI_GROUP, &g);
    anariRelease(m_device, g);
    configure(i);
    anariCommitParameters(m_device, i);
    return i;
  }
  ANARIWorld worldOf(ANARIInstance i)
  {
    ANARIWorld w = anariNewWorld(m_device);
    setArray(w,
        "instance",
        anariNewArray1D(m_device, &i, nullptr, nullptr, ANARI_INSTANCE, 1));
    anariRelease(m_device, i);
    anariCommitParameters(m_device, w);
    return keep(w);
  }
  // The strip moving from x = -2 to 2 over time [0, 1] by motion.transform.
  ANARIWorld movingStrip()
  {
    return worldOf(instance("motionTransform", strip(), [&](ANARIInstance i) {
      setArray(i,
          "motion.transform",
          matrices({translation(-2.f), translation(2.f)}));
    }));
  }
  // Looking down at the xy plane; configure adds shutter and motion.
  ANARICamera camera(
      Box1 shutter, const std::function<void(ANARICamera)> &configure = {})
  {
    ANARICamera c = anariNewCamera(m_device, "orthographic");
    const float eye[3] = {0, 0, 5}, down[3] = {0, 0, -1};
    const float height = 2.f, aspect = float(kWidth) / float(kHeight);
    anariSetParameter(m_device, c, "position", ANARI_FLOAT32_VEC3, eye);
    anariSetParameter(m_device, c, "direction", ANARI_FLOAT32_VEC3, down);
    anariSetParameter(m_device, c, "height", ANARI_FLOAT32, &height);
    anariSetParameter(m_device, c, "aspect", ANARI_FLOAT32, &aspect);
    anariSetParameter(
        m_device, c, "shutter", ANARI_FLOAT32_BOX1, shutter.data());
    if (configure)
      configure(c);
    anariCommitParameters(m_device, c);
    return keep(c);
  }
  ANARIRenderer raycast()
  {
    return keep(renderer("raycast"));
  }
  // The red channel after accumulating `frames` samples per pixel.
  std::vector<float> accumulate(ANARIWorld w,
      ANARICamera c,
      ANARIRenderer r,
      int frames,
      uint32_t width = kWidth,
      uint32_t height = kHeight)
  {
    ANARIFrame f = anariNewFrame(m_device);
    const uint32_t size[2] = {width, height};
    const ANARIDataType color = ANARI_FLOAT32_VEC4;
    const uint8_t on = 1;
    anariSetParameter(m_device, f, "world", ANARI_WORLD, &w);
    anariSetParameter(m_device, f, "camera", ANARI_CAMERA, &c);
    anariSetParameter(m_device, f, "renderer", ANARI_RENDERER, &r);
    anariSetParameter(m_device, f, "size", ANARI_UINT32_VEC2, size);
    anariSetParameter(m_device, f, "channel.color", ANARI_DATA_TYPE, &color);
    anariSetParameter(m_device, f, "accumulation", ANARI_BOOL, &on);
    anariCommitParameters(m_device, f);
    for (int i = 0; i < frames; i++) {
      anariRenderFrame(m_device, f);
      anariFrameReady(m_device, f, ANARI_WAIT);
    }
    uint32_t w2 = 0, h2 = 0;
    ANARIDataType type;
    auto *p = (const float *)anariMapFrame(
        m_device, f, "channel.color", &w2, &h2, &type);
    std::vector<float> red(size_t(width) * height, -1.f);
    for (size_t i = 0; p && i < red.size(); i++)
      red[i] = p[4 * i];
    anariUnmapFrame(m_device, f, "channel.color");
    anariRelease(m_device, f);
    return red;
  }
  // Every pixel whose centre |x| <= 1.4 shows the strip a quarter of the
  // time (within `pixelTolerance`, their mean within 0.01); pixels with
  // |x| >= 2.6 never see it.
  void expectQuarterCoverage(
      const std::vector<float> &red, float pixelTolerance = 0.06f)
  {
    double sum = 0.0;
    int count = 0;
    for (uint32_t y = 0; y < kHeight; y++) {
      for (uint32_t x = 0; x < kWidth; x++) {
        const float at = pixelCentreX(x);
        const float value = red[y * kWidth + x];
        if (std::abs(at) <= 1.4f) {
          EXPECT_NEAR(value, 0.25f, pixelTolerance)
              << "pixel " << x << ", " << y;
          sum += value;
          count++;
        } else if (std::abs(at) >= 2.6f) {
          EXPECT_EQ(value, 0.f) << "pixel " << x << ", " << y;
        }
      }
    }
    ASSERT_GT(count, 0);
    EXPECT_NEAR(sum / count, 0.25, 0.01);
  }
  // The sharp strip centred at `centre`: 1 over it, 0 elsewhere (pixels
  // within `margin` of its edges are not checked).
  void expectSharpStrip(
      const std::vector<float> &red, float centre, float margin = 0.07f)
  {
    for (uint32_t y = 0; y < kHeight; y++) {
      for (uint32_t x = 0; x < kWidth; x++) {
        const float distance = std::abs(pixelCentreX(x) - centre);
        if (std::abs(distance - 0.5f) < margin)
          continue;
        EXPECT_EQ(red[y * kWidth + x], distance < 0.5f ? 1.f : 0.f)
            << "pixel " << x << ", " << y;
      }
    }
  }

 private:
  std::vector<ANARIObject> m_objects;
};

constexpr int kFrames = 64;

TEST_F(MotionBlur, InstanceCoverageIsTheFractionOfTheShutter)
{
  expectQuarterCoverage(
      accumulate(movingStrip(), camera({0.f, 1.f}), raycast(), kFrames));
}

TEST_F(MotionBlur, DecomposedInstanceCoverageIsTheFractionOfTheShutter)
{
  // Three translation keys (multi-segment) and identity rotations.
  ANARIWorld w = worldOf(
      instance("motionScaleRotationTranslation", strip(), [&](ANARIInstance i) {
        setArray(i,
            "motion.translation",
            array1D(std::vector<float>{-2, 0, 0, 0, 0, 0, 2, 0, 0},
                ANARI_FLOAT32_VEC3));
        setArray(i,
            "motion.rotation",
            array1D(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1},
                ANARI_FLOAT32_QUAT_IJKW));
        setArray(i,
            "motion.scale",
            array1D(std::vector<float>{1, 1, 1, 1, 1, 1, 1, 1, 1},
                ANARI_FLOAT32_VEC3));
      }));
  expectQuarterCoverage(accumulate(w, camera({0.f, 1.f}), raycast(), kFrames));
}

TEST_F(MotionBlur, FirstSampleIsAtTheShutterMidpoint)
{
  ANARIWorld w = movingStrip();
  expectSharpStrip(
      accumulate(w, camera({0.f, 1.f}), raycast(), 1), stripCentre(0.5f));
  expectSharpStrip(
      accumulate(w, camera({0.f, 0.5f}), raycast(), 1), stripCentre(0.25f));
}

TEST_F(MotionBlur, ClosedShutterIsSharp)
{
  // The strip's edges at t = 0.25 (x = -1.5, -0.5) lie on pixel borders,
  // so even jittered samples see every pixel fully covered or empty.
  expectSharpStrip(
      accumulate(movingStrip(), camera({0.25f, 0.25f}), raycast(), 16),
      stripCentre(0.25f),
      0.f);
}

TEST_F(MotionBlur, KeysHoldBeforeAndAfterTheirTime)
{
  // The keys span t in [0.25, 0.5]; before and after, the first and the
  // last key hold (the strip never vanishes).
  ANARIWorld w =
      worldOf(instance("motionTransform", strip(), [&](ANARIInstance i) {
        setArray(i,
            "motion.transform",
            matrices({translation(-2.f), translation(2.f)}));
        const float time[2] = {0.25f, 0.5f};
        anariSetParameter(m_device, i, "time", ANARI_FLOAT32_BOX1, time);
      }));
  expectSharpStrip(accumulate(w, camera({0.1f, 0.1f}), raycast(), 1), -2.f);
  expectSharpStrip(accumulate(w, camera({0.9f, 0.9f}), raycast(), 1), 2.f);
  expectSharpStrip(accumulate(w, camera({0.375f, 0.375f}), raycast(), 1), 0.f);
}

TEST_F(MotionBlur, DeformingTrianglesCoverTheFractionOfTheShutter)
{
  // Two triangles of the strip at three keys: x offsets -2, 0 and 2.
  ANARIGeometry g = anariNewGeometry(m_device, "triangle");
  std::vector<ANARIArray1D> keys;
  for (float offset : {-2.f, 0.f, 2.f}) {
    const std::vector<float> c = stripCorners(offset);
    std::vector<float> soup;
    for (int corner : {0, 1, 2, 0, 2, 3})
      soup.insert(
          soup.end(), c.begin() + 3 * corner, c.begin() + 3 * corner + 3);
    keys.push_back(array1D(soup, ANARI_FLOAT32_VEC3));
  }
  setArray(g,
      "motion.vertex.position",
      anariNewArray1D(
          m_device, keys.data(), nullptr, nullptr, ANARI_ARRAY1D, keys.size()));
  for (ANARIArray1D a : keys)
    anariRelease(m_device, a);
  ANARIWorld w = keep(world({surface(g, matte(1, 1, 1))}));
  expectQuarterCoverage(accumulate(w, camera({0.f, 1.f}), raycast(), kFrames));
}

TEST_F(MotionBlur, DeformingQuadsCoverTheFractionOfTheShutter)
{
  ANARIGeometry g = anariNewGeometry(m_device, "quad");
  std::vector<ANARIArray1D> keys;
  for (float offset : {-2.f, 2.f})
    keys.push_back(array1D(stripCorners(offset), ANARI_FLOAT32_VEC3));
  setArray(g,
      "motion.vertex.position",
      anariNewArray1D(
          m_device, keys.data(), nullptr, nullptr, ANARI_ARRAY1D, keys.size()));
  for (ANARIArray1D a : keys)
    anariRelease(m_device, a);
  // Deformation inside an instance: the group's scene is traced at the
  // ray's time through the instance level too.
  ANARIWorld w = worldOf(
      instance("transform", surface(g, matte(1, 1, 1)), [](ANARIInstance) {}));
  expectQuarterCoverage(accumulate(w, camera({0.f, 1.f}), raycast(), kFrames));
}

TEST_F(MotionBlur, CameraMotionMirrorsObjectMotion)
{
  // A camera moving from x = 2 to -2 sees the resting strip move from -2
  // to 2: whole matrices and decomposed translations alike.
  ANARIWorld w = keep(world({strip()}));
  ANARICamera byMatrices = camera({0.f, 1.f}, [&](ANARICamera c) {
    setArray(
        c, "motion.transform", matrices({translation(2.f), translation(-2.f)}));
  });
  expectQuarterCoverage(accumulate(w, byMatrices, raycast(), kFrames));
  ANARICamera byTranslation = camera({0.f, 1.f}, [&](ANARICamera c) {
    setArray(c,
        "motion.translation",
        array1D(std::vector<float>{2, 0, 0, -2, 0, 0}, ANARI_FLOAT32_VEC3));
  });
  expectQuarterCoverage(accumulate(w, byTranslation, raycast(), kFrames));
  // Between samples the camera is where its keys put it.
  expectSharpStrip(accumulate(w, byTranslation, raycast(), 1), 0.f);
}

TEST_F(MotionBlur, RollingShutterShearsTheStrip)
{
  // With no open time per line, each row records one instant: "down"
  // starts at the top row (t = 0) and ends at the bottom (t = 1), "up"
  // the other way round; each row shows the strip sharp where it was then.
  ANARIWorld w = movingStrip();
  for (const char *direction : {"down", "up"}) {
    ANARICamera c = camera({0.f, 1.f}, [&](ANARICamera c) {
      anariSetParameter(
          m_device, c, "rollingShutterDirection", ANARI_STRING, direction);
    });
    const std::vector<float> red = accumulate(w, c, raycast(), 1);
    const bool down = std::string(direction) == "down";
    for (uint32_t y = 0; y < kHeight; y++) {
      const float screenY = (float(y) + 0.5f) / float(kHeight);
      const float centre = stripCentre(down ? 1.f - screenY : screenY);
      for (uint32_t x = 0; x < kWidth; x++) {
        const float distance = std::abs(pixelCentreX(x) - centre);
        if (std::abs(distance - 0.5f) < 1e-3f)
          continue;
        EXPECT_EQ(red[y * kWidth + x], distance < 0.5f ? 1.f : 0.f)
            << direction << " pixel " << x << ", " << y;
      }
    }
  }
  // A line open for the whole shutter (the duration is clamped to it) is
  // the global shutter again.
  ANARICamera whole = camera({0.f, 1.f}, [&](ANARICamera c) {
    const float duration = 2.f;
    anariSetParameter(
        m_device, c, "rollingShutterDirection", ANARI_STRING, "right");
    anariSetParameter(
        m_device, c, "rollingShutterDuration", ANARI_FLOAT32, &duration);
  });
  expectQuarterCoverage(accumulate(w, whole, raycast(), kFrames));
}

TEST_F(MotionBlur, MovingInstancesShadeWithTheirNormalAtTheRayTime)
{
  // The strip turns 60 degrees about y over the shutter; at t = 1 its
  // normal makes 60 degrees with the view, so the raycast eye light
  // (0.5 |cos| + 0.5) is 0.75 (0.93 at the midpoint's 30 degrees).
  const float half = 0.5f * 60.f * float(M_PI) / 180.f;
  ANARIWorld w = worldOf(
      instance("motionScaleRotationTranslation", strip(), [&](ANARIInstance i) {
        setArray(i,
            "motion.rotation",
            array1D(
                std::vector<float>{
                    0, 0, 0, 1, 0, std::sin(half), 0, std::cos(half)},
                ANARI_FLOAT32_QUAT_IJKW));
      }));
  const std::vector<float> end =
      accumulate(w, camera({1.f, 1.f}), raycast(), 1);
  EXPECT_NEAR(end[8 * kWidth + 32], 0.75f, 1e-3f);
  const std::vector<float> middle =
      accumulate(w, camera({0.5f, 0.5f}), raycast(), 1);
  EXPECT_NEAR(middle[8 * kWidth + 32], 0.5f * std::cos(half) + 0.5f, 1e-3f);
}

TEST_F(MotionBlur, PathTracedBouncesSeeTheSceneAtTheRayTime)
{
  // A white ground lit only by a white ambient light. A tall black wall
  // rises from below the ground (t = 0) to stand on it (t = 1), where it
  // hides half of every ground point's sky: the ground's radiance is 1
  // with the wall below, 1/2 with it standing. At the shutter midpoint it
  // is still below the ground, so bounces traced at any other time than
  // their camera ray's would see the whole sky.
  ANARISurface ground = surface(
      geometry("quad",
          {-1000, -1000, 0, 1000, -1000, 0, 1000, 1000, 0, -1000, 1000, 0}),
      matte(1, 1, 1));
  ANARISurface wall = surface(geometry("quad",
                                  {0.05f,
                                      -1000,
                                      0,
                                      0.05f,
                                      1000,
                                      0,
                                      0.05f,
                                      1000,
                                      1000,
                                      0.05f,
                                      -1000,
                                      1000}),
      matte(0, 0, 0));
  ANARIInstance rising =
      instance("motionTransform", wall, [&](ANARIInstance i) {
        setArray(i,
            "motion.transform",
            matrices({translation(0, 0, -2000.f), translation(0, 0, 0)}));
      });
  ANARIGroup groundGroup = group(ground);
  ANARIInstance still = anariNewInstance(m_device, "transform");
  anariSetParameter(m_device, still, "group", ANARI_GROUP, &groundGroup);
  anariCommitParameters(m_device, still);
  anariRelease(m_device, groundGroup);
  ANARIInstance both[2] = {rising, still};
  ANARIWorld w = keep(anariNewWorld(m_device));
  setArray(w,
      "instance",
      anariNewArray1D(m_device, both, nullptr, nullptr, ANARI_INSTANCE, 2));
  anariRelease(m_device, rising);
  anariRelease(m_device, still);
  anariCommitParameters(m_device, w);

  ANARIRenderer r = keep(renderer("pathtracer"));
  const float ambient = 1.f;
  anariSetParameter(m_device, r, "ambientRadiance", ANARI_FLOAT32, &ambient);
  anariCommitParameters(m_device, r);
  auto meanRadiance = [&](float time) {
    const std::vector<float> red =
        accumulate(w, camera({time, time}), r, 32, 32, 32);
    double sum = 0.0;
    for (float v : red)
      sum += v;
    return sum / double(red.size());
  };
  EXPECT_NEAR(meanRadiance(1.f), 0.5, 0.03);
  EXPECT_NEAR(meanRadiance(0.f), 1.0, 0.03);
}

} // namespace
