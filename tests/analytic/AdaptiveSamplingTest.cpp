// Adaptive sampling (the renderers' errorThreshold): a tile stops taking
// samples once the RMS error of its average, estimated from the average of
// its even-numbered samples, is below the threshold. Checked against an
// independent reference (other seeds, many samples): the tiles that
// stopped are as close to it as the threshold says; the frame counts the
// pixels still sampled; off by default.
#include "AnalyticScene.h"

#include <cmath>

namespace {

constexpr uint32_t kTile = 32; // the frame's tile size

class AdaptiveSampling : public AnalyticTest
{
 protected:
  void SetUp() override
  {
    AnalyticTest::SetUp();
    // A lit box corner: soft shadows and bounces, noisy for a while.
    m_world = boxCorner();
    ANARILight light = anariNewLight(m_device, "quad");
    const float position[3] = {-0.5f, -1.5f, 2.5f}, edge1[3] = {1, 0, 0},
                edge2[3] = {0, 1, 0}, intensity = 20.f;
    anariSetParameter(
        m_device, light, "position", ANARI_FLOAT32_VEC3, position);
    anariSetParameter(m_device, light, "edge1", ANARI_FLOAT32_VEC3, edge1);
    anariSetParameter(m_device, light, "edge2", ANARI_FLOAT32_VEC3, edge2);
    anariSetParameter(m_device, light, "intensity", ANARI_FLOAT32, &intensity);
    setOnlyLight(m_world, light); // releases the light
    const float eye[3] = {0, -2.5f, 2}, direction[3] = {0, 2.5f, -1.8f};
    m_camera = perspective(eye, direction, 0.8f);
  }
  void TearDown() override
  {
    anariRelease(m_device, m_world);
    anariRelease(m_device, m_camera);
    AnalyticTest::TearDown();
  }
  ANARIRenderer pathTracer(float threshold, int32_t pixelSamples, int32_t seed)
  {
    ANARIRenderer r = renderer("pathtracer");
    anariSetParameter(m_device, r, "errorThreshold", ANARI_FLOAT32, &threshold);
    anariSetParameter(m_device, r, "pixelSamples", ANARI_INT32, &pixelSamples);
    anariSetParameter(m_device, r, "seed", ANARI_INT32, &seed);
    anariCommitParameters(m_device, r);
    return r;
  }
  uint64_t activePixels(ANARIFrame f)
  {
    uint64_t value = ~0ull;
    EXPECT_TRUE(anariGetProperty(m_device,
        f,
        "activePixels",
        ANARI_UINT64,
        &value,
        sizeof(value),
        ANARI_WAIT));
    return value;
  }
  void renderOnce(ANARIFrame f)
  {
    anariRenderFrame(m_device, f);
    anariFrameReady(m_device, f, ANARI_WAIT);
  }
  // The RMS difference of two RGBA images over one tile's RGB values.
  static double tileRmse(const std::vector<float> &a,
      const std::vector<float> &b,
      uint32_t width,
      uint32_t height,
      uint32_t tx,
      uint32_t ty)
  {
    double sum = 0.0;
    size_t values = 0;
    for (uint32_t y = ty * kTile; y < std::min((ty + 1) * kTile, height); y++) {
      for (uint32_t x = tx * kTile; x < std::min((tx + 1) * kTile, width);
           x++) {
        for (int c = 0; c < 3; c++) {
          const double d = a[(size_t(y) * width + x) * 4 + c]
                           - b[(size_t(y) * width + x) * 4 + c];
          sum += d * d;
          values++;
        }
      }
    }
    return std::sqrt(sum / double(values));
  }

  ANARIWorld m_world{nullptr};
  ANARICamera m_camera{nullptr};
};

// Nothing in view: every sample of every tile is the background, the
// estimate is exactly 0, and every tile stops at the minimum of 8 samples
// (not before), whatever the threshold.
TEST_F(AdaptiveSampling, ConstantTilesStopAfterEightSamples)
{
  ANARIWorld empty = world({});
  ANARIRenderer r = pathTracer(1e-6f, 1, 0);
  ANARIFrame f = colorFrame(empty, m_camera, r, 70, 40);
  for (int sample = 1; sample <= 7; sample++)
    renderOnce(f);
  EXPECT_EQ(activePixels(f), 70u * 40u);
  renderOnce(f);
  EXPECT_EQ(activePixels(f), 0u);
  // A converged frame stays as it is.
  const std::vector<float> before = mappedColor(f);
  renderOnce(f);
  EXPECT_EQ(mappedColor(f), before);
  anariRelease(m_device, f);
  anariRelease(m_device, r);
  anariRelease(m_device, empty);
  EXPECT_TRUE(problems().empty());
}

// Off by default: every pixel stays active and the property says so.
TEST_F(AdaptiveSampling, OffByDefaultEveryPixelIsSampled)
{
  ANARIWorld empty = world({});
  ANARIRenderer r = renderer("pathtracer");
  ANARIFrame f = colorFrame(empty, m_camera, r, 70, 40);
  EXPECT_EQ(activePixels(f), 0u); // nothing rendered yet
  for (int sample = 0; sample < 12; sample++)
    renderOnce(f);
  EXPECT_EQ(activePixels(f), 70u * 40u);
  // Asked as another type, or into too small a buffer: not written.
  float asFloat = -1.f;
  EXPECT_FALSE(anariGetProperty(m_device,
      f,
      "activePixels",
      ANARI_FLOAT32,
      &asFloat,
      sizeof(asFloat),
      ANARI_WAIT));
  EXPECT_EQ(asFloat, -1.f);
  uint64_t small = 7;
  EXPECT_FALSE(anariGetProperty(
      m_device, f, "activePixels", ANARI_UINT64, &small, 4, ANARI_WAIT));
  EXPECT_EQ(small, 7u);
  anariRelease(m_device, f);
  anariRelease(m_device, r);
  anariRelease(m_device, empty);
  EXPECT_TRUE(problems().empty());
}

// The tiles that stopped are within the threshold of an independent
// reference (1024 samples of another seed), and stopped tiles no longer
// change.
TEST_F(AdaptiveSampling, StoppedTilesMeetTheThreshold)
{
  const uint32_t width = 96, height = 64; // 3 x 2 tiles
  const float threshold = 0.02f;
  ANARIRenderer reference = pathTracer(0.f, 256, 7);
  ANARIFrame rf = colorFrame(m_world, m_camera, reference, width, height);
  for (int call = 0; call < 4; call++)
    renderOnce(rf);
  const std::vector<float> truth = mappedColor(rf);
  anariRelease(m_device, rf);
  anariRelease(m_device, reference);

  ANARIRenderer r = pathTracer(threshold, 8, 0);
  ANARIFrame f = colorFrame(m_world, m_camera, r, width, height);
  std::vector<std::vector<float>> images;
  uint64_t active = width * height;
  for (int call = 0; call < 32 && active > 0; call++) {
    renderOnce(f);
    images.push_back(mappedColor(f));
    const uint64_t now = activePixels(f);
    EXPECT_LE(now, active); // tiles never start again by themselves
    active = now;
  }
  EXPECT_LT(active, uint64_t(width) * height); // some tiles stopped
  // A stopped tile's pixels no longer change; its error is the threshold's.
  const std::vector<float> &last = images.back();
  const std::vector<float> &earlier = images[images.size() / 2];
  int stopped = 0;
  for (uint32_t ty = 0; ty < 2; ty++) {
    for (uint32_t tx = 0; tx < 3; tx++) {
      if (tileRmse(last, earlier, width, height, tx, ty) != 0.0)
        continue; // still sampling at the halfway image
      stopped++;
      const double error = tileRmse(last, truth, width, height, tx, ty);
      // The estimate is conservative (the path tracer's samples are
      // stratified, so the whole sequence beats its halves): 0.3-0.45 of
      // the threshold here.
      EXPECT_LT(error, threshold) << "tile " << tx << "," << ty;
    }
  }
  EXPECT_GT(stopped, 0);
  anariRelease(m_device, f);
  anariRelease(m_device, r);
  EXPECT_TRUE(problems().empty());
}

// A new threshold restarts the accumulation: every tile samples again.
TEST_F(AdaptiveSampling, ANewThresholdSamplesEveryTileAgain)
{
  ANARIWorld empty = world({});
  ANARIRenderer r = pathTracer(0.5f, 8, 0);
  ANARIFrame f = colorFrame(empty, m_camera, r, 40, 40);
  renderOnce(f);
  EXPECT_EQ(activePixels(f), 0u);
  const float threshold = 0.25f;
  anariSetParameter(m_device, r, "errorThreshold", ANARI_FLOAT32, &threshold);
  const int32_t one = 1;
  anariSetParameter(m_device, r, "pixelSamples", ANARI_INT32, &one);
  anariCommitParameters(m_device, r);
  renderOnce(f);
  EXPECT_EQ(activePixels(f), 40u * 40u);
  anariRelease(m_device, f);
  anariRelease(m_device, r);
  anariRelease(m_device, empty);
  EXPECT_TRUE(problems().empty());
}

} // namespace
