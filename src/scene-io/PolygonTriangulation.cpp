#include "PolygonTriangulation.h"

#include <algorithm>
#include <cmath>

namespace prism::scene_io {
namespace {

struct Point2
{
  double x, y;
};

using Triangles = std::vector<std::array<uint32_t, 3>>;

// Twice the signed area of (a, b, c): positive when they turn left.
double turn(const Point2 &a, const Point2 &b, const Point2 &c)
{
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

void fan(size_t n, Triangles &out)
{
  for (size_t i = 1; i + 1 < n; i++)
    out.push_back({0u, uint32_t(i), uint32_t(i + 1)});
}

// The corners in the plane most facing the polygon's Newell normal, mirrored
// if needed so the polygon winds counter-clockwise there. False when the
// polygon has no area (every corner on one line). Doubles: float coordinates
// up to 3.4e38 square without overflow.
bool projectCounterClockwise(
    const std::vector<std::array<float, 3>> &corners, std::vector<Point2> &out)
{
  const size_t n = corners.size();
  double normal[3] = {0.0, 0.0, 0.0};
  for (size_t i = 0; i < n; i++) {
    const auto &a = corners[i];
    const auto &b = corners[(i + 1) % n];
    normal[0] += (double(a[1]) - b[1]) * (double(a[2]) + b[2]);
    normal[1] += (double(a[2]) - b[2]) * (double(a[0]) + b[0]);
    normal[2] += (double(a[0]) - b[0]) * (double(a[1]) + b[1]);
  }
  int axis = 0;
  for (int k = 1; k < 3; k++)
    if (std::fabs(normal[k]) > std::fabs(normal[axis]))
      axis = k;
  if (!(std::fabs(normal[axis]) > 0.0) || !std::isfinite(normal[axis]))
    return false;
  // normal[axis] is twice the polygon's area in the plane of the two other
  // axes taken in cyclic order (y z, z x or x y).
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const double mirror = normal[axis] > 0.0 ? 1.0 : -1.0;
  out.resize(n);
  for (size_t i = 0; i < n; i++)
    out[i] = {mirror * corners[i][size_t(u)], corners[i][size_t(v)]};
  return true;
}

// Convex: no corner dents inwards by more than a tolerance relative to the
// polygon's size (so points on a curve, rounded to the file's decimals, still
// count), and the outline winds around once, which with no right turns means
// the edges' x direction changes sign at most twice.
bool isConvex(const std::vector<Point2> &p)
{
  const size_t n = p.size();
  Point2 lower = p[0], upper = p[0];
  for (const Point2 &q : p) {
    lower = {std::min(lower.x, q.x), std::min(lower.y, q.y)};
    upper = {std::max(upper.x, q.x), std::max(upper.y, q.y)};
  }
  const double tolerance =
      1e-5 * std::hypot(upper.x - lower.x, upper.y - lower.y);
  int xSignChanges = 0;
  int firstSign = 0, lastSign = 0;
  for (size_t i = 0; i < n; i++) {
    const Point2 &a = p[(i + n - 1) % n];
    const Point2 &b = p[i];
    const Point2 &c = p[(i + 1) % n];
    // turn = |c - a| * (how far b lies right of the line a -> c)
    if (turn(a, b, c) < -tolerance * std::hypot(c.x - a.x, c.y - a.y))
      return false;
    const double dx = c.x - b.x;
    const int sign = dx > 0.0 ? 1 : dx < 0.0 ? -1 : 0;
    if (sign == 0)
      continue;
    if (firstSign == 0)
      firstSign = sign;
    else if (sign != lastSign)
      xSignChanges++;
    lastSign = sign;
  }
  if (lastSign != 0 && lastSign != firstSign)
    xSignChanges++;
  return xSignChanges <= 2;
}

// Ear clipping over a ring of corners. Only reflex corners can lie inside an
// ear, so each ear test scans the reflex list; clipping an ear changes the
// status of its two neighbours only, so the whole run is O(n * reflex).
class EarClipper
{
 public:
  explicit EarClipper(const std::vector<Point2> &p)
      : m_p(p),
        m_prev(p.size()),
        m_next(p.size()),
        m_reflex(p.size()),
        m_ear(p.size()),
        m_removed(p.size(), 0)
  {
    const size_t n = p.size();
    for (size_t i = 0; i < n; i++) {
      m_prev[i] = uint32_t((i + n - 1) % n);
      m_next[i] = uint32_t((i + 1) % n);
    }
    for (uint32_t i = 0; i < n; i++) {
      m_reflex[i] = isReflex(i);
      if (m_reflex[i])
        m_reflexList.push_back(i);
    }
    for (uint32_t i = 0; i < n; i++) {
      m_ear[i] = isEar(i);
      if (m_ear[i])
        m_candidates.push_back(i);
    }
  }

  void run(Triangles &out)
  {
    size_t remaining = m_p.size();
    uint32_t any = 0;
    while (remaining > 3) {
      uint32_t corner;
      if (!m_candidates.empty()) {
        corner = m_candidates.back();
        m_candidates.pop_back();
        if (m_removed[corner] || !m_ear[corner])
          continue;
      } else {
        // No ear left: the outline crosses itself (or rounding hides the
        // ears). Clip a corner anyway so every corner is still covered.
        while (m_removed[any])
          any++;
        corner = any;
      }
      const uint32_t a = m_prev[corner], b = m_next[corner];
      out.push_back({a, corner, b});
      m_removed[corner] = 1;
      m_next[a] = b;
      m_prev[b] = a;
      remaining--;
      for (uint32_t neighbour : {a, b}) {
        const bool wasReflex = m_reflex[neighbour];
        m_reflex[neighbour] = isReflex(neighbour);
        if (m_reflex[neighbour] && !wasReflex)
          m_reflexList.push_back(neighbour);
        m_ear[neighbour] = isEar(neighbour);
        if (m_ear[neighbour])
          m_candidates.push_back(neighbour);
      }
    }
    while (m_removed[any])
      any++;
    out.push_back({m_prev[any], any, m_next[any]});
  }

 private:
  bool isReflex(uint32_t i) const
  {
    return turn(m_p[m_prev[i]], m_p[i], m_p[m_next[i]]) < 0.0;
  }

  bool isEar(uint32_t i)
  {
    if (m_reflex[i])
      return false;
    const Point2 &a = m_p[m_prev[i]], &b = m_p[i], &c = m_p[m_next[i]];
    auto same = [](const Point2 &p, const Point2 &q) {
      return p.x == q.x && p.y == q.y;
    };
    // Drops entries that were removed or stopped being reflex on the way.
    size_t kept = 0;
    bool ear = true;
    for (size_t k = 0; k < m_reflexList.size(); k++) {
      const uint32_t j = m_reflexList[k];
      if (m_removed[j] || !m_reflex[j])
        continue;
      m_reflexList[kept++] = j;
      if (!ear || j == m_prev[i] || j == m_next[i])
        continue;
      const Point2 &q = m_p[j];
      if (same(q, a) || same(q, b) || same(q, c))
        continue;
      if (turn(a, b, q) >= 0.0 && turn(b, c, q) >= 0.0 && turn(c, a, q) >= 0.0)
        ear = false;
    }
    m_reflexList.resize(kept);
    return ear;
  }

  const std::vector<Point2> &m_p;
  std::vector<uint32_t> m_prev, m_next;
  std::vector<char> m_reflex, m_ear, m_removed;
  std::vector<uint32_t> m_reflexList; // may hold stale and repeated entries
  std::vector<uint32_t> m_candidates;
};

} // namespace

PolygonTriangles triangulatePolygon(
    const std::vector<std::array<float, 3>> &corners)
{
  PolygonTriangles result;
  const size_t n = corners.size();
  if (n < 3)
    return result;
  result.triangles.reserve(n - 2);
  std::vector<Point2> projected;
  if (n == 3 || !projectCounterClockwise(corners, projected)
      || isConvex(projected)) {
    // Triangles, polygons without area and convex polygons.
    fan(n, result.triangles);
    return result;
  }
  if (n > kMaxEarClippingCorners) {
    fan(n, result.triangles);
    result.fannedConcave = true;
    return result;
  }
  EarClipper(projected).run(result.triangles);
  return result;
}

} // namespace prism::scene_io
