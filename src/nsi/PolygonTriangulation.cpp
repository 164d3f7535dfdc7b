#include "PolygonTriangulation.h"

#include <algorithm>
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

bool samePoint(Point2 a, Point2 b)
{
  return a.x == b.x && a.y == b.y;
}

std::vector<std::array<uint32_t, 3>> fan(size_t n)
{
  std::vector<std::array<uint32_t, 3>> out;
  for (size_t i = 1; i + 1 < n; ++i)
    out.push_back({0, uint32_t(i), uint32_t(i + 1)});
  return out;
}

// Newell's normal: robust for non-convex and slightly bent polygons.
Corner newellNormal(const std::vector<Corner> &loop)
{
  Corner normal{0, 0, 0};
  for (size_t i = 0; i < loop.size(); ++i) {
    const auto &a = loop[i];
    const auto &b = loop[(i + 1) % loop.size()];
    normal[0] += (a[1] - b[1]) * (a[2] + b[2]);
    normal[1] += (a[2] - b[2]) * (a[0] + b[0]);
    normal[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  return normal;
}

double signedArea(
    const std::vector<Point2> &points, const std::vector<uint32_t> &loop)
{
  double area = 0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const Point2 a = points[loop[i]], b = points[loop[(i + 1) % loop.size()]];
    area += a.x * b.y - b.x * a.y;
  }
  return area / 2;
}

// Ear clipping of `sequence` (indices into `points`, counter-clockwise; an
// index may repeat where a hole is bridged in).
std::vector<std::array<uint32_t, 3>> clipEars(
    const std::vector<Point2> &points, const std::vector<uint32_t> &sequence)
{
  std::list<uint32_t> remaining(sequence.begin(), sequence.end());
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
    const Point2 pa = points[a], pb = points[b], pc = points[c];
    bool ear = cross(pa, pb, pc) > 0;
    for (uint32_t p : remaining) {
      if (!ear)
        break;
      const Point2 q = points[p];
      // Corners of the ear itself, and their copies along a bridge, are
      // not in the way.
      if (samePoint(q, pa) || samePoint(q, pb) || samePoint(q, pc))
        continue;
      if (insideOrOnTriangle(q, pa, pb, pc))
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

// Splices `hole` (clockwise) into `outline` (counter-clockwise) through a
// bridge from the hole's rightmost corner to an outline corner it sees.
void bridgeHole(const std::vector<Point2> &points,
    std::vector<uint32_t> &outline,
    std::vector<uint32_t> hole)
{
  const auto rightmost = std::max_element(hole.begin(),
      hole.end(),
      [&](uint32_t a, uint32_t b) { return points[a].x < points[b].x; });
  std::rotate(hole.begin(), rightmost, hole.end());
  const Point2 m = points[hole.front()];

  // The nearest outline edge crossed by the ray from m towards +x.
  double nearestX = INFINITY;
  size_t edge = outline.size();
  for (size_t i = 0; i < outline.size(); ++i) {
    const Point2 a = points[outline[i]];
    const Point2 b = points[outline[(i + 1) % outline.size()]];
    if ((a.y > m.y) == (b.y > m.y))
      continue;
    const double x = a.x + (m.y - a.y) * (b.x - a.x) / (b.y - a.y);
    if (x >= m.x && x < nearestX) {
      nearestX = x;
      edge = i;
    }
  }
  size_t target = 0;
  if (edge == outline.size()) {
    // No crossing (a hole outside its outline): bridge to the nearest corner.
    double best = INFINITY;
    for (size_t i = 0; i < outline.size(); ++i) {
      const Point2 p = points[outline[i]];
      const double d = (p.x - m.x) * (p.x - m.x) + (p.y - m.y) * (p.y - m.y);
      if (d < best) {
        best = d;
        target = i;
      }
    }
  } else {
    // The crossed edge's end further right, unless an outline corner lies
    // inside the triangle (m, crossing, that end): then the one of those
    // closest in angle to the ray, which m certainly sees; of corners at
    // the same angle (on one line with m, as when holes sit in a row) the
    // nearest, so the bridge does not run along another hole's edge.
    const size_t end = (edge + 1) % outline.size();
    target = points[outline[edge]].x > points[outline[end]].x ? edge : end;
    const Point2 crossing{nearestX, m.y};
    const Point2 p = points[outline[target]];
    double bestAngle = INFINITY, bestDistance = INFINITY;
    for (size_t i = 0; i < outline.size(); ++i) {
      const Point2 q = points[outline[i]];
      if (i == target || samePoint(q, p))
        continue;
      const bool inside = p.y > m.y ? insideOrOnTriangle(q, m, crossing, p)
                                    : insideOrOnTriangle(q, m, p, crossing);
      if (!inside)
        continue;
      const double angle = std::atan2(std::abs(q.y - m.y), q.x - m.x);
      const double distance = std::hypot(q.x - m.x, q.y - m.y);
      if (angle < bestAngle
          || (angle == bestAngle && distance < bestDistance)) {
        bestAngle = angle;
        bestDistance = distance;
        target = i;
      }
    }
  }
  // outline[..target], hole from m round to m, m again, outline[target..].
  std::vector<uint32_t> merged(outline.begin(), outline.begin() + target + 1);
  merged.insert(merged.end(), hole.begin(), hole.end());
  merged.push_back(hole.front());
  merged.insert(merged.end(), outline.begin() + target, outline.end());
  outline = std::move(merged);
}

} // namespace

std::vector<std::array<uint32_t, 3>> triangulatePolygon(
    const std::vector<Corner> &corners)
{
  return triangulatePolygonWithHoles({corners});
}

std::vector<std::array<uint32_t, 3>> triangulatePolygonWithHoles(
    const std::vector<std::vector<Corner>> &loops)
{
  if (loops.empty())
    return {};
  const size_t n = loops[0].size();
  size_t total = 0;
  for (auto &loop : loops)
    total += loop.size();
  if (n < 3)
    return {};
  const bool holes = total > n;
  if ((n == 3 && !holes) || total > kMaxEarClippedCorners)
    return fan(n);

  const Corner normal = newellNormal(loops[0]);
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(normal[k]) > std::abs(normal[axis]))
      axis = k;
  }
  if (normal[axis] == 0)
    return fan(n);
  // Project along `axis`, ordered so the outline runs counter-clockwise.
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const double flip = normal[axis] > 0 ? 1.0 : -1.0;
  std::vector<Point2> points;
  std::vector<std::vector<uint32_t>> indexLoops;
  for (auto &loop : loops) {
    std::vector<uint32_t> indices;
    for (auto &corner : loop) {
      indices.push_back(uint32_t(points.size()));
      points.push_back({corner[u], flip * corner[v]});
    }
    indexLoops.push_back(std::move(indices));
  }
  std::vector<uint32_t> outline = indexLoops[0];
  // Holes clockwise, bridged in from the rightmost one leftwards, so each
  // bridge meets the outline as it stands.
  std::vector<std::vector<uint32_t>> holeLoops;
  for (size_t h = 1; h < indexLoops.size(); ++h) {
    if (indexLoops[h].size() < 3)
      continue;
    if (signedArea(points, indexLoops[h]) > 0)
      std::reverse(indexLoops[h].begin(), indexLoops[h].end());
    holeLoops.push_back(indexLoops[h]);
  }
  auto maxX = [&](const std::vector<uint32_t> &loop) {
    double x = -INFINITY;
    for (uint32_t i : loop)
      x = std::max(x, points[i].x);
    return x;
  };
  std::sort(holeLoops.begin(),
      holeLoops.end(),
      [&](const auto &a, const auto &b) { return maxX(a) > maxX(b); });
  for (auto &hole : holeLoops)
    bridgeHole(points, outline, hole);
  return clipEars(points, outline);
}

} // namespace prism::nsi
