#include "ATrousStep.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace prism::denoising {

namespace {

// B3-spline taps (1, 4, 6, 4, 1) / 16 indexed by |offset|.
constexpr float kB3[3] = {3.f / 8.f, 1.f / 4.f, 1.f / 16.f};
// 3x3 Gaussian (1, 2, 1) / 4 indexed by |offset|, to steady the variance.
constexpr float kGauss3[2] = {1.f / 2.f, 1.f / 4.f};
// SVGF's sigma_l: luminance differences are measured in noise deviations.
constexpr float kSigmaLuminance = 4.f;

// The noise deviation at pixel (x, y): its variance smoothed over its
// same-surface 3x3 neighbours, so one unlucky estimate does not decide.
float smoothedDeviation(const PixelGrid &grid,
    const NeighbourWeights &weights,
    const float4 *source,
    int x,
    int y)
{
  float varianceSum = 0.f, varianceWeightSum = 0.f;
  for (int dy = -1; dy <= 1; dy++) {
    for (int dx = -1; dx <= 1; dx++) {
      const float w = kGauss3[std::abs(dx)] * kGauss3[std::abs(dy)]
                      * weights[size_t(3 * (dy + 1) + dx + 1)];
      if (w == 0.f)
        continue;
      varianceSum += w * source[grid.index(x + dx, y + dy)].w;
      varianceWeightSum += w;
    }
  }
  return std::sqrt(max(0.f, varianceSum / varianceWeightSum));
}

} // namespace

void aTrousStep(const PixelGrid &grid,
    const Guide *guides,
    const NeighbourWeights *neighbourWeights,
    const float4 *source,
    int step,
    float4 *target)
{
  const int width = grid.width, height = grid.height;
  forEachRow(grid, [&](int y) {
    for (int x = 0; x < width; x++) {
      const size_t i = grid.index(x, y);
      const Guide &p = guides[i];
      const float4 center = source[i];
      const float centerLuminance = luminance(xyz(center));
      const float deviation =
          smoothedDeviation(grid, neighbourWeights[i], source, x, y);
      // Not 0: equal luminance still blends while any difference gets 0.
      const float luminanceScale =
          max(kSigmaLuminance * deviation, std::numeric_limits<float>::min());

      // Taps inside the image, in steps; p's depth plane along each axis.
      const int txFirst = max(-2, -(x / step));
      const int txLast = min(2, (width - 1 - x) / step);
      const int tyFirst = max(-2, -(y / step));
      const int tyLast = min(2, (height - 1 - y) / step);
      std::array<DepthExpectation, 5> alongX, alongY;
      for (int t = -2; t <= 2; t++) {
        alongX[size_t(t + 2)] = expectationAlongX(p, t * step);
        alongY[size_t(t + 2)] = expectationAlongY(p, t * step);
      }

      float3 colorSum = xyz(center) * (kB3[0] * kB3[0]);
      float weightSum = kB3[0] * kB3[0];
      float weightedVarianceSum = weightSum * weightSum * center.w;
      for (int ty = tyFirst; ty <= tyLast; ty++) {
        const size_t row = grid.index(x, y + ty * step);
        const DepthExpectation &ey = alongY[size_t(ty + 2)];
        for (int tx = txFirst; tx <= txLast; tx++) {
          if (tx == 0 && ty == 0)
            continue;
          const size_t j = size_t(ptrdiff_t(row) + tx * step);
          const Guide &q = guides[j];
          const float normal = normalWeight(p, q);
          if (normal == 0.f)
            continue;
          const DepthExpectation &ex = alongX[size_t(tx + 2)];
          const float depth = depthExponent(
              q.depth, {ey.depth + ex.depth, ey.tolerance + ex.tolerance});
          const float4 v = source[j];
          const float luminanceDistance =
              std::abs(luminance(xyz(v)) - centerLuminance) / luminanceScale;
          const float w = kB3[std::abs(tx)] * kB3[std::abs(ty)] * normal
                          * expNegative(depth + luminanceDistance);
          if (w == 0.f)
            continue;
          colorSum += xyz(v) * w;
          weightSum += w;
          weightedVarianceSum += w * w * v.w;
        }
      }
      target[i] = makeVec4(
          colorSum / weightSum, weightedVarianceSum / (weightSum * weightSum));
    }
  });
}

} // namespace prism::denoising
