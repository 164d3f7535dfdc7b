// Ear clipping: every polygon becomes n - 2 triangles that keep its winding
// and cover exactly its area, concave ones included.
#include "PolygonTriangulation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

using prism::nsi::triangulatePolygon;
using Corners = std::vector<std::array<double, 3>>;

// Signed area in the z = 0 plane (positive: counter-clockwise).
double signedArea(const std::array<double, 3> &a,
    const std::array<double, 3> &b,
    const std::array<double, 3> &c)
{
  return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

double polygonArea(const Corners &p)
{
  double area = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    const auto &a = p[i], &b = p[(i + 1) % p.size()];
    area += 0.5 * (a[0] * b[1] - b[0] * a[1]);
  }
  return area;
}

void expectCovers(const Corners &polygon)
{
  const auto triangles = triangulatePolygon(polygon);
  ASSERT_EQ(triangles.size(), polygon.size() - 2);
  double total = 0;
  const double sign = polygonArea(polygon) > 0 ? 1 : -1;
  for (auto [a, b, c] : triangles) {
    ASSERT_LT(a, polygon.size());
    ASSERT_LT(b, polygon.size());
    ASSERT_LT(c, polygon.size());
    const double area = signedArea(polygon[a], polygon[b], polygon[c]);
    EXPECT_GT(area * sign, 0) << "a triangle turned over";
    total += area;
  }
  // Same winding everywhere and the same total: no overlap, no gap.
  EXPECT_NEAR(total, polygonArea(polygon), 1e-9);
}

TEST(PolygonTriangulation, Square)
{
  expectCovers({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
}

TEST(PolygonTriangulation, ConcaveLShapeBothWindings)
{
  Corners l{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
  expectCovers(l);
  // Starting at the reflex corner, where a fan would go wrong.
  std::rotate(l.begin(), l.begin() + 3, l.end());
  expectCovers(l);
  std::reverse(l.begin(), l.end());
  expectCovers(l);
}

TEST(PolygonTriangulation, StarWithManyReflexCorners)
{
  Corners star;
  for (int i = 0; i < 16; ++i) {
    const double angle = i * M_PI / 8, radius = i % 2 ? 0.4 : 1.0;
    star.push_back({radius * std::cos(angle), radius * std::sin(angle), 0});
  }
  expectCovers(star);
}

TEST(PolygonTriangulation, TiltedPolygonsUseTheirOwnPlane)
{
  // The L in the x = z plane: triangles counted by projection onto y/z.
  const auto triangles = triangulatePolygon(
      {{0, 0, 0}, {2, 0, 2}, {2, 1, 2}, {1, 1, 1}, {1, 2, 1}, {0, 2, 0}});
  EXPECT_EQ(triangles.size(), 4u);
}

TEST(PolygonTriangulation, DegenerateInputStillEnds)
{
  EXPECT_TRUE(triangulatePolygon({{0, 0, 0}, {1, 1, 1}}).empty());
  EXPECT_EQ(
      triangulatePolygon({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}).size(),
      2u);
  EXPECT_EQ(triangulatePolygon(
                {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}})
                .size(),
      3u);
  // A bow tie crosses itself: triangles come out, whatever they are.
  EXPECT_EQ(
      triangulatePolygon({{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}}).size(),
      2u);
}

// The loops' corners numbered through, as triangulatePolygonWithHoles does.
Corners flatten(const std::vector<Corners> &loops)
{
  Corners all;
  for (auto &loop : loops)
    all.insert(all.end(), loop.begin(), loop.end());
  return all;
}

// Triangles keep the outline's winding, cover its area less the holes', and
// none has its centre in a hole.
void expectCoversWithHoles(
    const std::vector<Corners> &loops, size_t expectedTriangles)
{
  const auto triangles = prism::nsi::triangulatePolygonWithHoles(loops);
  const Corners all = flatten(loops);
  ASSERT_EQ(triangles.size(), expectedTriangles);
  double area = std::abs(polygonArea(loops[0]));
  for (size_t h = 1; h < loops.size(); ++h)
    area -= std::abs(polygonArea(loops[h]));
  const double sign = polygonArea(loops[0]) > 0 ? 1 : -1;
  double total = 0;
  for (auto [a, b, c] : triangles) {
    ASSERT_LT(std::max({a, b, c}), all.size());
    const double t = signedArea(all[a], all[b], all[c]);
    EXPECT_GE(t * sign, 0) << "a triangle turned over";
    total += std::abs(t);
    const double cx = (all[a][0] + all[b][0] + all[c][0]) / 3;
    const double cy = (all[a][1] + all[b][1] + all[c][1]) / 3;
    for (size_t h = 1; h < loops.size(); ++h) {
      double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
      for (auto &p : loops[h]) {
        x0 = std::min(x0, p[0]);
        x1 = std::max(x1, p[0]);
        y0 = std::min(y0, p[1]);
        y1 = std::max(y1, p[1]);
      }
      EXPECT_FALSE(cx > x0 && cx < x1 && cy > y0 && cy < y1)
          << "a triangle fills hole " << h;
    }
  }
  EXPECT_NEAR(total, area, 1e-9);
}

TEST(PolygonTriangulation, SquareWithASquareHole)
{
  const Corners outline{{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}};
  // Clockwise as NSI writes holes, and counter-clockwise: both work.
  Corners hole{{1, 1, 0}, {1, 3, 0}, {3, 3, 0}, {3, 1, 0}};
  expectCoversWithHoles({outline, hole}, 8);
  std::reverse(hole.begin(), hole.end());
  expectCoversWithHoles({outline, hole}, 8);
}

TEST(PolygonTriangulation, TwoHolesSideBySide)
{
  const Corners outline{{0, 0, 0}, {10, 0, 0}, {10, 4, 0}, {0, 4, 0}};
  const Corners left{{1, 1, 0}, {1, 3, 0}, {3, 3, 0}, {3, 1, 0}};
  const Corners right{{6, 1, 0}, {6, 3, 0}, {8, 2, 0}};
  // n + 2 h - 2 triangles: 11 corners, 2 holes: 13.
  expectCoversWithHoles({outline, left, right}, 13);
}

// The NSI spec's Listing 3.1, second face: two square holes in a row, wound
// as the outline is; each hole's rightmost corners and the other hole's
// leftmost ones lie on the same lines, so the bridges run along edges.
TEST(PolygonTriangulation, SpecListingTwoSquareHoles)
{
  const Corners outline{{4, 0, 0}, {9, 0, 0}, {9, 3, 0}, {4, 3, 0}};
  const Corners left{{5, 1, 0}, {6, 1, 0}, {6, 2, 0}, {5, 2, 0}};
  const Corners right{{7, 1, 0}, {8, 1, 0}, {8, 2, 0}, {7, 2, 0}};
  expectCoversWithHoles({outline, left, right}, 14);
}

} // namespace
