// Edge-avoiding à-trous filtering (Dammertz et al. 2010) of the demodulated
// color: five B3-spline passes with holes (steps 1 to 16), taps weighted by
// normal, depth-plane and luminance similarity as in SVGF (Schied et al.
// 2017), the luminance weight scaled by a per-pixel noise variance that is
// estimated once from the image and the sample count, then propagated.
#include "Denoiser.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <limits>

namespace prism {

namespace {

constexpr int kIterations = 5;
// B3-spline taps (1, 4, 6, 4, 1) / 16 indexed by |offset|.
constexpr float kB3[3] = {3.f / 8.f, 1.f / 4.f, 1.f / 16.f};
// 3x3 Gaussian (1, 2, 1) / 4 indexed by |offset|, to steady the variance.
constexpr float kGauss3[2] = {1.f / 2.f, 1.f / 4.f};
// SVGF's sigma_l: luminance differences are measured in noise deviations.
constexpr float kSigmaLuminance = 4.f;
// Normal weight max(0, n_p . n_q)^128 (SVGF's sigma_n) as 7 squarings.
constexpr int kNormalPowerSquarings = 7;
// Depth tolerance: one slope step per pixel of offset (the slope is noisy)...
constexpr float kDepthSlopeTolerance = 1.f;
// ...plus half a percent of the depth, for perspective and depth noise.
constexpr float kDepthRelativeTolerance = 0.005f;
// Clamp before dividing, so black texels don't become huge irradiance.
constexpr float kMinAlbedo = 0.01f;
// Averaged normals shorter than this are "no surface" (background).
constexpr float kMinNormalLength = 1e-3f;
// The noise estimate pools a 7x7 window of pixels at least this similar.
constexpr int kNoiseWindowRadius = 3;
constexpr float kSameSurfaceWeight = 0.5f;
// Median of chi-square(1): median(r^2) / this is the variance of Gaussian r.
constexpr float kMedianChiSquare1 = 0.4549364f;
// Prior: a sample deviates ~4x its mean at most, an N-sample mean 4 / sqrt(N).
constexpr float kMaxRelativeDeviation = 4.f;

constexpr float kInfinity = std::numeric_limits<float>::infinity();

float luminance(float3 c)
{
  return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

bool isFinite(float3 v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// exp(-x) for x >= 0 to 3e-6, inline: every tap of every pass needs one.
inline float expNegative(float x)
{
  const float t = x * 1.44269504f; // in powers of two
  if (!(t < 126.f))                // also catches NaN and +inf
    return 0.f;
  const int whole = int(t);
  const float u = (t - float(whole)) * 0.69314718f; // in [0, ln 2)
  // Taylor series of exp(-u); the dropped 8th term is below 1.3e-6.
  float fraction = 1.f - u * (1.f / 7.f);
  fraction = 1.f - u * (1.f / 6.f) * fraction;
  fraction = 1.f - u * (1.f / 5.f) * fraction;
  fraction = 1.f - u * (1.f / 4.f) * fraction;
  fraction = 1.f - u * (1.f / 3.f) * fraction;
  fraction = 1.f - u * (1.f / 2.f) * fraction;
  fraction = 1.f - u * fraction;
  return fraction * std::bit_cast<float>(uint32_t(127 - whole) << 23);
}

// What color is divided by before filtering and multiplied by after.
float3 demodulationFactor(const float3 *albedo, size_t i)
{
  if (!albedo)
    return {1.f, 1.f, 1.f};
  // A non-finite albedo would poison the round trip: skip that channel.
  const auto factor = [](float a) {
    return std::isfinite(a) ? max(a, kMinAlbedo) : 1.f;
  };
  const float3 a = albedo[i];
  return {factor(a.x), factor(a.y), factor(a.z)};
}

// max(0, n_p . n_q)^128; 0 across kinds, so background never meets surfaces.
inline float normalWeight(const Denoiser::Guide &p, const Denoiser::Guide &q)
{
  if (p.kind != q.kind)
    return 0.f;
  if (!(p.kind & Denoiser::Guide::kHasNormal))
    return 1.f;
  float weight = max(0.f, dot(p.normal, q.normal));
  for (int i = 0; i < kNormalPowerSquarings; i++)
    weight *= weight;
  return weight;
}

// Depth p's tangent plane predicts at an offset (so tilted planes match).
struct DepthExpectation
{
  float depth;
  float tolerance; // how far off a neighbour on p's surface may plausibly be
};

// The x and y halves of an expectation, so a pass tabulates them per pixel.
inline DepthExpectation expectationAlongX(const Denoiser::Guide &p, int dx)
{
  return {p.depthSlope.x * float(dx),
      kDepthSlopeTolerance * std::abs(p.depthSlope.x) * float(std::abs(dx))};
}
inline DepthExpectation expectationAlongY(const Denoiser::Guide &p, int dy)
{
  return {p.depth + p.depthSlope.y * float(dy),
      kDepthSlopeTolerance * std::abs(p.depthSlope.y) * float(std::abs(dy))
          + kDepthRelativeTolerance * std::abs(p.depth)};
}

// (error / tolerance)^2; 0 without depth buffer and for background pairs.
inline float depthExponent(float depth, DepthExpectation expected)
{
  const float error = depth - expected.depth;
  if (error == 0.f || !std::isfinite(depth))
    return 0.f;
  if (!(expected.tolerance > 0.f))
    return kInfinity;
  const float ratio = error / expected.tolerance;
  return ratio * ratio;
}

// Weight of q at offset (dx, dy) from p; 0 = another surface, never blended.
inline float geometryWeight(
    const Denoiser::Guide &p, const Denoiser::Guide &q, int dx, int dy)
{
  const float normal = normalWeight(p, q);
  if (normal == 0.f)
    return 0.f;
  const DepthExpectation x = expectationAlongX(p, dx);
  const DepthExpectation y = expectationAlongY(p, dy);
  return normal
         * expNegative(depthExponent(
             q.depth, {y.depth + x.depth, y.tolerance + x.tolerance}));
}

// Smaller one-sided difference: across a depth edge the change is larger.
float depthSlope(float here, float before, float after)
{
  const bool hasBefore = std::isfinite(before);
  const bool hasAfter = std::isfinite(after);
  if (hasBefore && hasAfter) {
    const float backward = here - before, forward = after - here;
    return std::abs(backward) <= std::abs(forward) ? backward : forward;
  }
  if (hasBefore)
    return here - before;
  if (hasAfter)
    return after - here;
  return 0.f;
}

// Rows in parallel; each writes only its own pixels, so any thread count
// gives the same bits.
template <typename F>
void forEachRow(uint32_t height, const F &rowFunction)
{
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, height),
      [&](const tbb::blocked_range<uint32_t> &rows) {
        for (uint32_t y = rows.begin(); y < rows.end(); y++)
          rowFunction(int(y));
      });
}

} // namespace

void Denoiser::denoise(const DenoiseInputs &in, float4 *out)
{
  const int width = int(in.width), height = int(in.height);
  if (width <= 0 || height <= 0 || !in.color || !out)
    return;
  const size_t pixels = size_t(width) * size_t(height);
  // resize() keeps capacity: same-size frames reuse the scratch memory.
  m_guides.resize(pixels);
  m_ping.resize(pixels);
  m_pong.resize(pixels);
  m_residualSquared.resize(pixels);
  m_neighbourWeights.resize(pixels);
  const float samples = float(max(in.samples, 1u));
  const auto index = [width](int x, int y) {
    return size_t(y) * size_t(width) + size_t(x);
  };

  // Guides and demodulated color; non-finite colors are zeroed, not spread.
  forEachRow(in.height, [&](int y) {
    for (int x = 0; x < width; x++) {
      const size_t i = index(x, y);
      Guide &guide = m_guides[i];
      guide.normal = {0.f, 0.f, 0.f};
      guide.kind = 0;
      if (in.normal && isFinite(in.normal[i])) {
        const float normalLength = length(in.normal[i]);
        if (normalLength >= kMinNormalLength) {
          guide.normal = in.normal[i] / normalLength;
          guide.kind |= Guide::kHasNormal;
        }
      }
      // Without depth every pixel is a hit at 0, so the depth test passes.
      guide.depth = 0.f;
      if (in.depth)
        guide.depth = std::isfinite(in.depth[i]) ? in.depth[i] : kInfinity;
      if (std::isfinite(guide.depth))
        guide.kind |= Guide::kHit;
      float3 color = xyz(in.color[i]);
      if (!isFinite(color))
        color = {0.f, 0.f, 0.f};
      m_ping[i] = makeVec4(color / demodulationFactor(in.albedo, i), 0.f);
    }
  });

  // Screen-space depth slopes, once the depths of all rows are known.
  forEachRow(in.height, [&](int y) {
    for (int x = 0; x < width; x++) {
      Guide &guide = m_guides[index(x, y)];
      if (!std::isfinite(guide.depth)) {
        guide.depthSlope = {0.f, 0.f};
        continue;
      }
      const auto depthAt = [&](int qx, int qy) {
        if (qx < 0 || qy < 0 || qx >= width || qy >= height)
          return kInfinity;
        return m_guides[index(qx, qy)].depth;
      };
      guide.depthSlope = {
          depthSlope(guide.depth, depthAt(x - 1, y), depthAt(x + 1, y)),
          depthSlope(guide.depth, depthAt(x, y - 1), depthAt(x, y + 1))};
    }
  });

  // Noise probe: luminance minus the same-surface 3x3 mean cancels smooth
  // shading and leaves noise; 3x3 weights are kept for the passes.
  forEachRow(in.height, [&](int y) {
    for (int x = 0; x < width; x++) {
      const size_t i = index(x, y);
      const Guide &p = m_guides[i];
      NeighbourWeights &weights = m_neighbourWeights[i];
      float weightSum = 0.f, weightSquaredSum = 0.f, luminanceSum = 0.f;
      for (int dy = -1; dy <= 1; dy++) {
        for (int dx = -1; dx <= 1; dx++) {
          float &w = weights[size_t(3 * (dy + 1) + dx + 1)];
          w = 0.f;
          const int qx = x + dx, qy = y + dy;
          if (qx < 0 || qy < 0 || qx >= width || qy >= height)
            continue;
          const size_t j = index(qx, qy);
          w = geometryWeight(p, m_guides[j], dx, dy);
          if (w == 0.f || (dx == 0 && dy == 0))
            continue;
          weightSum += w;
          weightSquaredSum += w * w;
          luminanceSum += w * luminance(xyz(m_ping[j]));
        }
      }
      if (!(weightSum > 0.f)) {
        m_residualSquared[i] = -1.f; // isolated pixel: no estimate
        continue;
      }
      const float residual =
          luminance(xyz(m_ping[i])) - luminanceSum / weightSum;
      // Var(residual) = var (1 + sum w^2 / (sum w)^2) for i.i.d. noise.
      m_residualSquared[i] =
          residual * residual
          / (1.f + weightSquaredSum / (weightSum * weightSum));
    }
  });

  // Variance: the median probe of the same-surface 7x7 window (ignoring the
  // few a shadow edge lights up), capped by a prior shrinking as 1 / samples.
  forEachRow(in.height, [&](int y) {
    constexpr int kWindow = 2 * kNoiseWindowRadius + 1;
    std::array<float, kWindow * kWindow> probes;
    for (int x = 0; x < width; x++) {
      const size_t i = index(x, y);
      const Guide &p = m_guides[i];
      int count = 0, luminanceCount = 0;
      float luminanceSum = 0.f;
      for (int dy = -kNoiseWindowRadius; dy <= kNoiseWindowRadius; dy++) {
        for (int dx = -kNoiseWindowRadius; dx <= kNoiseWindowRadius; dx++) {
          const int qx = x + dx, qy = y + dy;
          if (qx < 0 || qy < 0 || qx >= width || qy >= height)
            continue;
          const size_t j = index(qx, qy);
          if (!(geometryWeight(p, m_guides[j], dx, dy) >= kSameSurfaceWeight))
            continue;
          luminanceSum += luminance(xyz(m_ping[j]));
          luminanceCount++;
          if (m_residualSquared[j] >= 0.f)
            probes[count++] = m_residualSquared[j];
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
      m_pong[i] = makeVec4(xyz(m_ping[i]), min(variance, prior));
    }
  });

  // À-trous passes; variance propagates as sum(w^2 var) / (sum w)^2, so
  // later passes trust luminance differences more.
  float4 *source = m_pong.data();
  float4 *target = m_ping.data();
  for (int iteration = 0; iteration < kIterations; iteration++) {
    const int step = 1 << iteration;
    forEachRow(in.height, [&](int y) {
      for (int x = 0; x < width; x++) {
        const size_t i = index(x, y);
        const Guide &p = m_guides[i];
        const float4 center = source[i];
        const float centerLuminance = luminance(xyz(center));

        const NeighbourWeights &weights = m_neighbourWeights[i];
        float varianceSum = 0.f, varianceWeightSum = 0.f;
        for (int dy = -1; dy <= 1; dy++) {
          for (int dx = -1; dx <= 1; dx++) {
            const float w = kGauss3[std::abs(dx)] * kGauss3[std::abs(dy)]
                            * weights[size_t(3 * (dy + 1) + dx + 1)];
            if (w == 0.f)
              continue;
            varianceSum += w * source[index(x + dx, y + dy)].w;
            varianceWeightSum += w;
          }
        }
        const float deviation =
            std::sqrt(max(0.f, varianceSum / varianceWeightSum));
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
          const size_t row = index(x, y + ty * step);
          const DepthExpectation &ey = alongY[size_t(ty + 2)];
          for (int tx = txFirst; tx <= txLast; tx++) {
            if (tx == 0 && ty == 0)
              continue;
            const size_t j = size_t(ptrdiff_t(row) + tx * step);
            const Guide &q = m_guides[j];
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
        target[i] = makeVec4(colorSum / weightSum,
            weightedVarianceSum / (weightSum * weightSum));
      }
    });
    std::swap(source, target);
  }

  // Remodulate and copy alpha; reading before writing allows in-place.
  forEachRow(in.height, [&](int y) {
    for (int x = 0; x < width; x++) {
      const size_t i = index(x, y);
      const float alpha = in.color[i].w;
      out[i] =
          makeVec4(xyz(source[i]) * demodulationFactor(in.albedo, i), alpha);
    }
  });
}

void denoise(const DenoiseInputs &in, float4 *out)
{
  Denoiser denoiser;
  denoiser.denoise(in, out);
}

} // namespace prism
