#include "CellBvh.h"

#include <algorithm>
#include <limits>

namespace prism {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

float2 unite(const float2 &a, const float2 &b)
{
  return {std::min(a.x, b.x), std::max(a.y, b.y)};
}

bool overlaps(const box3 &a, const box3 &b)
{
  return a.lower.x <= b.upper.x && a.lower.y <= b.upper.y
         && a.lower.z <= b.upper.z && b.lower.x <= a.upper.x
         && b.lower.y <= a.upper.y && b.lower.z <= a.upper.z;
}

bool inside(const box3 &inner, const box3 &outer)
{
  return contains(outer, inner.lower) && contains(outer, inner.upper);
}

} // namespace

std::vector<uint32_t> CellBvh::build(const std::vector<box3> &cellBounds,
    const std::vector<float2> &cellValueRanges)
{
  m_nodes.clear();
  m_nodeValueRanges.clear();
  const uint32_t cellCount = uint32_t(cellBounds.size());
  std::vector<uint32_t> order(cellCount);
  for (uint32_t i = 0; i < cellCount; i++)
    order[i] = i;
  if (cellCount == 0)
    return order;
  std::vector<float3> centroids(cellCount);
  for (uint32_t i = 0; i < cellCount; i++)
    centroids[i] = center(cellBounds[i]);

  struct Task
  {
    uint32_t begin, end;
    uint32_t parent; // whose `first` this right child sets (~0u: root)
  };
  std::vector<Task> pending{{0, cellCount, ~0u}};
  m_nodes.reserve(2 * (cellCount / kMaxLeafCells + 1));
  while (!pending.empty()) {
    Task task = pending.back();
    pending.pop_back();
    // Walks down the left spine, so each left child follows its parent.
    for (;;) {
      const uint32_t index = uint32_t(m_nodes.size());
      if (task.parent != ~0u)
        m_nodes[task.parent].first = index;
      box3 bounds = emptyBox3();
      box3 centroidBounds = emptyBox3();
      for (uint32_t i = task.begin; i < task.end; i++) {
        bounds = extend(bounds, cellBounds[order[i]]);
        centroidBounds = extend(centroidBounds, centroids[order[i]]);
      }
      m_nodes.push_back({bounds.lower, bounds.upper, task.begin, 0});
      const uint32_t count = task.end - task.begin;
      if (count <= kMaxLeafCells) {
        m_nodes[index].count = count;
        break;
      }
      const float3 spread = extent(centroidBounds);
      const int axis = spread.x >= spread.y && spread.x >= spread.z ? 0
                       : spread.y >= spread.z                       ? 1
                                                                    : 2;
      const uint32_t middle = task.begin + count / 2;
      std::nth_element(order.begin() + task.begin,
          order.begin() + middle,
          order.begin() + task.end,
          [&](uint32_t a, uint32_t b) {
            return centroids[a][axis] < centroids[b][axis];
          });
      pending.push_back({middle, task.end, index});
      task = {task.begin, middle, ~0u};
    }
  }

  // Cell data in leaf order, so a leaf's cells sit together in memory.
  m_cellBounds.resize(cellCount);
  m_cellValueRanges.resize(cellCount);
  for (uint32_t i = 0; i < cellCount; i++) {
    m_cellBounds[i] = cellBounds[order[i]];
    m_cellValueRanges[i] = cellValueRanges[order[i]];
  }
  // Children follow their parents, so one backward pass fills the ranges.
  m_nodeValueRanges.resize(m_nodes.size());
  for (size_t n = m_nodes.size(); n-- > 0;) {
    const Node &node = m_nodes[n];
    float2 range{kInfinity, -kInfinity};
    if (node.count == 0) {
      range = unite(m_nodeValueRanges[n + 1], m_nodeValueRanges[node.first]);
    } else {
      for (uint32_t i = node.first; i < node.first + node.count; i++)
        range = unite(range, m_cellValueRanges[i]);
    }
    m_nodeValueRanges[n] = range;
  }
  return order;
}

void CellBvh::valueRange(const box3 &region, float &lo, float &hi) const
{
  if (m_nodes.empty())
    return;
  uint32_t stack[kStackSize];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const uint32_t index = stack[--top];
    const Node &node = m_nodes[index];
    const box3 nodeBounds{node.lower, node.upper};
    if (!overlaps(nodeBounds, region))
      continue;
    if (inside(nodeBounds, region)) {
      lo = std::min(lo, m_nodeValueRanges[index].x);
      hi = std::max(hi, m_nodeValueRanges[index].y);
      continue;
    }
    if (node.count == 0) {
      stack[top++] = node.first;
      stack[top++] = index + 1;
      continue;
    }
    for (uint32_t i = node.first; i < node.first + node.count; i++) {
      if (overlaps(m_cellBounds[i], region)) {
        lo = std::min(lo, m_cellValueRanges[i].x);
        hi = std::max(hi, m_cellValueRanges[i].y);
      }
    }
  }
}

} // namespace prism
