#include "MajorantGrid.h"

#include <algorithm>
#include <cmath>

namespace prism {

void MajorantGrid::clear()
{
  m_values.clear();
  m_blockValues.clear();
  m_blocks[0] = m_blocks[1] = m_blocks[2] = 0;
  m_cells[0] = m_cells[1] = m_cells[2] = 0;
  m_maximum = 0.f;
}

void MajorantGrid::build(const box3 &bounds,
    float targetCellSize,
    const std::function<float(const box3 &)> &cellMajorant)
{
  clear();
  if (isEmpty(bounds) || !(targetCellSize > 0.f))
    return;
  m_bounds = bounds;
  const float3 extent = bounds.upper - bounds.lower;
  const float e[3] = {extent.x, extent.y, extent.z};
  float size[3];
  for (int a = 0; a < 3; a++) {
    // Cells of exactly the target size from the lower corner (so they line
    // up with a field's own blocks of that size), the last one reaching
    // past the bounds; wider where there would be too many. A flat axis
    // still gets a cell of non-zero width.
    size[a] =
        e[a] > 0.f ? std::max(targetCellSize, e[a] / float(kMaxCells)) : 1.f;
    m_cells[a] =
        int(std::clamp(std::ceil(e[a] / size[a]), 1.f, float(kMaxCells)));
  }
  m_cellSize = {size[0], size[1], size[2]};
  m_values.resize(size_t(m_cells[0]) * m_cells[1] * m_cells[2]);
  size_t i = 0;
  for (int z = 0; z < m_cells[2]; z++) {
    for (int y = 0; y < m_cells[1]; y++) {
      for (int x = 0; x < m_cells[0]; x++, i++) {
        const float3 lower =
            bounds.lower
            + float3{
                float(x) * size[0], float(y) * size[1], float(z) * size[2]};
        // Neighbouring cells share their faces: a sample on a face may be
        // counted in either, so both include it.
        const box3 cell{lower, min(lower + m_cellSize, bounds.upper)};
        const float bound = cellMajorant(cell);
        m_values[i] = std::isnan(bound) ? 0.f : std::max(bound, 0.f);
        m_maximum = std::max(m_maximum, m_values[i]);
      }
    }
  }
  for (int a = 0; a < 3; a++)
    m_blocks[a] = (m_cells[a] + kBlock - 1) / kBlock;
  m_blockValues.assign(size_t(m_blocks[0]) * m_blocks[1] * m_blocks[2], 0.f);
  for (int z = 0; z < m_cells[2]; z++) {
    for (int y = 0; y < m_cells[1]; y++) {
      for (int x = 0; x < m_cells[0]; x++) {
        float &block = m_blockValues[(size_t(z / kBlock) * m_blocks[1]
                                         + size_t(y / kBlock))
                                         * m_blocks[0]
                                     + size_t(x / kBlock)];
        block = std::max(block, value(x, y, z));
      }
    }
  }
}

} // namespace prism
