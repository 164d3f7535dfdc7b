#include "Sampling.h"

#include "math/Trig.h"

#include <algorithm>
#include <cmath>

namespace prism::light {

Frame frameAround(float3 z)
{
  // Two vectors orthogonal to z and to each other, from the identity
  // x = (1 - s zx^2 / (1 + s zz), ...) with s the sign of z.z, which has no
  // singularity for either hemisphere.
  const float sign = std::copysign(1.f, z.z);
  const float a = -1.f / (sign + z.z);
  const float b = z.x * z.y * a;
  return {{1.f + sign * z.x * z.x * a, sign * b, -sign * z.x},
      {b, sign + z.y * z.y * a, -z.y},
      z};
}

Frame frameAround(float3 z, float3 hint)
{
  const float3 x = hint - z * dot(hint, z);
  const float length2 = lengthSquared(x);
  if (!(length2 > 1e-12f * max(lengthSquared(hint), 1e-30f)))
    return frameAround(z);
  const float3 xUnit = x / std::sqrt(length2);
  return {xUnit, cross(z, xUnit), z};
}

float3 sampleCap(float2 u, float capHeight)
{
  // cos(theta) is uniform in [1 - capHeight, 1]; sin^2 from the cap height
  // keeps tiny cones (the sun) from rounding to a single direction.
  const float h = u.x * capHeight;
  const float cosTheta = 1.f - h;
  const float sinTheta = std::sqrt(max(0.f, h * (2.f - h)));
  const float2 cs = cosSinTurn(u.y);
  return {cs.x * sinTheta, cs.y * sinTheta, cosTheta};
}

double integrateOverSphere(const std::function<double(double theta)> &f,
    std::vector<double> breakpoints)
{
  breakpoints.push_back(0.0);
  breakpoints.push_back(kPiDouble);
  for (double &b : breakpoints)
    b = clamp(b, 0.0, kPiDouble);
  std::sort(breakpoints.begin(), breakpoints.end());
  constexpr int kIntervals = 64; // per piece, even for Simpson
  double sum = 0.0;
  for (size_t i = 0; i + 1 < breakpoints.size(); i++) {
    const double begin = breakpoints[i], end = breakpoints[i + 1];
    if (!(end > begin))
      continue;
    const double h = (end - begin) / kIntervals;
    // Jumps sit on breakpoints: evaluate just inside each piece so a step
    // belongs to the piece it bounds.
    const double inset = h * 1e-9;
    auto g = [&](int k) {
      double theta = begin + k * h;
      theta = k == 0 ? begin + inset : (k == kIntervals ? end - inset : theta);
      return f(theta) * std::sin(theta);
    };
    double piece = g(0) + g(kIntervals);
    for (int k = 1; k < kIntervals; k++)
      piece += (k % 2 ? 4.0 : 2.0) * g(k);
    sum += piece * h / 3.0;
  }
  return 2.0 * kPiDouble * sum;
}

} // namespace prism::light
