// A coarse grid over a volume's bounds holding, per cell, an upper bound
// of the extinction anywhere in the cell. Ray marchers skip cells whose
// bound is 0; delta and ratio tracking draw tentative collisions against
// each cell's bound instead of one bound for the whole volume.
#pragma once

#include "../math/Vec.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace prism {

class MajorantGrid
{
 public:
  // Cells about `targetCellSize` wide (at most kMaxCells per axis) over
  // `bounds`; each cell's bound from `cellMajorant(cell bounds)`.
  void build(const box3 &bounds,
      float targetCellSize,
      const std::function<float(const box3 &)> &cellMajorant);
  void clear();

  bool empty() const
  {
    return m_values.empty();
  }
  const box3 &bounds() const
  {
    return m_bounds;
  }
  // The largest bound of any cell.
  float maximum() const
  {
    return m_maximum;
  }

  // Visits, front to back, the cells the ray origin + t * direction
  // (object space; direction need not be unit) crosses within [t0, t1],
  // as visit(tEnter, tExit, majorant); stops when visit returns false.
  // Returns false if a visit stopped it.
  template <typename Visit>
  bool traverse(const float3 &origin,
      const float3 &direction,
      float t0,
      float t1,
      Visit &&visit) const;

  static constexpr int kMaxCells = 128;

 private:
  float value(int x, int y, int z) const
  {
    return m_values[(size_t(z) * m_cells[1] + size_t(y)) * m_cells[0]
                    + size_t(x)];
  }

  box3 m_bounds{};
  int m_cells[3]{0, 0, 0};
  float3 m_cellSize{0.f, 0.f, 0.f};
  float m_maximum{0.f};
  std::vector<float> m_values;
};

template <typename Visit>
bool MajorantGrid::traverse(const float3 &origin,
    const float3 &direction,
    float t0,
    float t1,
    Visit &&visit) const
{
  if (m_values.empty() || !(t1 > t0))
    return true;
  // Cell of the entry point, then a 3D DDA: per axis the t of the next
  // cell boundary and the t between boundaries.
  const float3 entry = origin + direction * t0;
  int cell[3], step[3];
  float next[3], delta[3];
  const float o[3] = {origin.x, origin.y, origin.z};
  const float d[3] = {direction.x, direction.y, direction.z};
  const float e[3] = {entry.x, entry.y, entry.z};
  const float lower[3] = {m_bounds.lower.x, m_bounds.lower.y, m_bounds.lower.z};
  const float size[3] = {m_cellSize.x, m_cellSize.y, m_cellSize.z};
  for (int a = 0; a < 3; a++) {
    const int c = int((e[a] - lower[a]) / size[a]);
    cell[a] = c < 0 ? 0 : (c >= m_cells[a] ? m_cells[a] - 1 : c);
    if (d[a] > 0.f) {
      step[a] = 1;
      next[a] = (lower[a] + float(cell[a] + 1) * size[a] - o[a]) / d[a];
      delta[a] = size[a] / d[a];
    } else if (d[a] < 0.f) {
      step[a] = -1;
      next[a] = (lower[a] + float(cell[a]) * size[a] - o[a]) / d[a];
      delta[a] = -size[a] / d[a];
    } else {
      step[a] = 0;
      next[a] = std::numeric_limits<float>::infinity();
      delta[a] = std::numeric_limits<float>::infinity();
    }
  }
  float t = t0;
  while (t < t1) {
    const int a = next[0] < next[1] ? (next[0] < next[2] ? 0 : 2)
                                    : (next[1] < next[2] ? 1 : 2);
    const float exit = std::min(std::max(next[a], t), t1);
    if (!visit(t, exit, value(cell[0], cell[1], cell[2])))
      return false;
    t = exit;
    cell[a] += step[a];
    if (cell[a] < 0 || cell[a] >= m_cells[a])
      break;
    next[a] += delta[a];
  }
  return true;
}

} // namespace prism
