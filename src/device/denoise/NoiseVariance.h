// How noisy each pixel is, estimated from the image itself: the à-trous
// steps measure luminance differences in these deviations, so they blend
// noise away and keep real detail.
#pragma once

#include "Guides.h"

namespace prism::denoising {

// Per pixel, the squared difference of its luminance from the mean of its
// same-surface 3x3 neighbours, scaled to estimate the noise variance
// (smooth shading cancels, noise stays); -1 for a pixel with no such
// neighbour. Also writes the 3x3 geometric weights, which every à-trous
// step's variance smoothing reuses.
void probeNoise(const PixelGrid &grid,
    const Guide *guides,
    const float4 *demodulated,
    float *residualSquared,
    NeighbourWeights *neighbourWeights);

// demodulated's color with the noise variance in w: the median probe of the
// same-surface 7x7 window (a shadow edge lights up only a few probes),
// capped by a prior that shrinks as 1 / samples.
void estimateVariance(const PixelGrid &grid,
    const Guide *guides,
    const float4 *demodulated,
    const float *residualSquared,
    float samples,
    float4 *withVariance);

} // namespace prism::denoising
