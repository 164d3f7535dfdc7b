// Edge-avoiding à-trous wavelet denoiser (Dammertz et al. 2010, with SVGF's
// variance-guided weights) for the renderer's `denoise` switch: Debian 12 has
// no OIDN package. Its passes, in order: guides (Guides.h), demodulation
// (Demodulation.h), noise variance (NoiseVariance.h), five à-trous steps
// (ATrousStep.h), remodulation.
#pragma once

#include "../math/Vec.h"
#include "DenoiseInputs.h"
#include "Guides.h"

#include <vector>

namespace prism {

// Keeps scratch between calls, so only a size change allocates.
// NOTE: one instance must not run two denoise() calls at the same time.
class Denoiser
{
 public:
  // Writes width * height pixels to out; out == in.color is allowed.
  void denoise(const DenoiseInputs &in, float4 *out);

 private:
  std::vector<denoising::Guide> m_guides;
  std::vector<denoising::NeighbourWeights> m_neighbourWeights;
  std::vector<float4> m_ping; // demodulated color (rgb) and its variance (w)
  std::vector<float4> m_pong;
  std::vector<float> m_residualSquared; // per-pixel noise probe, -1 = none
};

// One-off call with a temporary Denoiser (allocates its scratch each time).
void denoise(const DenoiseInputs &in, float4 *out);

} // namespace prism
