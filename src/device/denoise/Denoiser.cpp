// The denoiser's passes in order, on scratch buffers kept between frames.
#include "Denoiser.h"

#include "ATrousStep.h"
#include "Demodulation.h"
#include "NoiseVariance.h"

#include <utility>

namespace prism {

namespace {

// Five steps with holes of 1 to 16 pixels.
constexpr int kIterations = 5;

} // namespace

void Denoiser::denoise(const DenoiseInputs &in, float4 *out)
{
  const denoising::PixelGrid grid{int(in.width), int(in.height)};
  if (grid.width <= 0 || grid.height <= 0 || !in.color || !out)
    return;
  // resize() keeps capacity: same-size frames reuse the scratch memory.
  const size_t pixels = grid.pixels();
  m_guides.resize(pixels);
  m_ping.resize(pixels);
  m_pong.resize(pixels);
  m_residualSquared.resize(pixels);
  m_neighbourWeights.resize(pixels);

  denoising::buildGuides(in, m_guides.data());
  denoising::demodulate(in, m_ping.data());
  denoising::probeNoise(grid,
      m_guides.data(),
      m_ping.data(),
      m_residualSquared.data(),
      m_neighbourWeights.data());
  denoising::estimateVariance(grid,
      m_guides.data(),
      m_ping.data(),
      m_residualSquared.data(),
      float(max(in.samples, 1u)),
      m_pong.data());

  float4 *source = m_pong.data();
  float4 *target = m_ping.data();
  for (int iteration = 0; iteration < kIterations; iteration++) {
    denoising::aTrousStep(grid,
        m_guides.data(),
        m_neighbourWeights.data(),
        source,
        1 << iteration,
        target);
    std::swap(source, target);
  }
  denoising::remodulate(in, source, out);
}

void denoise(const DenoiseInputs &in, float4 *out)
{
  Denoiser denoiser;
  denoiser.denoise(in, out);
}

} // namespace prism
