// Adaptive sampling (the renderers' errorThreshold): an 8x8 block of
// pixels stops taking samples once the RMS error of its average, estimated
// from the average of its even-numbered samples, is below the threshold.
// Checked against an independent reference (other seeds, many samples):
// the blocks that stopped are as close to it as the threshold says; the
// frame counts the pixels still sampled; off by default.
#include "AnalyticScene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

constexpr uint32_t kBlock = 8; // TileConvergence::kBlockSize

class AdaptiveSampling : public AnalyticTest
{
 protected:
  void SetUp() override
  {
    AnalyticTest::SetUp();
    // A lit box corner: soft shadows and bounces, noisy for a while.
    m_world = boxCorner();
    const float position[3] = {-0.5f, -1.5f, 2.5f}, edge1[3] = {1, 0, 0},
                edge2[3] = {0, 1, 0};
    setOnlyLight(m_world, quadLight(position, edge1, edge2, "intensity", 20.f));
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
  static double blockRmse(const std::vector<float> &a,
      const std::vector<float> &b,
      uint32_t width,
      uint32_t height,
      uint32_t bx,
      uint32_t by)
  {
    double sum = 0.0;
    size_t values = 0;
    for (uint32_t y = by * kBlock; y < std::min((by + 1) * kBlock, height);
         y++) {
      for (uint32_t x = bx * kBlock; x < std::min((bx + 1) * kBlock, width);
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

// The blocks that stopped are within the threshold of an independent
// reference (1024 samples of another seed), and stopped blocks no longer
// change.
TEST_F(AdaptiveSampling, StoppedBlocksMeetTheThreshold)
{
  const uint32_t width = 96, height = 64; // 3 x 2 tiles, 12 x 8 blocks
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
    EXPECT_LE(now, active); // blocks never start again by themselves
    active = now;
  }
  EXPECT_LT(active, uint64_t(width) * height); // some blocks stopped
  // A stopped block's pixels no longer change; its error is the
  // threshold's.
  const std::vector<float> &last = images.back();
  const std::vector<float> &earlier = images[images.size() / 2];
  int sampling = 0;
  std::vector<double> errors;
  for (uint32_t by = 0; by < height / kBlock; by++) {
    for (uint32_t bx = 0; bx < width / kBlock; bx++) {
      if (blockRmse(last, earlier, width, height, bx, by) != 0.0) {
        sampling++; // still sampling at the halfway image
        continue;
      }
      errors.push_back(blockRmse(last, truth, width, height, bx, by));
    }
  }
  // Blocks stop at different times: some early, some later.
  ASSERT_GT(errors.size(), 8u);
  EXPECT_GT(sampling, 0);
  // The estimate is conservative (the path tracer's samples are
  // stratified, so the whole sequence beats its halves): the median
  // stopped block is well within the threshold (0.43 of it here). One
  // block's estimate, from 192 values, is itself uncertain by about 10 %,
  // and the reference a little: no block beyond 1.25 of it (0.96 the
  // largest here).
  std::sort(errors.begin(), errors.end());
  const double median = errors[errors.size() / 2];
  std::printf(
      "%zu blocks stopped by the halfway image, %d later; error "
      "against the reference: median %.4f, largest %.4f\n",
      errors.size(),
      sampling,
      median,
      errors.back());
  EXPECT_LT(median, 0.6 * threshold);
  EXPECT_LT(errors.back(), 1.25 * threshold);
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
