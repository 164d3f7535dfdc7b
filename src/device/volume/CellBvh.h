// A bounding volume hierarchy over the cells of an unstructured field:
// finds the cells whose bounds hold a point, and answers conservative value
// ranges per region from the min / max stored in every node.
#pragma once

#include "../math/Vec.h"

#include <cstdint>
#include <vector>

namespace prism {

class CellBvh
{
 public:
  // Builds over one box and one value range (x = min, y = max) per cell
  // (median splits along the longest centroid axis). Returns the cells in
  // leaf order: from now on the hierarchy names cell order[i] i, so that
  // callers can store cells in that order (neighbours near in memory).
  std::vector<uint32_t> build(const std::vector<box3> &cellBounds,
      const std::vector<float2> &cellValueRanges);

  box3 bounds() const
  {
    return m_pairs.empty() ? emptyBox3() : m_pairs[0].node[0].bounds();
  }

  // Calls `visit(cell)` (cell in leaf order) for every cell whose bounds
  // contain `point` until it returns true; returns whether one did.
  template <typename Visit>
  bool findCell(const float3 &point, Visit &&visit) const;

  // Extends [lo, hi] by the value ranges of the cells whose bounds overlap
  // `region`, taking whole subtrees that lie inside it at once.
  void valueRange(const box3 &region, float &lo, float &hi) const;

 private:
  // 32 bytes: a leaf holds cells [first, first + count); an inner node
  // (count 0) has its two children in pair `first`.
  struct Node
  {
    float3 lower;
    float3 upper;
    uint32_t first;
    uint32_t count;

    box3 bounds() const
    {
      return {lower, upper};
    }
  };
  // Siblings share one cache line, so a descent tests both children with
  // one memory access. The root is pair 0's first node (its second unused).
  struct alignas(64) NodePair
  {
    Node node[2];
  };
  static constexpr int kMaxLeafCells = 4;
  static constexpr int kStackSize = 64; // depth is below log2(cells) + 1

  std::vector<NodePair> m_pairs;
  std::vector<float2> m_nodeValueRanges; // 2 per pair, beside the nodes
  // In leaf order.
  std::vector<box3> m_cellBounds;
  std::vector<float2> m_cellValueRanges;
};

template <typename Visit>
bool CellBvh::findCell(const float3 &point, Visit &&visit) const
{
  if (m_pairs.empty() || !contains(bounds(), point))
    return false;
  const Node *stack[kStackSize];
  int top = 0;
  stack[top++] = &m_pairs[0].node[0];
  while (top > 0) {
    const Node &node = *stack[--top];
    if (node.count == 0) {
      const NodePair &children = m_pairs[node.first];
      for (int side = 1; side >= 0; side--) {
        if (contains(children.node[side].bounds(), point))
          stack[top++] = &children.node[side];
      }
      continue;
    }
    for (uint32_t i = node.first; i < node.first + node.count; i++) {
      if (contains(m_cellBounds[i], point) && visit(i))
        return true;
    }
  }
  return false;
}

} // namespace prism
