// Generated tangents (the MikkTSpace method) on meshes with known answers.
// glTF's v runs down the image and a normal map's +Y up it, so the
// bitangent cross(N, T) * w points along decreasing v: w is -1 where the
// uv mapping keeps the surface's orientation, +1 where it mirrors it (as
// the tangents glTF exporters write with MikkTSpace; see
// cli::tangents::generated-match-mikktspace for a real file's).
#include "TangentGeneration.h"

#include <gtest/gtest.h>

#include <cmath>

namespace prism::scene_io {
namespace {

// A grid of n x n quads over [-1, 1]^2 in z = 0, normals +z, uv from `uv`.
struct Grid
{
  std::vector<Vec3> positions, normals;
  std::vector<Vec2> uvs;
  std::vector<std::array<uint32_t, 3>> triangles;
};

template <typename UvOf>
Grid grid(int n, UvOf uvOf)
{
  Grid g;
  for (int y = 0; y <= n; y++) {
    for (int x = 0; x <= n; x++) {
      const float px = -1.f + 2.f * float(x) / float(n);
      const float py = -1.f + 2.f * float(y) / float(n);
      g.positions.push_back({px, py, 0.f});
      g.normals.push_back({0.f, 0.f, 1.f});
      g.uvs.push_back(uvOf(px, py));
    }
  }
  auto at = [n](int x, int y) {
    return uint32_t(y * (n + 1) + x);
  };
  for (int y = 0; y < n; y++) {
    for (int x = 0; x < n; x++) {
      g.triangles.push_back({at(x, y), at(x + 1, y), at(x + 1, y + 1)});
      g.triangles.push_back({at(x, y), at(x + 1, y + 1), at(x, y + 1)});
    }
  }
  return g;
}

void expectTangent(const Vec4 &t, const Vec4 &expected, const char *what)
{
  for (int i = 0; i < 4; i++)
    EXPECT_NEAR(t[i], expected[i], 1e-5f) << what << " component " << i;
}

TEST(TangentGeneration, PlaneTangentsFollowIncreasingU)
{
  // u along +x, v along +y: the tangent is +x, the bitangent -y (up the
  // image).
  Grid g = grid(3, [](float x, float y) { return Vec2{x, y}; });
  for (const Vec4 &t :
      generateTangents(g.positions, g.normals, g.uvs, g.triangles))
    expectTangent(t, {1, 0, 0, -1}, "plane");
  // u along +y, v along -x (rotated UVs): the tangent is +y.
  g = grid(3, [](float x, float y) { return Vec2{y, -x}; });
  for (const Vec4 &t :
      generateTangents(g.positions, g.normals, g.uvs, g.triangles))
    expectTangent(t, {0, 1, 0, -1}, "rotated");
}

TEST(TangentGeneration, MirroredIslandsSplitAtTheSeam)
{
  // u = |x|: the left half is mirrored. Seam vertices (x = 0) are shared by
  // both halves with the same uv, yet each half keeps its own tangent.
  Grid g = grid(4, [](float x, float y) { return Vec2{std::abs(x), y}; });
  const auto tangents =
      generateTangents(g.positions, g.normals, g.uvs, g.triangles);
  for (size_t c = 0; c < tangents.size(); c++) {
    const auto &tri = g.triangles[c / 3];
    float cx = 0;
    for (uint32_t v : tri)
      cx += g.positions[v][0] / 3.f;
    if (cx < 0.f)
      expectTangent(tangents[c], {-1, 0, 0, 1}, "mirrored half");
    else
      expectTangent(tangents[c], {1, 0, 0, -1}, "unmirrored half");
  }
}

TEST(TangentGeneration, CurvedSurfaceTangentsAreUnitAndPerpendicular)
{
  // A cylinder strip: normals vary, tangents must stay in each corner's
  // normal plane, unit length, and smooth across shared vertices.
  Grid g = grid(8, [](float x, float y) { return Vec2{x, y}; });
  for (size_t i = 0; i < g.positions.size(); i++) {
    const float a = g.positions[i][0];
    g.positions[i] = {std::sin(a), g.positions[i][1], std::cos(a)};
    g.normals[i] = {std::sin(a), 0.f, std::cos(a)};
  }
  const auto tangents =
      generateTangents(g.positions, g.normals, g.uvs, g.triangles);
  std::vector<Vec4> perVertex(g.positions.size(), Vec4{0, 0, 0, 0});
  for (size_t c = 0; c < tangents.size(); c++) {
    const Vec4 &t = tangents[c];
    const Vec3 &n = g.normals[g.triangles[c / 3][c % 3]];
    EXPECT_NEAR(t[0] * t[0] + t[1] * t[1] + t[2] * t[2], 1.f, 1e-5f);
    EXPECT_NEAR(t[0] * n[0] + t[1] * n[1] + t[2] * n[2], 0.f, 1e-5f);
    EXPECT_EQ(t[3], -1.f);
    // Around the cylinder: the tangent is the circle's direction.
    const uint32_t v = g.triangles[c / 3][c % 3];
    const float a = std::atan2(g.positions[v][0], g.positions[v][2]);
    expectTangent(t, {std::cos(a), 0.f, -std::sin(a), -1.f}, "cylinder");
    Vec4 &seen = perVertex[v];
    if (seen[3] != 0.f)
      expectTangent(t, seen, "shared vertex");
    seen = t;
  }
}

TEST(TangentGeneration, DegenerateUvsStillGiveAPerpendicularTangent)
{
  Grid g = grid(1, [](float, float) { return Vec2{0.5f, 0.5f}; });
  for (const Vec4 &t :
      generateTangents(g.positions, g.normals, g.uvs, g.triangles)) {
    EXPECT_NEAR(t[0] * t[0] + t[1] * t[1] + t[2] * t[2], 1.f, 1e-5f);
    EXPECT_NEAR(t[2], 0.f, 1e-6f);
    EXPECT_TRUE(std::abs(t[3]) == 1.f);
  }
}

} // namespace
} // namespace prism::scene_io
