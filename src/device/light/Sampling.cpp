#include "Sampling.h"

#include "math/Trig.h"

#include <algorithm>
#include <cmath>

namespace prism::light {
namespace {

// Unit vector along `v`, or `fallback` when `v` is too short to normalise.
double3 normalizeOr(const double3 &v, const double3 &fallback)
{
  const double length2 = lengthSquared(v);
  return length2 > 1e-300 ? v / std::sqrt(length2) : fallback;
}

} // namespace

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

double sphericalTriangleArea(
    const double3 &a, const double3 &b, const double3 &c)
{
  // tan(area / 2) = |a . (b x c)| / (1 + a.b + b.c + c.a) for unit vectors;
  // atan2 keeps areas above pi, where the denominator turns negative.
  const double numerator = std::abs(dot(a, cross(b, c)));
  const double denominator = 1.0 + dot(a, b) + dot(b, c) + dot(c, a);
  return 2.0 * std::atan2(numerator, denominator);
}

double3 sampleSphericalTriangle(
    const double3 &a, const double3 &b, const double3 &c, double area, float2 u)
{
  // The interior angle at `a`, between the great circles through a, b and
  // a, c (the angle of their planes' normals).
  // Its sine from the cross product stays accurate for thin triangles.
  const double3 normalAB = normalizeOr(cross(a, b), {0, 0, 1});
  const double3 normalAC = normalizeOr(cross(a, c), {0, 0, 1});
  const double cosAlpha = clamp(dot(normalAB, normalAC), -1.0, 1.0);
  const double sinAlpha = std::min(1.0, length(cross(normalAB, normalAC)));

  // The point c' on arc ac for which triangle a, b, c' has area u.x * area:
  // the spherical law of cosines for angles solved for cos(arc a c'), with
  // s, t the sine and cosine of u.x * area - alpha.
  const double sampled = double(u.x) * area;
  const double sinSampled = std::sin(sampled), cosSampled = std::cos(sampled);
  const double s = sinSampled * cosAlpha - cosSampled * sinAlpha;
  const double t = cosSampled * cosAlpha + sinSampled * sinAlpha;
  const double p = t - cosAlpha;
  const double q = s + sinAlpha * dot(a, b);
  const double denominator = (q * s + p * t) * sinAlpha;
  const double cosArc =
      denominator != 0.0
          ? clamp(((q * t - p * s) * cosAlpha - q) / denominator, -1.0, 1.0)
          : 1.0;
  const double3 towardsC = normalizeOr(c - a * dot(c, a), b);
  const double3 cPrime =
      a * cosArc + towardsC * std::sqrt(max(0.0, 1.0 - cosArc * cosArc));

  // Along arc b c', cos(angle from b) uniform between 1 and b . c' gives
  // uniform area in the sub-triangle's last sliver.
  const double z = 1.0 - double(u.y) * (1.0 - dot(cPrime, b));
  const double3 towardsCPrime = normalizeOr(cPrime - b * dot(cPrime, b), b);
  return b * z + towardsCPrime * std::sqrt(max(0.0, 1.0 - z * z));
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
