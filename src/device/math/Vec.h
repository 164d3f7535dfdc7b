// Small vector, box and matrix types for the device. All are POD (trivial,
// standard layout, no padding), so ANARI data can be memcpy'd straight in;
// matrices are column-major exactly as ANARI stores FLOAT32_MAT4 / MAT3x4.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace prism {

// ---------------------------------------------------------------------------
// Vectors

template <typename T>
struct Vec2
{
  T x, y;

  constexpr T &operator[](int i)
  {
    return i == 0 ? x : y;
  }
  constexpr const T &operator[](int i) const
  {
    return i == 0 ? x : y;
  }
  constexpr bool operator==(const Vec2 &) const = default;
};

template <typename T>
struct Vec3
{
  T x, y, z;

  constexpr T &operator[](int i)
  {
    return i == 0 ? x : (i == 1 ? y : z);
  }
  constexpr const T &operator[](int i) const
  {
    return i == 0 ? x : (i == 1 ? y : z);
  }
  constexpr bool operator==(const Vec3 &) const = default;
};

template <typename T>
struct Vec4
{
  T x, y, z, w;

  constexpr T &operator[](int i)
  {
    return i == 0 ? x : (i == 1 ? y : (i == 2 ? z : w));
  }
  constexpr const T &operator[](int i) const
  {
    return i == 0 ? x : (i == 1 ? y : (i == 2 ? z : w));
  }
  constexpr bool operator==(const Vec4 &) const = default;
};

using float2 = Vec2<float>;
using float3 = Vec3<float>;
using float4 = Vec4<float>;
using double2 = Vec2<double>;
using double3 = Vec3<double>;
using double4 = Vec4<double>;
using int2 = Vec2<int32_t>;
using int3 = Vec3<int32_t>;
using int4 = Vec4<int32_t>;
using uint2 = Vec2<uint32_t>;
using uint3 = Vec3<uint32_t>;
using uint4 = Vec4<uint32_t>;

static_assert(sizeof(float3) == 12 && std::is_trivial_v<float3>);
static_assert(sizeof(float4) == 16 && std::is_standard_layout_v<float4>);

namespace detail {

template <typename V>
struct VecTraits
{
  static constexpr bool kIsVector = false;
};
template <typename T>
struct VecTraits<Vec2<T>>
{
  static constexpr bool kIsVector = true;
  using Scalar = T;
};
template <typename T>
struct VecTraits<Vec3<T>>
{
  static constexpr bool kIsVector = true;
  using Scalar = T;
};
template <typename T>
struct VecTraits<Vec4<T>>
{
  static constexpr bool kIsVector = true;
  using Scalar = T;
};

// Component-wise application of `f`; written out per size so that every
// operator below compiles to straight-line code.
template <typename T, typename F>
constexpr Vec2<T> zip(Vec2<T> a, Vec2<T> b, F f)
{
  return {T(f(a.x, b.x)), T(f(a.y, b.y))};
}
template <typename T, typename F>
constexpr Vec3<T> zip(Vec3<T> a, Vec3<T> b, F f)
{
  return {T(f(a.x, b.x)), T(f(a.y, b.y)), T(f(a.z, b.z))};
}
template <typename T, typename F>
constexpr Vec4<T> zip(Vec4<T> a, Vec4<T> b, F f)
{
  return {T(f(a.x, b.x)), T(f(a.y, b.y)), T(f(a.z, b.z)), T(f(a.w, b.w))};
}

template <typename T, typename F>
constexpr auto map(Vec2<T> a, F f)
{
  using U = decltype(f(a.x));
  return Vec2<U>{f(a.x), f(a.y)};
}
template <typename T, typename F>
constexpr auto map(Vec3<T> a, F f)
{
  using U = decltype(f(a.x));
  return Vec3<U>{f(a.x), f(a.y), f(a.z)};
}
template <typename T, typename F>
constexpr auto map(Vec4<T> a, F f)
{
  using U = decltype(f(a.x));
  return Vec4<U>{f(a.x), f(a.y), f(a.z), f(a.w)};
}

template <typename T, typename F>
constexpr T fold(Vec2<T> a, F f)
{
  return f(a.x, a.y);
}
template <typename T, typename F>
constexpr T fold(Vec3<T> a, F f)
{
  return f(f(a.x, a.y), a.z);
}
template <typename T, typename F>
constexpr T fold(Vec4<T> a, F f)
{
  return f(f(a.x, a.y), f(a.z, a.w));
}

} // namespace detail

template <typename V>
concept Vector = detail::VecTraits<V>::kIsVector;

template <Vector V>
using ScalarOf = typename detail::VecTraits<V>::Scalar;

// Scalars: one set of helpers so code in `prism` never mixes std:: and ours.

template <typename T>
requires std::is_arithmetic_v<T>
constexpr T min(T a, T b)
{
  return b < a ? b : a;
}
template <typename T>
requires std::is_arithmetic_v<T>
constexpr T max(T a, T b)
{
  return a < b ? b : a;
}
template <typename T>
requires std::is_arithmetic_v<T>
constexpr T clamp(T v, T lo, T hi)
{
  return min(max(v, lo), hi);
}
// (1 - t) a + t b: exact at both ends, unlike a + t (b - a).
template <typename T>
requires std::is_floating_point_v<T>
constexpr T lerp(T a, T b, T t)
{
  return (T(1) - t) * a + t * b;
}

// Arithmetic, component-wise and with a scalar on either side.

template <Vector V>
constexpr V operator+(V a, V b)
{
  return detail::zip(a, b, [](auto p, auto q) { return p + q; });
}
template <Vector V>
constexpr V operator-(V a, V b)
{
  return detail::zip(a, b, [](auto p, auto q) { return p - q; });
}
template <Vector V>
constexpr V operator*(V a, V b)
{
  return detail::zip(a, b, [](auto p, auto q) { return p * q; });
}
template <Vector V>
constexpr V operator/(V a, V b)
{
  return detail::zip(a, b, [](auto p, auto q) { return p / q; });
}
template <Vector V>
constexpr V operator-(V a)
{
  return detail::map(a, [](auto p) { return ScalarOf<V>(-p); });
}
template <Vector V>
constexpr V operator*(V a, ScalarOf<V> s)
{
  return detail::map(a, [s](auto p) { return ScalarOf<V>(p * s); });
}
template <Vector V>
constexpr V operator*(ScalarOf<V> s, V a)
{
  return a * s;
}
template <Vector V>
constexpr V operator/(V a, ScalarOf<V> s)
{
  return detail::map(a, [s](auto p) { return ScalarOf<V>(p / s); });
}
template <Vector V>
constexpr V operator/(ScalarOf<V> s, V a)
{
  return detail::map(a, [s](auto p) { return ScalarOf<V>(s / p); });
}
template <Vector V>
constexpr V operator+(V a, ScalarOf<V> s)
{
  return detail::map(a, [s](auto p) { return ScalarOf<V>(p + s); });
}
template <Vector V>
constexpr V operator-(V a, ScalarOf<V> s)
{
  return detail::map(a, [s](auto p) { return ScalarOf<V>(p - s); });
}

template <Vector V>
constexpr V &operator+=(V &a, V b)
{
  return a = a + b;
}
template <Vector V>
constexpr V &operator-=(V &a, V b)
{
  return a = a - b;
}
template <Vector V>
constexpr V &operator*=(V &a, V b)
{
  return a = a * b;
}
template <Vector V>
constexpr V &operator/=(V &a, V b)
{
  return a = a / b;
}
template <Vector V>
constexpr V &operator*=(V &a, ScalarOf<V> s)
{
  return a = a * s;
}
template <Vector V>
constexpr V &operator/=(V &a, ScalarOf<V> s)
{
  return a = a / s;
}

// Component-wise functions and reductions.

template <Vector V>
constexpr V min(V a, V b)
{
  return detail::zip(a, b, [](auto p, auto q) { return min(p, q); });
}
template <Vector V>
constexpr V max(V a, V b)
{
  return detail::zip(a, b, [](auto p, auto q) { return max(p, q); });
}
template <Vector V>
constexpr V clamp(V v, V lo, V hi)
{
  return min(max(v, lo), hi);
}
template <Vector V>
constexpr V clamp(V v, ScalarOf<V> lo, ScalarOf<V> hi)
{
  return detail::map(v, [=](auto p) { return clamp(p, lo, hi); });
}
template <Vector V>
inline V abs(V a)
{
  return detail::map(a, [](auto p) { return ScalarOf<V>(std::abs(p)); });
}
template <Vector V>
constexpr V lerp(V a, V b, ScalarOf<V> t)
{
  return (ScalarOf<V>(1) - t) * a + t * b;
}
template <Vector V>
constexpr ScalarOf<V> minComponent(V a)
{
  return detail::fold(a, [](auto p, auto q) { return min(p, q); });
}
template <Vector V>
constexpr ScalarOf<V> maxComponent(V a)
{
  return detail::fold(a, [](auto p, auto q) { return max(p, q); });
}

template <Vector V>
constexpr ScalarOf<V> dot(V a, V b)
{
  return detail::fold(a * b, [](auto p, auto q) { return p + q; });
}
template <typename T>
constexpr Vec3<T> cross(Vec3<T> a, Vec3<T> b)
{
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <Vector V>
constexpr ScalarOf<V> lengthSquared(V a)
{
  return dot(a, a);
}
template <Vector V>
inline ScalarOf<V> length(V a)
{
  return std::sqrt(dot(a, a));
}
// Unit vector along `a`; a zero vector gives non-finite components.
template <Vector V>
inline V normalize(V a)
{
  return a * (ScalarOf<V>(1) / length(a));
}

// Conversions between element types and sizes.

template <typename U, typename T>
constexpr Vec2<U> vecCast(Vec2<T> a)
{
  return {U(a.x), U(a.y)};
}
template <typename U, typename T>
constexpr Vec3<U> vecCast(Vec3<T> a)
{
  return {U(a.x), U(a.y), U(a.z)};
}
template <typename U, typename T>
constexpr Vec4<U> vecCast(Vec4<T> a)
{
  return {U(a.x), U(a.y), U(a.z), U(a.w)};
}
template <typename T>
constexpr Vec3<T> xyz(Vec4<T> a)
{
  return {a.x, a.y, a.z};
}
template <typename T>
constexpr Vec4<T> makeVec4(Vec3<T> a, T w)
{
  return {a.x, a.y, a.z, w};
}

// ---------------------------------------------------------------------------
// Axis-aligned box; the empty box has lower > upper so extend() just works.

struct box3
{
  float3 lower, upper;
};

constexpr box3 emptyBox3()
{
  constexpr float inf = std::numeric_limits<float>::infinity();
  return {{inf, inf, inf}, {-inf, -inf, -inf}};
}
constexpr bool isEmpty(const box3 &b)
{
  return b.lower.x > b.upper.x || b.lower.y > b.upper.y
         || b.lower.z > b.upper.z;
}
constexpr box3 extend(const box3 &b, float3 p)
{
  return {min(b.lower, p), max(b.upper, p)};
}
constexpr box3 extend(const box3 &a, const box3 &b)
{
  return {min(a.lower, b.lower), max(a.upper, b.upper)};
}
constexpr box3 intersect(const box3 &a, const box3 &b)
{
  return {max(a.lower, b.lower), min(a.upper, b.upper)};
}
constexpr bool contains(const box3 &b, float3 p)
{
  return p.x >= b.lower.x && p.y >= b.lower.y && p.z >= b.lower.z
         && p.x <= b.upper.x && p.y <= b.upper.y && p.z <= b.upper.z;
}
constexpr float3 center(const box3 &b)
{
  return 0.5f * (b.lower + b.upper);
}
constexpr float3 extent(const box3 &b)
{
  return b.upper - b.lower;
}

// ---------------------------------------------------------------------------
// Matrices, column-major: col[j] is column j, m * v = sum_j col[j] * v[j].

struct mat3
{
  float3 col[3];
};

// ANARI's FLOAT32_MAT4: four columns, the translation in col[3].
struct mat4
{
  float4 col[4];
};

// ANARI's FLOAT32_MAT3x4 affine transform: linear part in col[0..2],
// translation in col[3] (the implicit fourth row is (0, 0, 0, 1)).
struct mat3x4
{
  float3 col[4];
};

static_assert(
    sizeof(mat3x4) == 12 * sizeof(float) && std::is_trivial_v<mat3x4>);
static_assert(sizeof(mat4) == 16 * sizeof(float) && std::is_trivial_v<mat4>);

inline constexpr mat3 kIdentityMat3{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
inline constexpr mat3x4 kIdentityMat3x4{
    {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 0}}};
inline constexpr mat4 kIdentityMat4{
    {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};

constexpr float3 operator*(const mat3 &m, float3 v)
{
  return m.col[0] * v.x + m.col[1] * v.y + m.col[2] * v.z;
}
constexpr mat3 operator*(const mat3 &a, const mat3 &b)
{
  return {{a * b.col[0], a * b.col[1], a * b.col[2]}};
}
constexpr mat3 transpose(const mat3 &m)
{
  return {{{m.col[0].x, m.col[1].x, m.col[2].x},
      {m.col[0].y, m.col[1].y, m.col[2].y},
      {m.col[0].z, m.col[1].z, m.col[2].z}}};
}
constexpr float determinant(const mat3 &m)
{
  return dot(m.col[0], cross(m.col[1], m.col[2]));
}
// Rows of the inverse are the cross products of column pairs over the
// determinant; a singular matrix gives non-finite entries.
constexpr mat3 inverse(const mat3 &m)
{
  const float3 r0 = cross(m.col[1], m.col[2]);
  const float3 r1 = cross(m.col[2], m.col[0]);
  const float3 r2 = cross(m.col[0], m.col[1]);
  const float s = 1.f / dot(m.col[0], r0);
  return transpose(mat3{{r0 * s, r1 * s, r2 * s}});
}

constexpr float4 operator*(const mat4 &m, float4 v)
{
  return m.col[0] * v.x + m.col[1] * v.y + m.col[2] * v.z + m.col[3] * v.w;
}
constexpr mat4 operator*(const mat4 &a, const mat4 &b)
{
  return {{a * b.col[0], a * b.col[1], a * b.col[2], a * b.col[3]}};
}
constexpr mat4 transpose(const mat4 &m)
{
  mat4 t{};
  for (int i = 0; i < 4; i++) {
    for (int j = 0; j < 4; j++)
      t.col[i][j] = m.col[j][i];
  }
  return t;
}

constexpr mat3 linearPart(const mat3x4 &m)
{
  return {{m.col[0], m.col[1], m.col[2]}};
}
constexpr mat3x4 makeAffine(const mat3 &linear, float3 translation)
{
  return {{linear.col[0], linear.col[1], linear.col[2], translation}};
}
// Drops the last row, which the spec lets devices treat as (0, 0, 0, 1).
constexpr mat3x4 affineFromMat4(const mat4 &m)
{
  return {{xyz(m.col[0]), xyz(m.col[1]), xyz(m.col[2]), xyz(m.col[3])}};
}
constexpr mat4 mat4FromAffine(const mat3x4 &m)
{
  return {{makeVec4(m.col[0], 0.f),
      makeVec4(m.col[1], 0.f),
      makeVec4(m.col[2], 0.f),
      makeVec4(m.col[3], 1.f)}};
}

constexpr float3 transformPoint(const mat3x4 &m, float3 p)
{
  return m.col[0] * p.x + m.col[1] * p.y + m.col[2] * p.z + m.col[3];
}
constexpr float3 transformDirection(const mat3x4 &m, float3 d)
{
  return m.col[0] * d.x + m.col[1] * d.y + m.col[2] * d.z;
}
// Normals transform by the inverse transpose; taking the already inverted
// transform keeps this to three dot products per normal.
constexpr float3 transformNormal(const mat3x4 &inverseTransform, float3 n)
{
  return {dot(inverseTransform.col[0], n),
      dot(inverseTransform.col[1], n),
      dot(inverseTransform.col[2], n)};
}
// a * b applies b first, then a.
constexpr mat3x4 operator*(const mat3x4 &a, const mat3x4 &b)
{
  return {{transformDirection(a, b.col[0]),
      transformDirection(a, b.col[1]),
      transformDirection(a, b.col[2]),
      transformPoint(a, b.col[3])}};
}
constexpr mat3x4 inverse(const mat3x4 &m)
{
  const mat3 inverseLinear = inverse(linearPart(m));
  return makeAffine(inverseLinear, -(inverseLinear * m.col[3]));
}

} // namespace prism
