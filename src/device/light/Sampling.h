// Geometry and sampling helpers only lights need: caps of cones,
// spherical-triangle sampling and quadrature over the sphere of directions
// (frames and the warps they share with BSDFs are math/LocalFrame.h and
// math/SphereSampling.h). Angles in radians, solid angles in steradians.
#pragma once

#include "../math/LocalFrame.h"
#include "../math/Luminance.h"
#include "../math/SphereSampling.h"
#include "../math/Vec.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

namespace prism::light {

// What of a point light's intensity reaches distance sqrt(distance2):
// 1 / d^decay (PRISM_LIGHT_DECAY; 2, the inverse square, exactly as 1/d^2).
inline float distanceFalloff(float distance2, float decay)
{
  return decay == 2.f ? 1.f / distance2 : std::pow(distance2, -0.5f * decay);
}

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr double kPiDouble = 3.14159265358979323846;

// The unit direction `d` (object space) in world space; `d` itself when a
// singular transform collapses it.
inline float3 transformUnit(const mat3x4 &worldFromObject, float3 d)
{
  const float3 w = transformDirection(worldFromObject, d);
  const float length2 = lengthSquared(w);
  return length2 > 0.f && std::isfinite(length2) ? w / std::sqrt(length2) : d;
}

// 3t^2 - 2t^3 of t clamped to [0, 1].
inline float smoothStep(float t)
{
  t = clamp(t, 0.f, 1.f);
  return t * t * (3.f - 2.f * t);
}

// 1 - cos(angle), accurate for small angles (2 sin^2(angle / 2)).
inline float oneMinusCos(float angle)
{
  const float s = std::sin(0.5f * angle);
  return 2.f * s * s;
}
// 1 - dot(a, b) of unit vectors, accurate when they nearly agree.
inline float oneMinusDot(float3 a, float3 b)
{
  return 0.5f * lengthSquared(a - b);
}

// Whether the unit `direction` lies in the cone around the unit `axis` of
// cap height 1 - cos(halfAngle); the slack of a few float roundings of the
// cone's chord keeps sampleUniformCap()'s own rim directions inside.
inline bool insideCap(float3 direction, float3 axis, float capHeight)
{
  return oneMinusDot(direction, axis)
         <= capHeight + 4e-7f * std::sqrt(capHeight);
}

// Spherical triangles, in float (quad lights' sampling) or double (tests'
// references).

// Unit vector along `v`, or `fallback` when `v` is too short to normalise.
template <typename T>
inline Vec3<T> normalizeOr(const Vec3<T> &v, const Vec3<T> &fallback)
{
  const T length2 = lengthSquared(v);
  return length2 > std::numeric_limits<T>::min()
             ? v * (T(1) / std::sqrt(length2))
             : fallback;
}
// Solid angle of the spherical triangle of the unit vectors a, b, c
// (Van Oosterom and Strackee's formula; exact for every size).
template <typename T>
inline T sphericalTriangleArea(
    const Vec3<T> &a, const Vec3<T> &b, const Vec3<T> &c)
{
  // tan(area / 2) = |a . (b x c)| / (1 + a.b + b.c + c.a) for unit vectors;
  // atan2 keeps areas above pi, where the denominator turns negative.
  const T numerator = std::abs(dot(a, cross(b, c)));
  const T denominator = T(1) + dot(a, b) + dot(b, c) + dot(c, a);
  return T(2) * std::atan2(numerator, denominator);
}

// A direction uniform in that triangle, `area` its solid angle (Arvo 1995:
// a sub-triangle of area u.x * area, then a point along its last arc).
template <typename T>
inline Vec3<T> sampleSphericalTriangle(
    const Vec3<T> &a, const Vec3<T> &b, const Vec3<T> &c, T area, float2 u)
{
  // The interior angle at `a`, between the great circles through a, b and
  // a, c (the angle of their planes' normals).
  // Its sine from the cross product stays accurate for thin triangles.
  const Vec3<T> normalAB = normalizeOr(cross(a, b), {0, 0, 1});
  const Vec3<T> normalAC = normalizeOr(cross(a, c), {0, 0, 1});
  const T cosAlpha = clamp(dot(normalAB, normalAC), -T(1), T(1));
  const T sinAlpha = std::min(T(1), length(cross(normalAB, normalAC)));

  // The point c' on arc ac for which triangle a, b, c' has area u.x * area:
  // the spherical law of cosines for angles solved for cos(arc a c'), with
  // s, t the sine and cosine of u.x * area - alpha.
  const T sampled = T(u.x) * area;
  const T sinSampled = std::sin(sampled), cosSampled = std::cos(sampled);
  const T s = sinSampled * cosAlpha - cosSampled * sinAlpha;
  const T t = cosSampled * cosAlpha + sinSampled * sinAlpha;
  const T p = t - cosAlpha;
  const T q = s + sinAlpha * dot(a, b);
  const T denominator = (q * s + p * t) * sinAlpha;
  const T cosArc =
      denominator != T(0)
          ? clamp(((q * t - p * s) * cosAlpha - q) / denominator, -T(1), T(1))
          : T(1);
  const Vec3<T> towardsC = normalizeOr(c - a * dot(c, a), b);
  const Vec3<T> cPrime =
      a * cosArc + towardsC * std::sqrt(max(T(0), T(1) - cosArc * cosArc));

  // Along arc b c', cos(angle from b) uniform between 1 and b . c' gives
  // uniform area in the sub-triangle's last sliver.
  const T z = T(1) - T(u.y) * (T(1) - dot(cPrime, b));
  const Vec3<T> towardsCPrime = normalizeOr(cPrime - b * dot(cPrime, b), b);
  return b * z + towardsCPrime * std::sqrt(max(T(0), T(1) - z * z));
}

// 2 pi * integral over [0, pi] of f(theta) sin(theta): the integral over the
// sphere of a function of the angle to an axis. Composite Simpson between
// sorted `breakpoints` (where f has kinks or jumps), accurate to ~1e-9 for
// piecewise smooth f.
double integrateOverSphere(const std::function<double(double theta)> &f,
    std::vector<double> breakpoints);

} // namespace prism::light
