#include "PolygonTriangulation.h"

#include <cmath>
#include <list>

namespace prism::nsi {

namespace {

// Ear clipping costs O(n^2) per polygon and more; past this a fan it is.
constexpr size_t kMaxEarClippedCorners = 4096;

struct Point2
{
  double x, y;
};

double cross(Point2 a, Point2 b, Point2 c)
{
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool insideOrOnTriangle(Point2 p, Point2 a, Point2 b, Point2 c)
{
  return cross(a, b, p) >= 0 && cross(b, c, p) >= 0 && cross(c, a, p) >= 0;
}

std::vector<std::array<uint32_t, 3>> fan(size_t n)
{
  std::vector<std::array<uint32_t, 3>> out;
  for (size_t i = 1; i + 1 < n; ++i)
    out.push_back({0, uint32_t(i), uint32_t(i + 1)});
  return out;
}

} // namespace

std::vector<std::array<uint32_t, 3>> triangulatePolygon(
    const std::vector<std::array<double, 3>> &corners)
{
  const size_t n = corners.size();
  if (n < 3)
    return {};
  if (n == 3 || n > kMaxEarClippedCorners)
    return fan(n);

  // Newell's normal: robust for non-convex and slightly bent polygons.
  std::array<double, 3> normal{0, 0, 0};
  for (size_t i = 0; i < n; ++i) {
    const auto &a = corners[i];
    const auto &b = corners[(i + 1) % n];
    normal[0] += (a[1] - b[1]) * (a[2] + b[2]);
    normal[1] += (a[2] - b[2]) * (a[0] + b[0]);
    normal[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(normal[k]) > std::abs(normal[axis]))
      axis = k;
  }
  if (normal[axis] == 0)
    return fan(n);
  // Project along `axis`, ordered so the polygon runs counter-clockwise.
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const double flip = normal[axis] > 0 ? 1.0 : -1.0;
  std::vector<Point2> points(n);
  for (size_t i = 0; i < n; ++i)
    points[i] = {corners[i][u], flip * corners[i][v]};

  std::list<uint32_t> remaining;
  for (size_t i = 0; i < n; ++i)
    remaining.push_back(uint32_t(i));
  std::vector<std::array<uint32_t, 3>> out;
  auto next = [&](std::list<uint32_t>::iterator it) {
    return ++it == remaining.end() ? remaining.begin() : it;
  };
  auto previous = [&](std::list<uint32_t>::iterator it) {
    return it == remaining.begin() ? std::prev(remaining.end()) : std::prev(it);
  };
  auto it = remaining.begin();
  size_t sinceLastEar = 0;
  while (remaining.size() > 3) {
    const uint32_t a = *previous(it), b = *it, c = *next(it);
    bool ear = cross(points[a], points[b], points[c]) > 0;
    for (uint32_t p : remaining) {
      if (!ear)
        break;
      if (p == a || p == b || p == c)
        continue;
      const Point2 q = points[p];
      const bool atCorner = (q.x == points[a].x && q.y == points[a].y)
                            || (q.x == points[c].x && q.y == points[c].y);
      if (!atCorner && insideOrOnTriangle(q, points[a], points[b], points[c]))
        ear = false;
    }
    // A whole round without an ear: the rest is degenerate; clip anyway.
    if (ear || sinceLastEar > remaining.size()) {
      out.push_back({a, b, c});
      auto after = remaining.erase(it);
      if (after == remaining.end())
        after = remaining.begin();
      // Go on from `a`, whose angle the clip changed.
      it = previous(after);
      sinceLastEar = 0;
    } else {
      it = next(it);
      ++sinceLastEar;
    }
  }
  auto last = remaining.begin();
  const uint32_t a = *last++, b = *last++, c = *last;
  out.push_back({a, b, c});
  return out;
}

} // namespace prism::nsi
