// How far apart two images are: RMSE, largest difference, PSNR and the share
// of pixels that differ visibly, plus a difference image to look at. Images
// of different sizes are infinitely far apart; a NaN where the other image
// has a number is an infinite difference, so no metric hides it.
#pragma once

#include "Image.h"

namespace prism::image {

// Which channels a metric compares.
enum class Channels { Rgb, Rgba };

// Root mean square of the per-channel differences.
double rmse(const Image &a, const Image &b, Channels channels = Channels::Rgba);

// The largest per-channel absolute difference.
double maxAbsDifference(
    const Image &a, const Image &b, Channels channels = Channels::Rgba);

// Peak signal-to-noise ratio in dB for signals of amplitude `peak`:
// 20 log10(peak / rmse), +infinity for identical images.
double psnr(const Image &a,
    const Image &b,
    Channels channels = Channels::Rgba,
    double peak = 1.0);

// The fraction (0..1) of pixels with some channel differing by more than
// `threshold`.
double fractionDiffering(const Image &a,
    const Image &b,
    double threshold,
    Channels channels = Channels::Rgba);

// Every metric at once.
struct Comparison
{
  double rmse;
  double maxAbsDifference;
  double psnr;
  double fractionDiffering; // by more than the threshold given to compare()
};
Comparison compare(const Image &a,
    const Image &b,
    double threshold,
    Channels channels = Channels::Rgba);

// |a - b| per RGB channel times `scale`, alpha 1; `scale` 0 picks the scale
// that shows the largest finite difference as 1, so small errors are visible.
// Non-finite differences show as 1. Empty when the sizes differ.
Image diffImage(const Image &a, const Image &b, float scale = 0.f);

} // namespace prism::image
