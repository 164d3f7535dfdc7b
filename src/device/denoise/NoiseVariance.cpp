#include "NoiseVariance.h"

#include <algorithm>
#include <array>

namespace prism::denoising {

namespace {

// The variance pools a 7x7 window of pixels at least this similar.
constexpr int kNoiseWindowRadius = 3;
constexpr float kSameSurfaceWeight = 0.5f;
// Median of chi-square(1): median(r^2) / this is the variance of Gaussian r.
constexpr float kMedianChiSquare1 = 0.4549364f;
// Prior: a sample deviates ~4x its mean at most, an N-sample mean 4 / sqrt(N).
constexpr float kMaxRelativeDeviation = 4.f;

} // namespace

void probeNoise(const PixelGrid &grid,
    const Guide *guides,
    const float4 *demodulated,
    float *residualSquared,
    NeighbourWeights *neighbourWeights)
{
  forEachRow(grid, [&](int y) {
    for (int x = 0; x < grid.width; x++) {
      const size_t i = grid.index(x, y);
      const Guide &p = guides[i];
      NeighbourWeights &weights = neighbourWeights[i];
      float weightSum = 0.f, weightSquaredSum = 0.f, luminanceSum = 0.f;
      for (int dy = -1; dy <= 1; dy++) {
        for (int dx = -1; dx <= 1; dx++) {
          float &w = weights[size_t(3 * (dy + 1) + dx + 1)];
          w = 0.f;
          const int qx = x + dx, qy = y + dy;
          if (!grid.contains(qx, qy))
            continue;
          const size_t j = grid.index(qx, qy);
          w = geometryWeight(p, guides[j], dx, dy);
          if (w == 0.f || (dx == 0 && dy == 0))
            continue;
          weightSum += w;
          weightSquaredSum += w * w;
          luminanceSum += w * luminance(xyz(demodulated[j]));
        }
      }
      if (!(weightSum > 0.f)) {
        residualSquared[i] = -1.f; // isolated pixel: no estimate
        continue;
      }
      const float residual =
          luminance(xyz(demodulated[i])) - luminanceSum / weightSum;
      // Var(residual) = var (1 + sum w^2 / (sum w)^2) for i.i.d. noise.
      residualSquared[i] = residual * residual
                           / (1.f + weightSquaredSum / (weightSum * weightSum));
    }
  });
}

void estimateVariance(const PixelGrid &grid,
    const Guide *guides,
    const float4 *demodulated,
    const float *residualSquared,
    float samples,
    float4 *withVariance)
{
  forEachRow(grid, [&](int y) {
    constexpr int kWindow = 2 * kNoiseWindowRadius + 1;
    std::array<float, kWindow * kWindow> probes;
    for (int x = 0; x < grid.width; x++) {
      const size_t i = grid.index(x, y);
      const Guide &p = guides[i];
      int count = 0, luminanceCount = 0;
      float luminanceSum = 0.f;
      for (int dy = -kNoiseWindowRadius; dy <= kNoiseWindowRadius; dy++) {
        for (int dx = -kNoiseWindowRadius; dx <= kNoiseWindowRadius; dx++) {
          const int qx = x + dx, qy = y + dy;
          if (!grid.contains(qx, qy))
            continue;
          const size_t j = grid.index(qx, qy);
          if (!(geometryWeight(p, guides[j], dx, dy) >= kSameSurfaceWeight))
            continue;
          luminanceSum += luminance(xyz(demodulated[j]));
          luminanceCount++;
          if (residualSquared[j] >= 0.f)
            probes[count++] = residualSquared[j];
        }
      }
      float variance = 0.f;
      if (count > 0) {
        float *median = probes.data() + count / 2;
        std::nth_element(probes.data(), median, probes.data() + count);
        variance = *median / kMedianChiSquare1;
      }
      const float meanLuminance =
          luminanceCount > 0 ? luminanceSum / float(luminanceCount) : 0.f;
      const float prior = kMaxRelativeDeviation * kMaxRelativeDeviation
                          * meanLuminance * meanLuminance / samples;
      withVariance[i] = makeVec4(xyz(demodulated[i]), min(variance, prior));
    }
  });
}

} // namespace prism::denoising
