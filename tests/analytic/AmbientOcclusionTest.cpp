// The ao renderer against the analytic occlusion between two parallel
// planes: with cosine-distributed rays of length d from a plane facing
// another at height h < d, the open fraction is (h / d)^2.
#include "AnalyticScene.h"

#include <cmath>

namespace {

class AmbientOcclusionTest : public AnalyticTest
{
 protected:
  // The floor z = 0 facing up, and a ceiling z = h facing down.
  ANARIWorld floorAndCeiling(float h)
  {
    ANARIGeometry floor = geometry(
        "quad", {-100, -100, 0, 100, -100, 0, 100, 100, 0, -100, 100, 0});
    ANARIGeometry ceiling = geometry(
        "quad", {-100, -100, h, -100, 100, h, 100, 100, h, 100, -100, h});
    return world(
        {surface(floor, matte(1, 1, 1)), surface(ceiling, matte(1, 1, 1))});
  }
  // Mean red over all pixels of an accumulated ao render looking down.
  float meanVisibility(ANARIWorld w, float aoDistance, int frames)
  {
    const float eye[3] = {0, 0, 0.5f}, down[3] = {0, 0, -1};
    ANARICamera c = orthographic(eye, down, 1.f);
    ANARIRenderer r = renderer("ao");
    const int32_t samples = 8;
    anariSetParameter(m_device, r, "aoSamples", ANARI_INT32, &samples);
    anariSetParameter(m_device, r, "aoDistance", ANARI_FLOAT32, &aoDistance);
    anariCommitParameters(m_device, r);
    const std::vector<float> p = accumulatedColor(w, c, r, 16, frames);
    double sum = 0;
    for (size_t i = 0; i < p.size(); i += 4)
      sum += p[i];
    for (ANARIObject o : {(ANARIObject)c, (ANARIObject)r})
      anariRelease(m_device, o);
    return float(sum / (p.size() / 4));
  }
};

TEST_F(AmbientOcclusionTest, OpenFractionBetweenParallelPlanes)
{
  ANARIWorld w = floorAndCeiling(1.f);
  // 16x16 pixels x 32 frames x 8 rays = 65536 rays: standard error < 0.002.
  EXPECT_NEAR(meanVisibility(w, 2.f, 32), 0.25f, 0.01f);   // (1/2)^2
  EXPECT_NEAR(meanVisibility(w, 4.f, 32), 0.0625f, 0.01f); // (1/4)^2
  // Rays shorter than the gap never reach the ceiling.
  EXPECT_FLOAT_EQ(meanVisibility(w, 0.9f, 4), 1.f);
  anariRelease(m_device, w);
  EXPECT_TRUE(problems().empty());
}

TEST_F(AmbientOcclusionTest, SeesThroughSurfacesByTheirOpacity)
{
  // A grey floor at z = 0 under a red sheet at z = 0.2 of opacity 0.25
  // (alphaMode blend); the camera looks down from z = 1 and the rays of
  // length 0.1 reach nothing, so a pixel is red where the camera ray stops
  // at the sheet (a quarter of the samples) and grey where it passes.
  ANARIGeometry floor = geometry(
      "quad", {-100, -100, 0, 100, -100, 0, 100, 100, 0, -100, 100, 0});
  ANARIGeometry sheet = geometry("quad",
      {-100, -100, 0.2f, 100, -100, 0.2f, 100, 100, 0.2f, -100, 100, 0.2f});
  ANARIMaterial red = anariNewMaterial(m_device, "matte");
  const float color[3] = {1, 0, 0}, opacity = 0.25f;
  anariSetParameter(m_device, red, "color", ANARI_FLOAT32_VEC3, color);
  anariSetParameter(m_device, red, "opacity", ANARI_FLOAT32, &opacity);
  anariSetParameter(m_device, red, "alphaMode", ANARI_STRING, "blend");
  anariCommitParameters(m_device, red);
  ANARIWorld w =
      world({surface(floor, matte(0.5f, 0.5f, 0.5f)), surface(sheet, red)});
  const float eye[3] = {0, 0, 1}, down[3] = {0, 0, -1};
  ANARICamera c = orthographic(eye, down, 1.f);
  ANARIRenderer r = renderer("ao");
  const float distance = 0.1f;
  anariSetParameter(m_device, r, "aoDistance", ANARI_FLOAT32, &distance);
  anariCommitParameters(m_device, r);
  const std::vector<float> p = accumulatedColor(w, c, r, 16, 64);
  double red_ = 0, green = 0;
  for (size_t i = 0; i < p.size(); i += 4) {
    red_ += p[i];
    green += p[i + 1];
  }
  const double n = double(p.size() / 4);
  // red = 0.25 * 1 + 0.75 * 0.5, green = 0.75 * 0.5; 16384 samples.
  EXPECT_NEAR(red_ / n, 0.625, 0.01);
  EXPECT_NEAR(green / n, 0.375, 0.01);
  for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
    anariRelease(m_device, o);
  EXPECT_TRUE(problems().empty());
}

} // namespace
