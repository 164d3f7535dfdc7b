// Vector, box and matrix helpers.
#include "math/Vec.h"

#include <gtest/gtest.h>

#include <cstring>

using namespace prism;

namespace {

void expectNear(float3 a, float3 b, float tolerance = 1e-6f)
{
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

void expectIdentity(const mat3x4 &m, float tolerance)
{
  for (int c = 0; c < 4; c++)
    expectNear(m.col[c], kIdentityMat3x4.col[c], tolerance);
}

// Rotation about a tilted axis, non-uniform scale, translation.
mat3x4 testTransform()
{
  const float3 axis = normalize(float3{1.f, 2.f, 3.f});
  const float angle = 0.7f, c = std::cos(angle), s = std::sin(angle);
  const auto column = [&](float3 e) {
    // Rodrigues' rotation of basis vector e.
    return e * c + cross(axis, e) * s + axis * (dot(axis, e) * (1.f - c));
  };
  const mat3 rotation{
      {column({1, 0, 0}), column({0, 1, 0}), column({0, 0, 1})}};
  const mat3 scale{{{2.f, 0, 0}, {0, 0.5f, 0}, {0, 0, 3.f}}};
  return makeAffine(rotation * scale, {4.f, -5.f, 6.f});
}

} // namespace

// Compile-time use in constexpr contexts.
static_assert(float3{1, 2, 3} + float3{1, 1, 1} == float3{2, 3, 4});
static_assert(dot(float3{1, 2, 3}, float3{4, 5, 6}) == 32.f);
static_assert(cross(float3{1, 0, 0}, float3{0, 1, 0}) == float3{0, 0, 1});
static_assert(
    transformPoint(kIdentityMat3x4, float3{1, 2, 3}) == float3{1, 2, 3});

TEST(Vec, Arithmetic)
{
  const float3 a{1.f, 2.f, 3.f}, b{4.f, 6.f, 8.f};
  EXPECT_EQ(a + b, (float3{5.f, 8.f, 11.f}));
  EXPECT_EQ(b - a, (float3{3.f, 4.f, 5.f}));
  EXPECT_EQ(a * b, (float3{4.f, 12.f, 24.f}));
  EXPECT_EQ(b / a, (float3{4.f, 3.f, 8.f / 3.f}));
  EXPECT_EQ(a * 2.f, (float3{2.f, 4.f, 6.f}));
  EXPECT_EQ(2.f * a, a * 2.f);
  EXPECT_EQ(b / 2.f, (float3{2.f, 3.f, 4.f}));
  EXPECT_EQ(12.f / b, (float3{3.f, 2.f, 1.5f}));
  EXPECT_EQ(-a, (float3{-1.f, -2.f, -3.f}));
  float4 c{1.f, 1.f, 1.f, 1.f};
  c += float4{1.f, 2.f, 3.f, 4.f};
  c *= 2.f;
  EXPECT_EQ(c, (float4{4.f, 6.f, 8.f, 10.f}));
  EXPECT_EQ((int2{7, -3} / 2), (int2{3, -1}));
  EXPECT_EQ((uint3{1u, 2u, 3u} * uint3{2u, 2u, 2u}), (uint3{2u, 4u, 6u}));
  EXPECT_EQ(c[3], 10.f);
  c[1] = 0.f;
  EXPECT_EQ(c.y, 0.f);
}

TEST(Vec, Geometry)
{
  EXPECT_EQ(dot(float3{1, 2, 3}, float3{4, -5, 6}), 12.f);
  EXPECT_EQ(cross(float3{0, 1, 0}, float3{0, 0, 1}), (float3{1, 0, 0}));
  EXPECT_EQ(length(float3{3, 4, 0}), 5.f);
  EXPECT_EQ(lengthSquared(float2{3, 4}), 25.f);
  EXPECT_NEAR(length(normalize(float3{1, -7, 3})), 1.f, 1e-6f);
  EXPECT_EQ(normalize(float3{0, 0, -2}), (float3{0, 0, -1}));
  EXPECT_DOUBLE_EQ(length(double3{2, 3, 6}), 7.0);
}

TEST(Vec, ComponentWise)
{
  const float4 a{1, 5, -2, 0}, b{3, 4, -1, 0};
  EXPECT_EQ(min(a, b), (float4{1, 4, -2, 0}));
  EXPECT_EQ(max(a, b), (float4{3, 5, -1, 0}));
  EXPECT_EQ(clamp(a, 0.f, 2.f), (float4{1, 2, 0, 0}));
  EXPECT_EQ(
      clamp(a, float4{2, 2, 2, 2}, float4{3, 3, 3, 3}), (float4{2, 3, 2, 2}));
  EXPECT_EQ(abs(float3{-1, 2, -3}), (float3{1, 2, 3}));
  EXPECT_EQ(minComponent(a), -2.f);
  EXPECT_EQ(maxComponent(a), 5.f);
  EXPECT_EQ(min(3, 4), 3);
  EXPECT_EQ(clamp(5.f, 0.f, 1.f), 1.f);
  EXPECT_EQ(xyz(a), (float3{1, 5, -2}));
  EXPECT_EQ(makeVec4(float3{1, 2, 3}, 4.f), (float4{1, 2, 3, 4}));
  EXPECT_EQ(vecCast<float>(int3{1, -2, 3}), (float3{1, -2, 3}));
}

TEST(Vec, LerpIsExactAtTheEnds)
{
  const float3 a{0.1f, 0.7f, 1e8f}, b{0.3f, -0.2f, 1.f};
  EXPECT_EQ(lerp(a, b, 0.f), a);
  EXPECT_EQ(lerp(a, b, 1.f), b);
  EXPECT_EQ(lerp(float2{0, 2}, float2{1, 4}, 0.5f), (float2{0.5f, 3}));
  EXPECT_EQ(lerp(0.1f, 0.3f, 1.f), 0.3f);
}

TEST(Vec, Box)
{
  box3 b = emptyBox3();
  EXPECT_TRUE(isEmpty(b));
  b = extend(b, float3{1, 2, 3});
  EXPECT_FALSE(isEmpty(b));
  b = extend(b, float3{-1, 4, 0});
  EXPECT_EQ(b.lower, (float3{-1, 2, 0}));
  EXPECT_EQ(b.upper, (float3{1, 4, 3}));
  EXPECT_EQ(center(b), (float3{0, 3, 1.5f}));
  EXPECT_EQ(extent(b), (float3{2, 2, 3}));
  EXPECT_TRUE(contains(b, float3{0, 3, 3}));
  EXPECT_FALSE(contains(b, float3{0, 5, 1}));
  const box3 other{{0, 0, 0}, {5, 5, 5}};
  EXPECT_EQ(extend(b, other).upper, (float3{5, 5, 5}));
  EXPECT_EQ(intersect(b, other).lower, (float3{0, 2, 0}));
  EXPECT_TRUE(isEmpty(intersect(b, box3{{2, 2, 2}, {3, 3, 3}})));
}

TEST(Vec, Mat3Inverse)
{
  const mat3 m = linearPart(testTransform());
  const mat3 product = m * inverse(m);
  for (int c = 0; c < 3; c++)
    expectNear(product.col[c], kIdentityMat3.col[c]);
  EXPECT_NEAR(determinant(m), 3.f, 1e-5f);
  EXPECT_EQ(transpose(transpose(m)).col[1], m.col[1]);
}

TEST(Vec, AffineTransforms)
{
  const mat3x4 scaleMove{{{2, 0, 0}, {0, 3, 0}, {0, 0, 4}, {1, 1, 1}}};
  EXPECT_EQ(transformPoint(scaleMove, float3{1, 1, 1}), (float3{3, 4, 5}));
  EXPECT_EQ(transformDirection(scaleMove, float3{1, 1, 1}), (float3{2, 3, 4}));
  const mat3x4 a = testTransform(), b = scaleMove;
  const float3 p{0.3f, -1.2f, 2.f};
  expectNear(
      transformPoint(a * b, p), transformPoint(a, transformPoint(b, p)), 1e-5f);
}

TEST(Vec, AffineInverse)
{
  const mat3x4 m = testTransform();
  const mat3x4 inv = inverse(m);
  expectIdentity(inv * m, 1e-6f);
  expectIdentity(m * inv, 1e-6f);
  const float3 p{1.f, 2.f, -3.f};
  expectNear(transformPoint(inv, transformPoint(m, p)), p, 1e-5f);
}

TEST(Vec, NormalsStayPerpendicular)
{
  const mat3x4 m = testTransform();
  const float3 tangent{1.f, -1.f, 0.f}, normal{1.f, 1.f, 5.f};
  ASSERT_EQ(dot(tangent, normal), 0.f);
  const float3 n = transformNormal(inverse(m), normal);
  EXPECT_NEAR(dot(transformDirection(m, tangent), n), 0.f, 1e-5f);
}

TEST(Vec, MatricesUseAnariMemoryLayout)
{
  // FLOAT32_MAT4 is column-major: the translation is floats 12-14.
  float data[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 7, 8, 9, 1};
  mat4 m4;
  std::memcpy(&m4, data, sizeof(m4));
  const mat3x4 affine = affineFromMat4(m4);
  EXPECT_EQ(transformPoint(affine, float3{0, 0, 0}), (float3{7, 8, 9}));
  EXPECT_EQ((m4 * float4{0, 0, 0, 1}), (float4{7, 8, 9, 1}));
  const mat4 back = mat4FromAffine(affine);
  EXPECT_EQ(std::memcmp(&back, data, sizeof(data)), 0);

  // FLOAT32_MAT3x4: four columns of three floats, translation last.
  const float data34[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 4, 5, 6};
  mat3x4 m34;
  std::memcpy(&m34, data34, sizeof(m34));
  EXPECT_EQ(m34.col[3], (float3{4, 5, 6}));
}

TEST(Vec, Mat4Products)
{
  mat4 m = mat4FromAffine(testTransform());
  const mat4 product = m * kIdentityMat4;
  EXPECT_EQ(std::memcmp(&product, &m, sizeof(m)), 0);
  const mat4 t = transpose(m);
  EXPECT_EQ(t.col[3].x, m.col[0].w);
  EXPECT_EQ(t.col[0].w, m.col[3].x);
}
