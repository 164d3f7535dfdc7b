// The little vector and matrix math scene builders need: column-major 4x4
// matrices laid out like ANARI_FLOAT32_MAT4, and a seeded random generator
// whose sequence is the same on every platform and standard library.
#pragma once

#include "Scene.h"

#include <cmath>
#include <cstdint>

namespace prism::scenes {

// Column-major: element (row r, column c) is m[4 * c + r].
using Mat4 = std::array<float, 16>;

inline Vec3 operator+(const Vec3 &a, const Vec3 &b)
{
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline Vec3 operator-(const Vec3 &a, const Vec3 &b)
{
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline Vec3 operator*(const Vec3 &a, float s)
{
  return {a[0] * s, a[1] * s, a[2] * s};
}
inline float dot(const Vec3 &a, const Vec3 &b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vec3 cross(const Vec3 &a, const Vec3 &b)
{
  return {a[1] * b[2] - a[2] * b[1],
      a[2] * b[0] - a[0] * b[2],
      a[0] * b[1] - a[1] * b[0]};
}
inline float length(const Vec3 &a)
{
  return std::sqrt(dot(a, a));
}
// `a` scaled to unit length; the zero vector stays zero.
inline Vec3 normalize(const Vec3 &a)
{
  const float l = length(a);
  return l > 0.f ? a * (1.f / l) : a;
}

inline Mat4 identityMatrix()
{
  return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
}
inline Mat4 translationMatrix(const Vec3 &t)
{
  return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, t[0], t[1], t[2], 1};
}
inline Mat4 scaleMatrix(const Vec3 &s)
{
  return {s[0], 0, 0, 0, 0, s[1], 0, 0, 0, 0, s[2], 0, 0, 0, 0, 1};
}
// Rotation by `radians` about +y (right-handed: +z turns towards +x).
inline Mat4 rotationYMatrix(float radians)
{
  const float c = std::cos(radians), s = std::sin(radians);
  return {c, 0, -s, 0, 0, 1, 0, 0, s, 0, c, 0, 0, 0, 0, 1};
}
inline Mat4 operator*(const Mat4 &a, const Mat4 &b)
{
  Mat4 m{};
  for (int c = 0; c < 4; c++)
    for (int r = 0; r < 4; r++) {
      float sum = 0.f;
      for (int k = 0; k < 4; k++)
        sum += a[4 * k + r] * b[4 * c + k];
      m[4 * c + r] = sum;
    }
  return m;
}
inline Vec3 transformPoint(const Mat4 &m, const Vec3 &p)
{
  return {m[0] * p[0] + m[4] * p[1] + m[8] * p[2] + m[12],
      m[1] * p[0] + m[5] * p[1] + m[9] * p[2] + m[13],
      m[2] * p[0] + m[6] * p[1] + m[10] * p[2] + m[14]};
}
inline Vec3 transformDirection(const Mat4 &m, const Vec3 &d)
{
  return {m[0] * d[0] + m[4] * d[1] + m[8] * d[2],
      m[1] * d[0] + m[5] * d[1] + m[9] * d[2],
      m[2] * d[0] + m[6] * d[1] + m[10] * d[2]};
}

// PCG32 (O'Neill): small, fast and fully specified, unlike the
// distributions of <random>, so scenes are identical everywhere.
class Random
{
 public:
  explicit Random(uint64_t seed)
  {
    next();
    m_state += seed;
    next();
  }
  uint32_t next()
  {
    const uint64_t old = m_state;
    m_state = old * 6364136223846793005ull + kIncrement;
    const uint32_t shifted = uint32_t(((old >> 18u) ^ old) >> 27u);
    const uint32_t rotation = uint32_t(old >> 59u);
    return (shifted >> rotation) | (shifted << ((32 - rotation) & 31));
  }
  // Uniform in [0, 1).
  float uniform()
  {
    return float(next() >> 8) * (1.f / 16777216.f);
  }
  // Uniform in [lower, upper).
  float uniform(float lower, float upper)
  {
    return lower + (upper - lower) * uniform();
  }

 private:
  static constexpr uint64_t kIncrement = 1442695040888963407ull;
  uint64_t m_state{0};
};

} // namespace prism::scenes
