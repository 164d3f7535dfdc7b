// The light tree's choice among emitters (its probabilities sum to one and
// are the frequencies pick() chooses with) and the irradiance emissive
// surfaces deliver through it against Lambert's closed form.
#include "light/EmissiveSurface.h"
#include "light/LightTree.h"

#include "SquareOfCells.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace prism {
namespace {

// A row of small triangles along x in the plane z = 0, alternately facing
// +z and tilted towards +x, with powers 1, 2, 3, ...
std::vector<float3> triangleRow(int count)
{
  std::vector<float3> corners;
  for (int i = 0; i < count; i++) {
    const float x = float(i);
    const float tilt = i % 2 ? 0.3f : 0.f;
    const float size = 0.2f * std::sqrt(float(i + 1));
    corners.push_back({x, 0.f, 0.f});
    corners.push_back({x + size, 0.f, tilt});
    corners.push_back({x, size, 0.f});
  }
  return corners;
}

std::vector<light::TreeEmitter> emittersOf(const std::vector<float3> &corners)
{
  std::vector<light::TreeEmitter> out;
  for (size_t i = 0; i + 2 < corners.size(); i += 3) {
    const float3 *t = &corners[i];
    light::TreeEmitter e;
    const float3 n = cross(t[1] - t[0], t[2] - t[0]);
    e.power = 0.5f * length(n);
    e.normal = normalize(n);
    e.lower = min(t[0], min(t[1], t[2]));
    e.upper = max(t[0], max(t[1], t[2]));
    out.push_back(e);
  }
  return out;
}

const float3 kPoints[] = {
    {0.5f, 0.5f, 0.3f}, {6.f, -2.f, 1.f}, {3.f, 0.1f, -0.5f}, {40, 3, 2}};
// Receiver normals: none (every side), facing the row, turned away, edge-on.
const float3 kNormals[] = {{0, 0, 0}, {0, 0, -1}, {0, 0.6f, 0.8f}, {1, 0, 0}};

TEST(LightTree, ProbabilitiesSumToOneAndAreWhatPickChoosesWith)
{
  // One leaf (up to 16), one level of nodes, and several.
  for (int count : {1, 2, 7, 16, 17, 70, 300})
    for (const float3 &normal : kNormals) {
      light::LightTree tree;
      tree.build(emittersOf(triangleRow(count)));
      for (const float3 &point : kPoints) {
        double sum = 0.0;
        for (int i = 0; i < count; i++) {
          const float p = tree.probability(point, normal, uint32_t(i));
          EXPECT_GT(p, 0.f) << "every emitter that can light the point";
          sum += p;
        }
        EXPECT_NEAR(sum, 1.0, 1e-5) << count << " emitters";
        // Counting: the frequency of each choice over stratified u.
        const int n = count > 16 ? 400000 : 100000;
        std::vector<int> chosen(size_t(count), 0);
        for (int k = 0; k < n; k++) {
          float u = (k + 0.5f) / n, probability = 0.f;
          const uint32_t e = tree.pick(point, normal, u, probability);
          ASSERT_LT(e, uint32_t(count));
          EXPECT_GE(u, 0.f);
          EXPECT_LT(u, 1.f);
          EXPECT_FLOAT_EQ(probability, tree.probability(point, normal, e));
          chosen[e]++;
        }
        for (int i = 0; i < count; i++)
          EXPECT_NEAR(double(chosen[size_t(i)]) / n,
              tree.probability(point, normal, uint32_t(i)),
              2e-4)
              << "emitter " << i << " of " << count;
      }
    }
}

TEST(LightTree, PrefersNearEmitters)
{
  // Sixteen unit triangles just below the point and sixteen equal ones
  // far off (a leaf's worth each).
  std::vector<float3> corners;
  for (int i = 0; i < 32; i++) {
    const float x = float(i % 16) * 0.25f + (i < 16 ? 0.f : 50.f);
    for (float3 c : {float3{x, 0, 0}, float3{x + 1, 0, 0}, float3{x, 1, 0}})
      corners.push_back(c);
  }
  light::LightTree tree;
  tree.build(emittersOf(corners));
  const float3 point{1.5f, 0.3f, 1.f}, none{0.f, 0.f, 0.f};
  float near = 0.f;
  for (uint32_t i = 0; i < 16; i++)
    near += tree.probability(point, none, i);
  EXPECT_GT(near, 0.99f);
  for (uint32_t i = 16; i < 32; i++) {
    EXPECT_GT(tree.probability(point, none, i), 0.f);
    EXPECT_LT(tree.probability(point, none, i), 0.01f);
  }
}

TEST(LightTree, PrefersEmittersAboveTheReceiversHorizon)
{
  // Two walls of 64 emitters each, at x = -4 and x = +4, facing the
  // receiver between them. A receiver facing +x takes light only from the
  // wall at +4: the tree gives that wall nearly all its choices, and
  // every emitter of the other a share still above zero.
  std::vector<float3> corners;
  for (float wall : {-4.f, 4.f})
    for (int i = 0; i < 64; i++) {
      const float y = float(i % 8) * 0.25f - 1.f,
                  z = float(i / 8) * 0.25f - 1.f;
      for (float3 c : {float3{wall, y, z},
               float3{wall, y + 0.2f, z},
               float3{wall, y, z + 0.2f}})
        corners.push_back(c);
    }
  light::LightTree tree;
  tree.build(emittersOf(corners));
  const float3 point{0.f, 0.f, 0.f};
  float facing = 0.f, evenly = 0.f;
  for (uint32_t i = 64; i < 128; i++) {
    facing += tree.probability(point, {1.f, 0.f, 0.f}, i);
    evenly += tree.probability(point, {0.f, 0.f, 0.f}, i);
  }
  EXPECT_NEAR(evenly, 0.5f, 0.02f) << "without a normal, both walls alike";
  EXPECT_GT(facing, 0.99f);
  for (uint32_t i = 0; i < 64; i++)
    EXPECT_GT(tree.probability(point, {1.f, 0.f, 0.f}, i), 0.f);
}

TEST(LightTree, LeftoverNumberIsUniform)
{
  // What pick() leaves of u is uniform: its mean and variance over
  // stratified u are those of U[0,1) for each emitter.
  // Within a leaf (5 emitters) and through nodes (40): each emitter
  // chosen often enough to tell.
  for (int emitters : {5, 40}) {
    light::LightTree tree;
    tree.build(emittersOf(triangleRow(emitters)));
    const int n = 400000;
    const float3 point{20.f, 0.5f, 40.f}, normal{0.f, 0.f, -1.f};
    std::vector<double> sum(size_t(emitters), 0.0), sum2 = sum, count = sum;
    for (int k = 0; k < n; k++) {
      float u = (k + 0.5f) / n, probability = 0.f;
      const uint32_t e = tree.pick(point, normal, u, probability);
      sum[e] += u, sum2[e] += double(u) * u, count[e] += 1.0;
    }
    for (size_t e = 0; e < size_t(emitters); e++) {
      ASSERT_GT(count[e], 300.0) << e << " of " << emitters;
      EXPECT_NEAR(sum[e] / count[e], 0.5, 0.01);
      EXPECT_NEAR(sum2[e] / count[e], 1.0 / 3.0, 0.01);
    }
  }
}

// Irradiance at `point` (normal +z) from a Lambertian polygon of radiance
// `radiance` above it: Lambert's formula, L/2 times the sum over edges of
// the angle they subtend times the cosine of their plane's normal with +z.
double lambertIrradiance(
    const std::vector<float3> &polygon, const float3 &point, double radiance)
{
  double sum = 0.0;
  for (size_t i = 0; i < polygon.size(); i++) {
    const float3 a = normalize(polygon[i] - point);
    const float3 b = normalize(polygon[(i + 1) % polygon.size()] - point);
    const double angle = std::acos(std::clamp(double(dot(a, b)), -1.0, 1.0));
    sum += angle * double(normalize(cross(a, b)).z);
  }
  return 0.5 * radiance * std::abs(sum);
}

// Monte Carlo irradiance at `point` (normal +z) with next-event samples
// of `light` chosen for a receiver facing `normal`: the mean of
// L cos / pdf over stratified, jittered samples.
double sampledIrradiance(
    const EmissiveSurface &light, const float3 &point, const float3 &normal)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<float> jitter(0.f, 1.f);
  const int n = 400;
  double sum = 0.0;
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++) {
      const float2 u{std::min((i + jitter(random)) / n, 0.99999994f),
          std::min((j + jitter(random)) / n, 0.99999994f)};
      const LightSample s = light.sampleFacing(point, normal, u);
      if (s.pdf > 0.f && s.direction.z > 0.f)
        sum += double(s.radiance.x) * s.direction.z / s.pdf;
    }
  return sum / (double(n) * n);
}

TEST(EmissiveSurface, IrradianceMatchesLambertsFormula)
{
  // A 2x2 square at z = 1 split into 8x8 cells of two triangles each,
  // radiance 3: near (solid-angle sampling of the big cells' triangles
  // under the point), off to the side and far (by area).
  const std::vector<float3> corners =
      test::squareOfCells(-1.f, -1.f, 2.f, 1.f, 8);
  const std::vector<float3> square = {
      {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  EmitterShape mesh;
  mesh.triangles = corners;
  EmitterShape two;
  two.triangles = {
      {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  for (const EmitterShape *shape : {&mesh, &two}) {
    const EmissiveSurface light(*shape, {3.f, 3.f, 3.f});
    for (const float3 point : {float3{0.1f, 0.2f, 0.7f},
             float3{0.f, 0.f, 0.05f},
             float3{1.5f, -0.5f, 0.4f},
             float3{3.f, 2.f, -6.f}}) {
      const double expected = lambertIrradiance(square, point, 3.0);
      // 0.5 %: several standard errors of 160,000 stratified samples;
      // with the receiver's normal (+z, the side the square is on) or
      // without, the estimate is the same.
      for (const float3 normal : {float3{0, 0, 0}, float3{0, 0, 1}})
        EXPECT_NEAR(
            sampledIrradiance(light, point, normal), expected, 5e-3 * expected)
            << "at " << point.x << ", " << point.y << ", " << point.z
            << " with " << shape->triangles.size() / 3 << " triangles, normal "
            << normal.z;
    }
  }
}

} // namespace
} // namespace prism
