// KHR_FRAME_ACCUMULATION with the raycast renderer (and the path tracer):
// samples jitter within pixels (anti-aliasing, depth of field), the first
// sample stays exact, any committed change restarts, and the result is
// deterministic.
#include "AnalyticScene.h"

#include <tbb/global_control.h>

#include <cmath>
#include <optional>

namespace {

const float kEye[3] = {0, 0, 5};
const float kDown[3] = {0, 0, -1};

class Accumulation : public AnalyticTest
{
 protected:
  // A white square covering x in [-10, 0]: the left half of the view.
  ANARIWorld halfPlane()
  {
    ANARIGeometry g =
        geometry("quad", {-10, -10, 0, 0, -10, 0, 0, 10, 0, -10, 10, 0});
    return world({surface(g, matte(1, 1, 1))});
  }
  ANARIFrame frame(ANARIWorld w, ANARICamera c, ANARIRenderer r, uint32_t size)
  {
    return colorFrame(w, c, r, size, size);
  }
  std::vector<float> renderSamples(ANARIFrame f, int samples)
  {
    for (int i = 0; i < samples; i++) {
      anariRenderFrame(m_device, f);
      anariFrameReady(m_device, f, ANARI_WAIT);
    }
    return mappedColor(f);
  }
  float refinement(ANARIFrame f)
  {
    float value = -1.f;
    anariGetProperty(m_device,
        f,
        "refinementProgress",
        ANARI_FLOAT32,
        &value,
        sizeof(value),
        ANARI_WAIT);
    return value;
  }
};

TEST_F(Accumulation, SamplesAntiAliasAnEdgeToItsCoverage)
{
  ANARIWorld w = halfPlane();
  // 5 pixels over x in [-1.25, 1.25]: pixel 2 spans [-0.25, 0.25], half
  // covered by the plane's edge at x = 0.
  ANARICamera c = orthographic(kEye, kDown, 2.5f);
  ANARIRenderer r = renderer("raycast");
  ANARIFrame f = frame(w, c, r, 5);
  const std::vector<float> first = renderSamples(f, 1);
  // The first sample goes through the pixel centre (x = 0, on the edge
  // which the quad's closed boundary includes): exact and unjittered.
  EXPECT_EQ(first[4 * (2 * 5 + 0)], 1.f);
  EXPECT_EQ(first[4 * (2 * 5 + 4)], 0.f);
  const std::vector<float> many = renderSamples(f, 255);
  EXPECT_NEAR(many[4 * (2 * 5 + 2)], 0.5f, 0.08f); // 256 samples
  EXPECT_EQ(many[4 * (2 * 5 + 0)], 1.f);           // fully covered
  EXPECT_EQ(many[4 * (2 * 5 + 4)], 0.f);           // fully uncovered
  EXPECT_FLOAT_EQ(refinement(f), 1.f);
  for (ANARIObject o :
      {(ANARIObject)f, (ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
    anariRelease(m_device, o);
  EXPECT_TRUE(problems().empty());
}

TEST_F(Accumulation, AnyCommittedChangeRestarts)
{
  ANARIWorld w = halfPlane();
  ANARICamera c = orthographic(kEye, kDown, 2.5f);
  ANARIRenderer r = renderer("raycast");
  ANARIFrame f = frame(w, c, r, 5);
  renderSamples(f, 4);
  EXPECT_FLOAT_EQ(refinement(f), 4.f / 16.f);
  const float height = 2.4f;
  anariSetParameter(m_device, c, "height", ANARI_FLOAT32, &height);
  anariCommitParameters(m_device, c);
  renderSamples(f, 1);
  EXPECT_FLOAT_EQ(refinement(f), 1.f / 16.f);
  // Staged but uncommitted changes do not restart it.
  const float other = 3.f;
  anariSetParameter(m_device, c, "height", ANARI_FLOAT32, &other);
  renderSamples(f, 1);
  EXPECT_FLOAT_EQ(refinement(f), 2.f / 16.f);
  for (ANARIObject o :
      {(ANARIObject)f, (ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
    anariRelease(m_device, o);
}

TEST_F(Accumulation, IsDeterministic)
{
  ANARIWorld w = halfPlane();
  ANARICamera c = perspective(kEye, kDown, 0.6f);
  const float aperture = 0.2f, focus = 5.f;
  anariSetParameter(m_device, c, "apertureRadius", ANARI_FLOAT32, &aperture);
  anariSetParameter(m_device, c, "focusDistance", ANARI_FLOAT32, &focus);
  anariCommitParameters(m_device, c);
  ANARIRenderer r = renderer("raycast");
  ANARIFrame a = frame(w, c, r, 16);
  ANARIFrame b = frame(w, c, r, 16);
  EXPECT_EQ(renderSamples(a, 8), renderSamples(b, 8));
  for (ANARIObject o : {(ANARIObject)a,
           (ANARIObject)b,
           (ANARIObject)w,
           (ANARIObject)c,
           (ANARIObject)r})
    anariRelease(m_device, o);
  EXPECT_TRUE(problems().empty());
}

TEST_F(Accumulation, PathTracedImageIsTheSameForAnyThreadCount)
{
  // A lit box corner: bounces, shadows and light sampling, all seeded by
  // pixel and sample alone, so the schedule of tiles cannot matter.
  ANARIWorld w =
      world({surface(geometry("quad", {-3, -3, 0, 3, -3, 0, 3, 3, 0, -3, 3, 0}),
                 matte(0.8f, 0.8f, 0.8f)),
          surface(geometry("quad", {-3, 1, 0, 3, 1, 0, 3, 1, 3, -3, 1, 3}),
              matte(0.2f, 0.7f, 0.3f)),
          surface(geometry("sphere", {0, 0, 0.5f}), matte(0.9f, 0.3f, 0.2f))});
  ANARILight light = anariNewLight(m_device, "point");
  const float position[3] = {1, -1, 3}, intensity = 10.f;
  anariSetParameter(m_device, light, "position", ANARI_FLOAT32_VEC3, position);
  anariSetParameter(m_device, light, "intensity", ANARI_FLOAT32, &intensity);
  setOnlyLight(w, light);
  const float eye[3] = {0, -5, 3}, direction[3] = {0, 5, -2.5f};
  ANARICamera c = perspective(eye, direction, 0.8f);
  ANARIRenderer r = renderer("pathtracer");
  std::vector<float> images[2];
  for (int threads : {1, 0}) {
    // TBB's process-wide limit also binds the device's task arena.
    std::optional<tbb::global_control> limit;
    if (threads > 0)
      limit.emplace(tbb::global_control::max_allowed_parallelism, threads);
    ANARIFrame f = frame(w, c, r, 64);
    images[threads > 0 ? 0 : 1] = renderSamples(f, 4);
    anariRelease(m_device, f);
  }
  ASSERT_FALSE(images[0].empty());
  EXPECT_EQ(images[0], images[1]);
  for (ANARIObject o : {(ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
    anariRelease(m_device, o);
  EXPECT_TRUE(problems().empty());
}

TEST_F(Accumulation, DepthOfFieldBlursWhatIsOutOfFocus)
{
  ANARIWorld w = halfPlane();
  auto edgeSharpness = [&](float focusDistance) {
    ANARICamera c = perspective(kEye, kDown, 0.6f);
    const float aperture = 0.5f;
    anariSetParameter(m_device, c, "apertureRadius", ANARI_FLOAT32, &aperture);
    anariSetParameter(
        m_device, c, "focusDistance", ANARI_FLOAT32, &focusDistance);
    anariCommitParameters(m_device, c);
    ANARIRenderer r = renderer("raycast");
    ANARIFrame f = frame(w, c, r, 33);
    const std::vector<float> image = renderSamples(f, 64);
    // How many pixels of the middle row are neither black nor white.
    int blurred = 0;
    for (int x = 0; x < 33; x++) {
      const float v = image[4 * (16 * 33 + x)];
      blurred += v > 0.05f && v < 0.95f;
    }
    for (ANARIObject o : {(ANARIObject)f, (ANARIObject)c, (ANARIObject)r})
      anariRelease(m_device, o);
    return blurred;
  };
  // In focus (the plane is 5 away) the edge stays within about a pixel;
  // focused far behind it, it spreads over several.
  EXPECT_LE(edgeSharpness(5.f), 2);
  EXPECT_GE(edgeSharpness(50.f), 4);
  anariRelease(m_device, w);
  EXPECT_TRUE(problems().empty());
}

// hdAnari's convergence control: the frame's numSamples counts the samples
// accumulated, and at the renderer's sampleLimit (4) a further
// anariRenderFrame returns without tracing a ray (the path tracer's
// raysTraced stays) and the image stays exactly what it was.
TEST_F(Accumulation, SampleLimitStopsAccumulating)
{
  ANARIWorld w = halfPlane();
  ANARILight light = anariNewLight(m_device, "directional");
  setOnlyLight(w, light);
  ANARICamera c = perspective(kEye, kDown, 1.f);
  ANARIRenderer r = renderer("pathtracer");
  const int32_t limit = 4;
  anariSetParameter(m_device, r, "sampleLimit", ANARI_INT32, &limit);
  anariCommitParameters(m_device, r);
  ANARIFrame f = frame(w, c, r, 16);
  auto samples = [&] {
    int32_t value = -1;
    anariGetProperty(m_device,
        f,
        "numSamples",
        ANARI_INT32,
        &value,
        sizeof(value),
        ANARI_WAIT);
    return value;
  };
  auto raysTraced = [&] {
    uint64_t value = 0;
    anariGetProperty(m_device,
        r,
        "raysTraced",
        ANARI_UINT64,
        &value,
        sizeof(value),
        ANARI_WAIT);
    return value;
  };
  EXPECT_EQ(samples(), 0);
  uint64_t rays = raysTraced();
  for (int32_t i = 1; i <= limit; i++) {
    renderSamples(f, 1);
    EXPECT_EQ(samples(), i);
    EXPECT_GT(raysTraced(), rays) << "sample " << i;
    rays = raysTraced();
  }
  EXPECT_FLOAT_EQ(refinement(f), 1.f);
  const std::vector<float> converged = renderSamples(f, 0);
  const std::vector<float> after = renderSamples(f, 3);
  EXPECT_EQ(samples(), limit);
  EXPECT_EQ(raysTraced(), rays);
  EXPECT_EQ(after, converged);
  // A change restarts, and the limit counts again from there.
  const float eye[3] = {0.1f, 0, 5};
  anariSetParameter(m_device, c, "position", ANARI_FLOAT32_VEC3, eye);
  anariCommitParameters(m_device, c);
  renderSamples(f, 1);
  EXPECT_EQ(samples(), 1);
  EXPECT_GT(raysTraced(), rays);
  for (ANARIObject o :
      {(ANARIObject)f, (ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
    anariRelease(m_device, o);
  EXPECT_TRUE(problems().empty());
}

// A negative sampleLimit is reported and means no limit.
TEST_F(Accumulation, NegativeSampleLimitIsReported)
{
  ANARIRenderer r = renderer("raycast");
  const int32_t limit = -2;
  anariSetParameter(m_device, r, "sampleLimit", ANARI_INT32, &limit);
  anariCommitParameters(m_device, r);
  ANARIWorld w = halfPlane();
  ANARICamera c = orthographic(kEye, kDown, 2.5f);
  ANARIFrame f = frame(w, c, r, 4);
  renderSamples(f, 3);
  int32_t samples = 0;
  anariGetProperty(m_device,
      f,
      "numSamples",
      ANARI_INT32,
      &samples,
      sizeof(samples),
      ANARI_WAIT);
  EXPECT_EQ(samples, 3);
  EXPECT_TRUE(reported(ANARI_SEVERITY_WARNING,
      ANARI_STATUS_INVALID_ARGUMENT,
      "'sampleLimit' (-2) must be >= 0"));
  for (ANARIObject o :
      {(ANARIObject)f, (ANARIObject)w, (ANARIObject)c, (ANARIObject)r})
    anariRelease(m_device, o);
}

} // namespace
