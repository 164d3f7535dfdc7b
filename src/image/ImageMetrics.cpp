#include "ImageMetrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace prism::image {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

bool sameSize(const Image &a, const Image &b)
{
  return a.width == b.width && a.height == b.height
         && a.pixels.size() == b.pixels.size()
         && a.pixels.size() == size_t(a.width) * a.height;
}

int channelCount(Channels channels)
{
  return channels == Channels::Rgb ? 3 : 4;
}

// |x - y|, with equal values (infinities, NaNs) 0 apart and a NaN against
// anything else infinitely far.
double difference(float x, float y)
{
  if (x == y || (std::isnan(x) && std::isnan(y)))
    return 0.0;
  const double d = std::fabs(double(x) - double(y));
  return std::isnan(d) ? kInfinity : d;
}

} // namespace

double rmse(const Image &a, const Image &b, Channels channels)
{
  if (!sameSize(a, b))
    return kInfinity;
  if (a.pixels.empty())
    return 0.0;
  const int n = channelCount(channels);
  double sum = 0.0;
  for (size_t i = 0; i < a.pixels.size(); i++) {
    for (int c = 0; c < n; c++) {
      const double d = difference(a.pixels[i][c], b.pixels[i][c]);
      sum += d * d;
    }
  }
  return std::sqrt(sum / (double(a.pixels.size()) * n));
}

double maxAbsDifference(const Image &a, const Image &b, Channels channels)
{
  if (!sameSize(a, b))
    return kInfinity;
  const int n = channelCount(channels);
  double largest = 0.0;
  for (size_t i = 0; i < a.pixels.size(); i++) {
    for (int c = 0; c < n; c++)
      largest = std::max(largest, difference(a.pixels[i][c], b.pixels[i][c]));
  }
  return largest;
}

double psnr(const Image &a, const Image &b, Channels channels, double peak)
{
  const double error = rmse(a, b, channels);
  if (error == 0.0)
    return kInfinity;
  return 20.0 * std::log10(peak / error);
}

double fractionDiffering(
    const Image &a, const Image &b, double threshold, Channels channels)
{
  if (!sameSize(a, b))
    return 1.0;
  if (a.pixels.empty())
    return 0.0;
  const int n = channelCount(channels);
  size_t differing = 0;
  for (size_t i = 0; i < a.pixels.size(); i++) {
    for (int c = 0; c < n; c++) {
      if (difference(a.pixels[i][c], b.pixels[i][c]) > threshold) {
        differing++;
        break;
      }
    }
  }
  return double(differing) / double(a.pixels.size());
}

Comparison compare(
    const Image &a, const Image &b, double threshold, Channels channels)
{
  return {rmse(a, b, channels),
      maxAbsDifference(a, b, channels),
      psnr(a, b, channels),
      fractionDiffering(a, b, threshold, channels)};
}

Image diffImage(const Image &a, const Image &b, float scale)
{
  if (!sameSize(a, b))
    return {};
  Image out(a.width, a.height);
  if (scale <= 0.f) {
    double largest = 0.0;
    for (size_t i = 0; i < a.pixels.size(); i++) {
      for (int c = 0; c < 3; c++) {
        const double d = difference(a.pixels[i][c], b.pixels[i][c]);
        if (std::isfinite(d))
          largest = std::max(largest, d);
      }
    }
    scale = largest > 0.0 ? float(1.0 / largest) : 1.f;
  }
  for (size_t i = 0; i < a.pixels.size(); i++) {
    for (int c = 0; c < 3; c++) {
      const double d = difference(a.pixels[i][c], b.pixels[i][c]);
      out.pixels[i][c] = std::isfinite(d) ? float(d) * scale : 1.f;
    }
  }
  return out;
}

} // namespace prism::image
