#include "CellShapes.h"

#include <algorithm>
#include <cmath>

namespace prism {
namespace {

// Parametric slack when deciding inside / outside, so a point on a face
// shared by two cells lands in at least one of them despite rounding.
constexpr double kInsideSlack = 1e-5;

struct Vector3d
{
  double x, y, z;
};

Vector3d toDouble(const float3 &v)
{
  return {v.x, v.y, v.z};
}

// Solves [a b c] x = rhs (columns a, b, c) by Cramer's rule; false when the
// matrix is singular relative to its scale.
bool solve3x3(const Vector3d &a,
    const Vector3d &b,
    const Vector3d &c,
    const Vector3d &rhs,
    Vector3d &x)
{
  auto det = [](const Vector3d &p, const Vector3d &q, const Vector3d &r) {
    return p.x * (q.y * r.z - q.z * r.y) - q.x * (p.y * r.z - p.z * r.y)
           + r.x * (p.y * q.z - p.z * q.y);
  };
  const double d = det(a, b, c);
  const double scale = std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z)
                       * std::sqrt(b.x * b.x + b.y * b.y + b.z * b.z)
                       * std::sqrt(c.x * c.x + c.y * c.y + c.z * c.z);
  if (!(std::abs(d) > 1e-14 * scale))
    return false;
  x = {det(rhs, b, c) / d, det(a, rhs, c) / d, det(a, b, rhs) / d};
  return true;
}

// Shape functions N_i(r, s, t) and their parametric derivatives for the
// isoparametric cells (VTK's parametric spaces: the unit cube for
// hexahedra and pyramids, the unit triangle times [0, 1] for wedges).
int shapeFunctions(CellType type,
    const Vector3d &p,
    double n[kMaxCellVertices],
    Vector3d dn[kMaxCellVertices])
{
  const double r = p.x, s = p.y, t = p.z;
  if (type == CellType::Wedge) {
    const double w = 1.0 - r - s;
    const double base[3] = {w, r, s};
    const Vector3d baseD[3] = {{-1, -1, 0}, {1, 0, 0}, {0, 1, 0}};
    for (int i = 0; i < 3; i++) {
      n[i] = base[i] * (1.0 - t);
      n[i + 3] = base[i] * t;
      dn[i] = {baseD[i].x * (1.0 - t), baseD[i].y * (1.0 - t), -base[i]};
      dn[i + 3] = {baseD[i].x * t, baseD[i].y * t, base[i]};
    }
    return 6;
  }
  // Hexahedra and the pyramid's base: bilinear in (r, s) over the corners
  // (0,0) (1,0) (1,1) (0,1), counterclockwise as VTK orders them.
  const double cornerR[4] = {0, 1, 1, 0};
  const double cornerS[4] = {0, 0, 1, 1};
  for (int i = 0; i < 4; i++) {
    const double fr = cornerR[i] ? r : 1.0 - r;
    const double fs = cornerS[i] ? s : 1.0 - s;
    const double dr = cornerR[i] ? 1.0 : -1.0;
    const double ds = cornerS[i] ? 1.0 : -1.0;
    n[i] = fr * fs * (1.0 - t);
    dn[i] = {dr * fs * (1.0 - t), fr * ds * (1.0 - t), -fr * fs};
    if (type == CellType::Hexahedron) {
      n[i + 4] = fr * fs * t;
      dn[i + 4] = {dr * fs * t, fr * ds * t, fr * fs};
    }
  }
  if (type == CellType::Hexahedron)
    return 8;
  // Pyramid: VTK's apex function is t alone (a hexahedron whose top face
  // collapsed to the apex).
  n[4] = t;
  dn[4] = {0, 0, 1};
  return 5;
}

// How far `p` lies outside the parametric cell (0 inside), in the max norm.
double distanceOutside(CellType type, const Vector3d &p)
{
  double d = std::max({0.0, -p.x, -p.y, -p.z, p.z - 1.0});
  if (type == CellType::Wedge)
    return std::max(d, p.x + p.y - 1.0);
  return std::max({d, p.x - 1.0, p.y - 1.0});
}

// Pulls a point accepted within the slack back into the cell, so weights
// are never negative and values stay within the cell's vertex range.
Vector3d clampParametric(CellType type, Vector3d p)
{
  p.x = std::clamp(p.x, 0.0, 1.0);
  p.y = std::clamp(p.y, 0.0, 1.0);
  p.z = std::clamp(p.z, 0.0, 1.0);
  if (type == CellType::Wedge && p.x + p.y > 1.0) {
    const double scale = 1.0 / (p.x + p.y);
    p.x *= scale;
    p.y *= scale;
  }
  return p;
}

enum class Inversion {
  Converged,
  Outside, // converging to a point clearly outside the cell
  Failed,
};

// Newton's method on x(r, s, t) = point from `start`.
Inversion invertMap(CellType type,
    const Vector3d *vertices,
    const Vector3d &point,
    double tolerance,
    Vector3d start,
    Vector3d &parametric)
{
  constexpr int kMaxIterations = 24;
  double n[kMaxCellVertices];
  Vector3d dn[kMaxCellVertices];
  Vector3d p = start;
  for (int iteration = 0; iteration < kMaxIterations; iteration++) {
    const int count = shapeFunctions(type, p, n, dn);
    Vector3d x{0, 0, 0}, dr{0, 0, 0}, ds{0, 0, 0}, dt{0, 0, 0};
    for (int i = 0; i < count; i++) {
      const Vector3d &v = vertices[i];
      x = {x.x + n[i] * v.x, x.y + n[i] * v.y, x.z + n[i] * v.z};
      dr = {dr.x + dn[i].x * v.x, dr.y + dn[i].x * v.y, dr.z + dn[i].x * v.z};
      ds = {ds.x + dn[i].y * v.x, ds.y + dn[i].y * v.y, ds.z + dn[i].y * v.z};
      dt = {dt.x + dn[i].z * v.x, dt.y + dn[i].z * v.y, dt.z + dn[i].z * v.z};
    }
    const Vector3d residual{point.x - x.x, point.y - x.y, point.z - x.z};
    const double error =
        std::sqrt(residual.x * residual.x + residual.y * residual.y
                  + residual.z * residual.z);
    if (error <= tolerance) {
      parametric = p;
      return Inversion::Converged;
    }
    Vector3d step;
    if (!solve3x3(dr, ds, dt, residual, step))
      return Inversion::Failed;
    // Damped: far from the cell the bilinear terms make full steps
    // overshoot; no legitimate step spans more than the parametric cell.
    const double length =
        std::sqrt(step.x * step.x + step.y * step.y + step.z * step.z);
    const double damping = length > 1.0 ? 1.0 / length : 1.0;
    p = {
        p.x + damping * step.x, p.y + damping * step.y, p.z + damping * step.z};
    if (!std::isfinite(p.x + p.y + p.z) || std::abs(p.x) > 1e3
        || std::abs(p.y) > 1e3 || std::abs(p.z) > 1e3)
      return Inversion::Failed;
    if (length < 1e-12) {
      parametric = p;
      return Inversion::Converged;
    }
    // Converging quadratically (small steps), the remaining error is far
    // below the step: a point this far outside will not come back in.
    // Most cells a point's search visits are rejected here, early.
    if (length < 0.05 && distanceOutside(type, p) > 4.0 * length + 0.01)
      return Inversion::Outside;
  }
  return Inversion::Failed;
}

bool tetrahedronWeights(
    const Vector3d *v, const Vector3d &point, float weights[])
{
  const Vector3d e1{v[1].x - v[0].x, v[1].y - v[0].y, v[1].z - v[0].z};
  const Vector3d e2{v[2].x - v[0].x, v[2].y - v[0].y, v[2].z - v[0].z};
  const Vector3d e3{v[3].x - v[0].x, v[3].y - v[0].y, v[3].z - v[0].z};
  const Vector3d rhs{point.x - v[0].x, point.y - v[0].y, point.z - v[0].z};
  Vector3d b;
  if (!solve3x3(e1, e2, e3, rhs, b))
    return false;
  const double b0 = 1.0 - b.x - b.y - b.z;
  if (b0 < -kInsideSlack || b.x < -kInsideSlack || b.y < -kInsideSlack
      || b.z < -kInsideSlack)
    return false;
  const double w[4] = {std::max(b0, 0.0),
      std::max(b.x, 0.0),
      std::max(b.y, 0.0),
      std::max(b.z, 0.0)};
  const double sum = w[0] + w[1] + w[2] + w[3];
  for (int i = 0; i < 4; i++)
    weights[i] = float(w[i] / sum);
  return true;
}

} // namespace

bool cellWeights(CellType type,
    const float3 *vertices,
    const float3 &point,
    float weights[kMaxCellVertices])
{
  Vector3d v[kMaxCellVertices];
  const int count = cellVertexCount(uint8_t(type));
  if (count == 0)
    return false;
  for (int i = 0; i < count; i++)
    v[i] = toDouble(vertices[i]);
  const Vector3d p = toDouble(point);
  if (type == CellType::Tetrahedron)
    return tetrahedronWeights(v, p, weights);

  // The residual tolerance: below the rounding level of the cell's float
  // coordinates, so iterating further would change no float value.
  double size = 0.0;
  for (int i = 1; i < count; i++) {
    size = std::max({size,
        std::abs(v[i].x - v[0].x),
        std::abs(v[i].y - v[0].y),
        std::abs(v[i].z - v[0].z)});
  }
  const double tolerance = 1e-8 * size;
  // From the cell's centre first; if Newton does not converge there
  // (strongly distorted cells), from the centres of the corner octants.
  const Vector3d centre = type == CellType::Wedge
                              ? Vector3d{1.0 / 3.0, 1.0 / 3.0, 0.5}
                              : Vector3d{0.5, 0.5, 0.5};
  Vector3d parametric;
  Inversion result = invertMap(type, v, p, tolerance, centre, parametric);
  for (int corner = 0; corner < 8 && result == Inversion::Failed; corner++) {
    const Vector3d start{corner & 1 ? 0.75 : 0.25,
        corner & 2 ? 0.75 : 0.25,
        corner & 4 ? 0.75 : 0.25};
    result = invertMap(type, v, p, tolerance, start, parametric);
  }
  if (result != Inversion::Converged
      || distanceOutside(type, parametric) > kInsideSlack)
    return false;
  double n[kMaxCellVertices];
  Vector3d dn[kMaxCellVertices];
  shapeFunctions(type, clampParametric(type, parametric), n, dn);
  for (int i = 0; i < count; i++)
    weights[i] = float(n[i]);
  return true;
}

} // namespace prism
