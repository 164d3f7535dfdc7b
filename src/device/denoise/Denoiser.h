// Edge-avoiding à-trous wavelet denoiser (Dammertz et al. 2010, with SVGF's
// variance-guided weights) for the renderer's `denoise` switch: Debian 12 has
// no OIDN package.
#pragma once

#include "../math/Vec.h"

#include <array>
#include <cstdint>
#include <vector>

namespace prism {

// A frame's linear buffers, row 0 at the bottom; NULL guides are ignored.
struct DenoiseInputs
{
  uint32_t width, height;
  const float4 *color;  // average of `samples` samples; alpha passes through
  const float3 *albedo; // average albedo, divided out so textures stay sharp
  const float3 *normal; // world space, average of unit normals; 0 = no hit
  const float *depth;   // distance to the camera, +inf where nothing was hit
  uint32_t samples;     // samples averaged into color (0 is treated as 1)
};

// Keeps scratch between calls, so only a size change allocates.
// NOTE: one instance must not run two denoise() calls at the same time.
class Denoiser
{
 public:
  // Writes width * height pixels to out; out == in.color is allowed.
  void denoise(const DenoiseInputs &in, float4 *out);

  // Per-pixel guides; pixels of different kinds never blend.
  struct Guide
  {
    static constexpr uint32_t kHasNormal = 1, kHit = 2;
    float3 normal;     // 0 unless kind has kHasNormal
    float depth;       // +inf = background; 0 everywhere without a depth buffer
    float2 depthSlope; // depth change per pixel along x and y
    uint32_t kind;     // kHasNormal | kHit
  };

 private:
  // 3x3 geometric weights from the bottom left; 0 off-image or off-surface.
  using NeighbourWeights = std::array<float, 9>;

  std::vector<Guide> m_guides;
  std::vector<NeighbourWeights> m_neighbourWeights;
  std::vector<float4> m_ping; // demodulated color (rgb) and its variance (w)
  std::vector<float4> m_pong;
  std::vector<float> m_residualSquared; // per-pixel noise probe, -1 = none
};

// One-off call with a temporary Denoiser (allocates its scratch each time).
void denoise(const DenoiseInputs &in, float4 *out);

} // namespace prism
