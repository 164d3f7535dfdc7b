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
  m_pairs.clear();
  m_nodeValueRanges.clear();
  m_cellBounds.clear();
  m_cellValueRanges.clear();
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
    uint32_t pair, side; // where the node goes
  };
  m_pairs.reserve(cellCount / kMaxLeafCells + 2);
  m_pairs.push_back({});
  std::vector<Task> pending{{0, cellCount, 0, 0}};
  while (!pending.empty()) {
    const Task task = pending.back();
    pending.pop_back();
    box3 bounds = emptyBox3();
    box3 centroidBounds = emptyBox3();
    for (uint32_t i = task.begin; i < task.end; i++) {
      bounds = extend(bounds, cellBounds[order[i]]);
      centroidBounds = extend(centroidBounds, centroids[order[i]]);
    }
    const uint32_t count = task.end - task.begin;
    Node node{bounds.lower, bounds.upper, task.begin, count};
    if (count > kMaxLeafCells) {
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
      // Children's pairs come after their parent's (see the ranges below).
      node = {bounds.lower, bounds.upper, uint32_t(m_pairs.size()), 0};
      m_pairs.push_back({});
      pending.push_back({middle, task.end, node.first, 1});
      pending.push_back({task.begin, middle, node.first, 0});
    }
    m_pairs[task.pair].node[task.side] = node;
  }

  // Cell data in leaf order, so a leaf's cells sit together in memory.
  m_cellBounds.resize(cellCount);
  m_cellValueRanges.resize(cellCount);
  for (uint32_t i = 0; i < cellCount; i++) {
    m_cellBounds[i] = cellBounds[order[i]];
    m_cellValueRanges[i] = cellValueRanges[order[i]];
  }
  // Children's pairs follow their parents', so one backward pass fills
  // the ranges.
  m_nodeValueRanges.resize(2 * m_pairs.size());
  for (size_t p = m_pairs.size(); p-- > 0;) {
    for (int side = 0; side < 2; side++) {
      const Node &node = m_pairs[p].node[side];
      float2 range{kInfinity, -kInfinity};
      if (node.count == 0 && !(p == 0 && side == 1)) {
        range = unite(m_nodeValueRanges[2 * node.first],
            m_nodeValueRanges[2 * node.first + 1]);
      } else {
        for (uint32_t i = node.first; i < node.first + node.count; i++)
          range = unite(range, m_cellValueRanges[i]);
      }
      m_nodeValueRanges[2 * p + side] = range;
    }
  }
  return order;
}

void CellBvh::valueRange(const box3 &region, float &lo, float &hi) const
{
  if (m_pairs.empty())
    return;
  uint32_t stack[kStackSize]; // node numbers: 2 * pair + side
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const uint32_t number = stack[--top];
    const Node &node = m_pairs[number / 2].node[number % 2];
    if (!overlaps(node.bounds(), region))
      continue;
    if (inside(node.bounds(), region)) {
      lo = std::min(lo, m_nodeValueRanges[number].x);
      hi = std::max(hi, m_nodeValueRanges[number].y);
      continue;
    }
    if (node.count == 0) {
      stack[top++] = 2 * node.first;
      stack[top++] = 2 * node.first + 1;
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
