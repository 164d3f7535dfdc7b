// A coarse grid over a volume's bounds holding, per cell, an upper bound
// of the extinction anywhere in the cell. Ray marchers skip cells whose
// bound is 0; delta and ratio tracking draw tentative collisions against
// each cell's bound instead of one bound for the whole volume.
#pragma once

#include "../math/Vec.h"

#include <algorithm>
#include <cmath>
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
  // Cells are grouped in blocks of kBlock^3 holding their largest bound,
  // so a ray crosses empty space a block at a time.
  static constexpr int kBlock = 4;

  // A 3D DDA: the cell a ray is in, the t at which it crosses the next
  // boundary along each axis and the t between boundaries.
  struct Walk
  {
    int cell[3], step[3];
    float next[3], delta[3];
    // Starts at parameter t, in the cell there clamped to [lo, hi].
    void start(const float o[3],
        const float d[3],
        float t,
        const float lower[3],
        const float size[3],
        const int lo[3],
        const int hi[3]);
    // The axis whose boundary comes next.
    int nextAxis() const
    {
      return next[0] < next[1] ? (next[0] < next[2] ? 0 : 2)
                               : (next[1] < next[2] ? 1 : 2);
    }
    // Crosses that boundary; false when it leaves [lo, hi].
    bool advance(int axis, const int lo[3], const int hi[3])
    {
      cell[axis] += step[axis];
      if (cell[axis] < lo[axis] || cell[axis] > hi[axis])
        return false;
      next[axis] += delta[axis];
      return true;
    }
  };

  float value(int x, int y, int z) const
  {
    return m_values[(size_t(z) * m_cells[1] + size_t(y)) * m_cells[0]
                    + size_t(x)];
  }
  float blockValue(const int block[3]) const
  {
    return m_blockValues[(size_t(block[2]) * m_blocks[1] + size_t(block[1]))
                             * m_blocks[0]
                         + size_t(block[0])];
  }

  box3 m_bounds{};
  int m_cells[3]{0, 0, 0};
  float3 m_cellSize{0.f, 0.f, 0.f};
  float m_maximum{0.f};
  std::vector<float> m_values;
  int m_blocks[3]{0, 0, 0};
  std::vector<float> m_blockValues;
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
  const float o[3] = {origin.x, origin.y, origin.z};
  const float d[3] = {direction.x, direction.y, direction.z};
  const float lower[3] = {m_bounds.lower.x, m_bounds.lower.y, m_bounds.lower.z};
  const float fine[3] = {m_cellSize.x, m_cellSize.y, m_cellSize.z};
  const float coarse[3] = {
      fine[0] * kBlock, fine[1] * kBlock, fine[2] * kBlock};
  const int first[3] = {0, 0, 0};
  const int last[3] = {m_blocks[0] - 1, m_blocks[1] - 1, m_blocks[2] - 1};
  Walk blocks;
  blocks.start(o, d, t0, lower, coarse, first, last);
  for (float t = t0; t < t1;) {
    const int a = blocks.nextAxis();
    const float exit = std::min(std::max(blocks.next[a], t), t1);
    const float blockBound = blockValue(blocks.cell);
    if (blockBound > 0.f) {
      // The block holds something: its cells one by one.
      int lo[3], hi[3];
      for (int b = 0; b < 3; b++) {
        lo[b] = blocks.cell[b] * kBlock;
        hi[b] = std::min(lo[b] + kBlock, m_cells[b]) - 1;
      }
      Walk cells;
      cells.start(o, d, t, lower, fine, lo, hi);
      float u = t;
      while (u < exit) {
        const int b = cells.nextAxis();
        const float cellExit = std::min(std::max(cells.next[b], u), exit);
        if (!visit(u,
                cellExit,
                value(cells.cell[0], cells.cell[1], cells.cell[2])))
          return false;
        u = cellExit;
        if (!cells.advance(b, lo, hi))
          break;
      }
      // Rounding can end the cells' walk before the block's exit: the rest
      // takes the block's bound, which bounds every cell in it.
      if (u < exit && !visit(u, exit, blockBound))
        return false;
    }
    t = exit;
    if (!blocks.advance(a, first, last))
      break;
  }
  return true;
}

inline void MajorantGrid::Walk::start(const float o[3],
    const float d[3],
    float t,
    const float lower[3],
    const float size[3],
    const int lo[3],
    const int hi[3])
{
  for (int a = 0; a < 3; a++) {
    const float entry = o[a] + d[a] * t;
    const int c = int(std::floor((entry - lower[a]) / size[a]));
    cell[a] = c < lo[a] ? lo[a] : (c > hi[a] ? hi[a] : c);
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
}

} // namespace prism
