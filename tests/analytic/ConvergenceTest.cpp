// How the path tracer converges: its error against a high-sample reference
// falls faster than 1/sqrt(N) (low-discrepancy sampling), and
// (KHR_RENDERER_DENOISE) at a few samples per pixel the denoised image is
// measurably closer to the reference than the noisy one. References are
// rendered with another renderer `seed`, so they do not share the samples
// of the images they score; seeds give independent estimates.
#include "AnalyticScene.h"

#include <cmath>
#include <cstdio>

namespace {

// Pearson's correlation coefficient of pairs added one at a time.
struct Correlation
{
  double sa = 0, sb = 0, sab = 0, saa = 0, sbb = 0;
  int n = 0;

  void add(double a, double b)
  {
    sa += a, sb += b, sab += a * b, saa += a * a, sbb += b * b, n++;
  }
  double value() const
  {
    const double cov = sab / n - sa / n * sb / n;
    return cov
           / std::sqrt(
               (saa / n - sa / n * sa / n) * (sbb / n - sb / n * sb / n));
  }
};

class Convergence : public AnalyticTest
{
 protected:
  // A sphere on a plane under a quad light, seen from above at an angle.
  ANARIWorld litScene()
  {
    ANARIWorld w = world(
        {surface(geometry("quad", {-5, -5, 0, 5, -5, 0, 5, 5, 0, -5, 5, 0}),
             matte(0.8f, 0.8f, 0.8f)),
            surface(geometry("sphere", {0, 0, 1}), matte(0.9f, 0.3f, 0.2f))});
    const float corner[3] = {-1, -1, 4}, edge1[3] = {2, 0, 0},
                edge2[3] = {0, 2, 0};
    setOnlyLight(w, quadLight(corner, edge1, edge2, "radiance", 4.f));
    return w;
  }
  // The seed of references: sequences independent of the default's.
  static constexpr int32_t kReferenceSeed = 1;

  std::vector<float> render(
      ANARIWorld w, bool denoise, int samples, int32_t seed = 0)
  {
    const float eye[3] = {0, -4, 5}, direction[3] = {0, 4, -4.5f};
    ANARICamera c = perspective(eye, direction, 0.8f);
    ANARIRenderer r = anariNewRenderer(m_device, "pathtracer");
    const uint8_t on = denoise ? 1 : 0;
    anariSetParameter(m_device, r, "denoise", ANARI_BOOL, &on);
    anariSetParameter(m_device, r, "seed", ANARI_INT32, &seed);
    anariCommitParameters(m_device, r);
    std::vector<float> out = accumulatedColor(w, c, r, 32, samples);
    for (ANARIObject o : {(ANARIObject)c, (ANARIObject)r})
      anariRelease(m_device, o);
    return out;
  }
  static float rmse(const std::vector<float> &a, const std::vector<float> &b)
  {
    double sum = 0;
    for (size_t i = 0; i < a.size(); i += 4) {
      for (int c = 0; c < 3; c++) {
        const double d = a[i + c] - b[i + c];
        sum += d * d;
      }
    }
    return float(std::sqrt(sum / (3.0 * a.size() / 4)));
  }
};

TEST_F(Convergence, ErrorFallsFasterThanOneOverTheSquareRootOfSamples)
{
  ANARIWorld w = litScene();
  const std::vector<float> reference = render(w, false, 4096, kReferenceSeed);
  std::vector<float> errors;
  for (int samples : {4, 16, 64, 256}) {
    errors.push_back(rmse(render(w, false, samples), reference));
    std::printf("%3d spp: RMSE %.5f\n", samples, errors.back());
  }
  // Stratified (low-discrepancy) samples: the error falls faster than
  // N^-0.5, what independent samples give (4x the samples: 2x less
  // error). Stated tolerance: each step between 1.9x and 3.2x, the overall
  // slope at most -0.57 (measured -0.591 against the independent
  // reference: RMSE 0.0143, 0.0059, 0.0027, 0.0012; with a centred first
  // sample, before the path tracer's sequences kept their first points,
  // -0.601 from a higher start: 0.0149, 0.0059, 0.0027, 0.0012).
  for (size_t i = 1; i < errors.size(); i++) {
    const float ratio = errors[i - 1] / errors[i];
    EXPECT_GT(ratio, 1.9f) << "step " << i;
    EXPECT_LT(ratio, 3.2f) << "step " << i;
  }
  const float slope =
      std::log(errors.back() / errors.front()) / std::log(256.f / 4.f);
  std::printf("slope %.3f\n", slope);
  EXPECT_LT(slope, -0.57f);
  EXPECT_GT(slope, -1.1f);
  anariRelease(m_device, w);
  EXPECT_TRUE(problems().empty());
}

TEST_F(Convergence, NeighbouringPixelsErrorsAreUncorrelated)
{
  // Each pixel scrambles its own sequences: the errors of neighbouring
  // pixels are independent (no visible structure), which shared or
  // correlated sequences would make them far from. Stated tolerance: the
  // correlation coefficient of horizontally and vertically adjacent
  // pixels' red errors within +-0.15 (1024 pixel pairs: 0.15 is ~5 sigma).
  ANARIWorld w = litScene();
  const std::vector<float> reference = render(w, false, 1024, kReferenceSeed);
  const std::vector<float> image = render(w, false, 8);
  const int size = 32;
  auto error = [&](int x, int y) {
    const size_t i = size_t(y * size + x) * 4;
    return double(image[i]) - double(reference[i]);
  };
  for (const auto &[dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
    Correlation correlation;
    for (int y = 0; y + dy < size; y++)
      for (int x = 0; x + dx < size; x++)
        correlation.add(error(x, y), error(x + dx, y + dy));
    const double corr = correlation.value();
    std::printf("neighbour (%d, %d) error correlation %.3f\n", dx, dy, corr);
    EXPECT_LT(std::abs(corr), 0.15);
  }
  anariRelease(m_device, w);
  EXPECT_TRUE(problems().empty());
}

TEST_F(Convergence, AnotherSeedIsAnIndependentEstimate)
{
  // The renderer's seed scrambles every sequence anew: images of two seeds
  // differ, their errors are uncorrelated (the same test as neighbouring
  // pixels', same tolerance), and the same seed renders the same bits.
  ANARIWorld w = litScene();
  const std::vector<float> reference = render(w, false, 1024, kReferenceSeed);
  const std::vector<float> a = render(w, false, 8, 2);
  const std::vector<float> b = render(w, false, 8, 3);
  ASSERT_NE(a, b);
  EXPECT_EQ(render(w, false, 8, 2), a);
  Correlation correlation;
  for (size_t i = 0; i < a.size(); i += 4)
    correlation.add(double(a[i]) - reference[i], double(b[i]) - reference[i]);
  const double corr = correlation.value();
  std::printf("seeds 2 and 3: error correlation %.3f\n", corr);
  EXPECT_LT(std::abs(corr), 0.15);
  anariRelease(m_device, w);
  EXPECT_TRUE(problems().empty());
}

TEST_F(Convergence, DenoisedLowSampleImageIsCloserToTheReference)
{
  // One sample: low-discrepancy sampling leaves little noise at four.
  constexpr int kLowSamples = 1;
  ANARIWorld w = litScene();
  const std::vector<float> reference = render(w, false, 1024, kReferenceSeed);
  const std::vector<float> noisy = render(w, false, kLowSamples);
  const std::vector<float> denoised = render(w, true, kLowSamples);
  const float noisyError = rmse(noisy, reference);
  const float denoisedError = rmse(denoised, reference);
  std::printf("%d spp RMSE against 1024 spp: noisy %.4f, denoised %.4f\n",
      kLowSamples,
      noisyError,
      denoisedError);
  EXPECT_LT(denoisedError, 0.7f * noisyError);
  // Without `denoise` the noisy color is what the frame shows.
  EXPECT_EQ(render(w, false, kLowSamples), noisy);
  anariRelease(m_device, w);
  EXPECT_TRUE(problems().empty());
}

} // namespace
