// The renderers' pixelSamples: one anariRenderFrame of N samples per pixel
// gives exactly the image of N one-sample frames (every random choice is
// seeded by pixel and sample index alone, and each tile folds its samples
// into the average in order), counts N samples, and bad counts are
// clamped with a warning.
#include "AnalyticScene.h"

#include <climits>

namespace {

class PixelSamples : public AnalyticTest
{
 protected:
  void SetUp() override
  {
    AnalyticTest::SetUp();
    // A lit box corner: bounces, shadows, occlusion and light sampling.
    m_world = boxCorner();
    ANARILight light = anariNewLight(m_device, "point");
    const float position[3] = {1, -1, 3}, intensity = 10.f;
    anariSetParameter(
        m_device, light, "position", ANARI_FLOAT32_VEC3, position);
    anariSetParameter(m_device, light, "intensity", ANARI_FLOAT32, &intensity);
    setOnlyLight(m_world, light); // releases the light
    const float eye[3] = {0, -5, 3}, direction[3] = {0, 5, -2.5f};
    m_camera = perspective(eye, direction, 0.8f);
  }
  void TearDown() override
  {
    anariRelease(m_device, m_world);
    anariRelease(m_device, m_camera);
    AnalyticTest::TearDown();
  }
  ANARIRenderer samplingRenderer(const char *subtype, int32_t pixelSamples)
  {
    ANARIRenderer r = renderer(subtype);
    anariSetParameter(m_device, r, "pixelSamples", ANARI_INT32, &pixelSamples);
    anariCommitParameters(m_device, r);
    return r;
  }
  // A width x height frame of the box corner, color as floats.
  ANARIFrame frame(
      ANARIRenderer r, bool accumulation, uint32_t width, uint32_t height)
  {
    return colorFrame(m_world, m_camera, r, width, height, accumulation);
  }
  // channel.color after `calls` renders of `f`.
  std::vector<float> renderCalls(ANARIFrame f, int calls)
  {
    for (int i = 0; i < calls; i++) {
      anariRenderFrame(m_device, f);
      anariFrameReady(m_device, f, ANARI_WAIT);
    }
    return mappedColor(f);
  }
  int32_t numSamples(ANARIFrame f)
  {
    int32_t value = -1;
    anariGetProperty(m_device,
        f,
        "numSamples",
        ANARI_INT32,
        &value,
        sizeof(value),
        ANARI_WAIT);
    return value;
  }
  // The image of `samples` accumulated one-sample frames.
  std::vector<float> oneSampleFrames(
      const char *subtype, int samples, uint32_t width, uint32_t height)
  {
    ANARIRenderer r = samplingRenderer(subtype, 1);
    ANARIFrame f = frame(r, true, width, height);
    std::vector<float> image = renderCalls(f, samples);
    anariRelease(m_device, f);
    anariRelease(m_device, r);
    return image;
  }

  ANARIWorld m_world{nullptr};
  ANARICamera m_camera{nullptr};
};

// 70 x 50: whole and partial tiles, more tiles than threads.
TEST_F(PixelSamples, OneCallEqualsAsManyOneSampleFrames)
{
  for (const char *subtype : {"pathtracer", "ao", "raycast"}) {
    SCOPED_TRACE(subtype);
    const std::vector<float> expected = oneSampleFrames(subtype, 6, 70, 50);
    ASSERT_FALSE(expected.empty());
    // Two calls of three samples: the second continues the sequence.
    ANARIRenderer r = samplingRenderer(subtype, 3);
    ANARIFrame f = frame(r, true, 70, 50);
    renderCalls(f, 1);
    EXPECT_EQ(numSamples(f), 3);
    EXPECT_EQ(renderCalls(f, 1), expected);
    EXPECT_EQ(numSamples(f), 6);
    anariRelease(m_device, f);
    anariRelease(m_device, r);
  }
  EXPECT_TRUE(problems().empty());
}

// One tile only: its samples are all taken in order by one thread at a
// time, however many threads claim them.
TEST_F(PixelSamples, ASingleTileTakesItsSamplesInOrder)
{
  const std::vector<float> expected = oneSampleFrames("pathtracer", 8, 9, 7);
  ANARIRenderer r = samplingRenderer("pathtracer", 8);
  ANARIFrame f = frame(r, true, 9, 7);
  EXPECT_EQ(renderCalls(f, 1), expected);
  EXPECT_EQ(numSamples(f), 8);
  anariRelease(m_device, f);
  anariRelease(m_device, r);
  EXPECT_TRUE(problems().empty());
}

// Without accumulation each call shows the average of its own samples,
// the same as the first N accumulated ones.
TEST_F(PixelSamples, WithoutAccumulationEachCallAveragesItsSamples)
{
  const std::vector<float> expected = oneSampleFrames("ao", 4, 40, 40);
  ANARIRenderer r = samplingRenderer("ao", 4);
  ANARIFrame f = frame(r, false, 40, 40);
  EXPECT_EQ(renderCalls(f, 1), expected);
  EXPECT_EQ(renderCalls(f, 1), expected);
  EXPECT_EQ(numSamples(f), 4);
  anariRelease(m_device, f);
  anariRelease(m_device, r);
  EXPECT_TRUE(problems().empty());
}

// A call never takes the accumulation past the renderer's sampleLimit.
TEST_F(PixelSamples, SampleLimitCutsTheLastCallShort)
{
  const std::vector<float> expected = oneSampleFrames("raycast", 5, 33, 33);
  ANARIRenderer r = samplingRenderer("raycast", 3);
  const int32_t limit = 5;
  anariSetParameter(m_device, r, "sampleLimit", ANARI_INT32, &limit);
  anariCommitParameters(m_device, r);
  ANARIFrame f = frame(r, true, 33, 33);
  EXPECT_EQ(renderCalls(f, 3), expected);
  EXPECT_EQ(numSamples(f), 5);
  anariRelease(m_device, f);
  anariRelease(m_device, r);
  EXPECT_TRUE(problems().empty());
}

TEST_F(PixelSamples, CountsBelowOneAreClampedToOne)
{
  const std::vector<float> expected = oneSampleFrames("raycast", 1, 20, 20);
  for (int32_t bad : {0, -1, INT_MIN}) {
    SCOPED_TRACE(bad);
    ANARIRenderer r = samplingRenderer("raycast", bad);
    ANARIFrame f = frame(r, true, 20, 20);
    EXPECT_EQ(renderCalls(f, 1), expected);
    // Commits take effect (and are checked) when the frame renders.
    EXPECT_TRUE(reported(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'pixelSamples'"));
    EXPECT_EQ(numSamples(f), 1);
    anariRelease(m_device, f);
    anariRelease(m_device, r);
  }
}

// A huge count is clamped to the maximum, and discarding the frame stops
// the call early: a cancelled render keeps no partial samples.
TEST_F(PixelSamples, HugeCountsAreClampedAndCanBeDiscarded)
{
  ANARIRenderer r = samplingRenderer("pathtracer", INT_MAX);
  ANARIFrame f = frame(r, true, 64, 64);
  anariRenderFrame(m_device, f);
  // Discarded once under way: 65536 samples would take minutes.
  float progress = 0.f;
  while (progress == 0.f && !anariFrameReady(m_device, f, ANARI_NO_WAIT))
    anariGetProperty(m_device,
        f,
        "renderProgress",
        ANARI_FLOAT32,
        &progress,
        sizeof(progress),
        ANARI_NO_WAIT);
  EXPECT_LT(progress, 1.f);
  anariDiscardFrame(m_device, f);
  anariFrameReady(m_device, f, ANARI_WAIT);
  EXPECT_TRUE(reported(ANARI_SEVERITY_WARNING,
      ANARI_STATUS_INVALID_ARGUMENT,
      "clamped to 65536"));
  EXPECT_EQ(numSamples(f), 0);
  anariRelease(m_device, f);
  anariRelease(m_device, r);
  EXPECT_TRUE(problems().empty());
}

} // namespace
