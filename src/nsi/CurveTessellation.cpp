#include "CurveTessellation.h"

#include <cmath>

namespace prism::nsi {

namespace {

// Segments per cubic span: smooth enough at the sizes curves are seen.
constexpr int kSegmentsPerSpan = 8;

using Point = std::array<double, 3>;

// The cubic through control points p0..p3 at t in [0, 1].
Point evaluateCubic(bool bspline, const Point *p, double t)
{
  double w[4];
  const double t2 = t * t, t3 = t2 * t;
  if (bspline) {
    w[0] = (1 - t) * (1 - t) * (1 - t) / 6;
    w[1] = (3 * t3 - 6 * t2 + 4) / 6;
    w[2] = (-3 * t3 + 3 * t2 + 3 * t + 1) / 6;
    w[3] = t3 / 6;
  } else { // catmull-rom: passes through p1 and p2
    w[0] = 0.5 * (-t3 + 2 * t2 - t);
    w[1] = 0.5 * (3 * t3 - 5 * t2 + 2);
    w[2] = 0.5 * (-3 * t3 + 4 * t2 + t);
    w[3] = 0.5 * (t3 - t2);
  }
  Point out{0, 0, 0};
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c)
      out[c] += w[i] * p[i][c];
  return out;
}

} // namespace

std::optional<GeometryData> buildCurves(
    const std::string &handle, const Node &curves, const ReportFunction &report)
{
  auto fail = [&](const std::string &why) {
    report(NSIErrWarning, "curves '" + handle + "': " + why + "; not rendered");
    return std::nullopt;
  };
  const Value *pValue = curves.attribute("P");
  const Value *nValue = curves.attribute("nvertices");
  const std::vector<double> points =
      pValue ? pValue->numbers() : std::vector<double>{};
  const std::vector<double> counts =
      nValue ? nValue->numbers() : std::vector<double>{};
  if (points.empty() || points.size() % 3)
    return fail("no 'P'");
  if (counts.empty())
    return fail("no 'nvertices'");
  const size_t pointCount = points.size() / 3;

  // One count for all curves, or one per curve.
  std::vector<size_t> perCurve;
  for (double n : counts) {
    if (!(n >= 2 && n < 1e9 && n == std::floor(n)))
      return fail("'nvertices' holds " + shortNumber(n));
    perCurve.push_back(size_t(n));
  }
  if (perCurve.size() == 1 && pointCount % perCurve[0] == 0)
    perCurve.assign(pointCount / perCurve[0], perCurve[0]);
  size_t total = 0;
  for (size_t n : perCurve)
    total += n;
  if (total != pointCount)
    return fail("'nvertices' adds up to " + std::to_string(total)
                + " but 'P' has " + std::to_string(pointCount));

  const Value *widthValue = curves.attribute("width");
  std::vector<double> widths =
      widthValue ? widthValue->numbers() : std::vector<double>{};
  if (widths.size() != pointCount && widths.size() != 1) {
    if (!widths.empty())
      report(NSIErrWarning,
          "curves '" + handle
              + "': 'width' count matches neither 1 nor 'P'; using 1");
    widths = {1.0};
  }
  auto radiusAt = [&](size_t i) {
    return float(std::abs(widths[widths.size() == 1 ? 0 : i]) / 2);
  };

  std::string basis = curves.type == "linearcurves" ? "linear" : "catmull-rom";
  if (const Value *b = curves.attribute("basis"))
    basis = b->string(basis);
  const bool linear = basis == "linear";
  const bool bspline = basis == "b-spline";
  if (!linear && !bspline && basis != "catmull-rom") {
    report(NSIErrWarning,
        "curves '" + handle + "': basis '" + basis
            + "' is not supported; catmull-rom used");
  }
  const Value *extrapolateValue = curves.attribute("extrapolate");
  const bool extrapolate = extrapolateValue && extrapolateValue->number(0) != 0;

  GeometryData data;
  data.curves = true;
  auto addVertex = [&](const Point &p, float radius) {
    data.positions.insert(
        data.positions.end(), {float(p[0]), float(p[1]), float(p[2])});
    data.radii.push_back(radius);
  };
  size_t first = 0;
  for (size_t n : perCurve) {
    std::vector<Point> control;
    std::vector<float> radii;
    for (size_t i = first; i < first + n; ++i) {
      control.push_back({points[3 * i], points[3 * i + 1], points[3 * i + 2]});
      radii.push_back(radiusAt(i));
    }
    first += n;
    const uint32_t start = uint32_t(data.radii.size());
    if (linear) {
      for (size_t i = 0; i < n; ++i)
        addVertex(control[i], radii[i]);
    } else {
      if (extrapolate) { // mirrored end points: the curve reaches the ends
        Point before, after;
        for (int c = 0; c < 3; ++c) {
          before[c] = 2 * control[0][c] - control[1][c];
          after[c] = 2 * control[n - 1][c] - control[n - 2][c];
        }
        control.insert(control.begin(), before);
        control.push_back(after);
        radii.insert(radii.begin(), radii.front());
        radii.push_back(radii.back());
      }
      if (control.size() < 4) {
        report(NSIErrWarning,
            "curves '" + handle
                + "': a cubic curve with fewer than 4 vertices is skipped");
        continue;
      }
      for (size_t span = 0; span + 3 < control.size(); ++span) {
        for (int k = (span == 0 ? 0 : 1); k <= kSegmentsPerSpan; ++k) {
          const double t = double(k) / kSegmentsPerSpan;
          const float radius =
              float(radii[span + 1] + t * (radii[span + 2] - radii[span + 1]));
          addVertex(evaluateCubic(bspline, &control[span], t), radius);
        }
      }
    }
    const uint32_t end = uint32_t(data.radii.size());
    for (uint32_t v = start; v + 1 < end; ++v)
      data.segmentStarts.push_back(v);
  }
  if (data.segmentStarts.empty())
    return fail("no curve has a segment");
  return data;
}

} // namespace prism::nsi
