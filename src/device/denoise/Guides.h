// The geometric guides of the denoiser: per pixel a normal, a depth and its
// screen-space slope, and the weights that keep filtering on one surface.
#pragma once

#include "../math/Luminance.h"
#include "../math/Vec.h"
#include "DenoiseInputs.h"
#include "ExpNegative.h"
#include "PixelGrid.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace prism::denoising {

// Per-pixel guides; pixels of different kinds never blend.
struct Guide
{
  static constexpr uint32_t kHasNormal = 1, kHit = 2;
  float3 normal;     // 0 unless kind has kHasNormal
  float depth;       // +inf = background; 0 everywhere without a depth buffer
  float2 depthSlope; // depth change per pixel along x and y
  uint32_t kind;     // kHasNormal | kHit
};

// 3x3 geometric weights from the bottom left; 0 off-image or off-surface.
using NeighbourWeights = std::array<float, 9>;

// Normal weight max(0, n_p . n_q)^128 (SVGF's sigma_n) as 7 squarings.
inline constexpr int kNormalPowerSquarings = 7;
// Depth tolerance: one slope step per pixel of offset (the slope is noisy)...
inline constexpr float kDepthSlopeTolerance = 1.f;
// ...plus half a percent of the depth, for perspective and depth noise.
inline constexpr float kDepthRelativeTolerance = 0.005f;

// Normals and depths of `in` (depth slopes once all depths are known).
void buildGuides(const DenoiseInputs &in, Guide *guides);

// max(0, n_p . n_q)^128; 0 across kinds, so background never meets surfaces.
inline float normalWeight(const Guide &p, const Guide &q)
{
  if (p.kind != q.kind)
    return 0.f;
  if (!(p.kind & Guide::kHasNormal))
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
inline DepthExpectation expectationAlongX(const Guide &p, int dx)
{
  return {p.depthSlope.x * float(dx),
      kDepthSlopeTolerance * std::abs(p.depthSlope.x) * float(std::abs(dx))};
}
inline DepthExpectation expectationAlongY(const Guide &p, int dy)
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
    return std::numeric_limits<float>::infinity();
  const float ratio = error / expected.tolerance;
  return ratio * ratio;
}

// Weight of q at offset (dx, dy) from p; 0 = another surface, never blended.
inline float geometryWeight(const Guide &p, const Guide &q, int dx, int dy)
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

} // namespace prism::denoising
