// One pass of the edge-avoiding à-trous wavelet filter (Dammertz et al.
// 2010) with SVGF's weights (Schied et al. 2017): five such passes with
// doubling holes reach as far as a 61x61 filter at the cost of 5x5 each.
#pragma once

#include "Guides.h"

namespace prism::denoising {

// Filters source (demodulated color, variance in w) into target: a 5x5
// B3-spline with taps `step` pixels apart, each weighted by normal,
// depth-plane and luminance similarity, the luminance difference measured
// in deviations of the 3x3-smoothed variance. The variance propagates as
// sum(w^2 var) / (sum w)^2, so later passes trust luminance differences
// more.
void aTrousStep(const PixelGrid &grid,
    const Guide *guides,
    const NeighbourWeights *neighbourWeights,
    const float4 *source,
    int step,
    float4 *target);

} // namespace prism::denoising
