#include "NanoVdbGridSampler.h"

#include "CatmullRom.h"
#include "NanoVdbGridTypes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace prism {

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

template <typename BuildT, FieldFilter kFilter>
class TypedGridSampler : public NanoVdbGridSampler
{
  using Grid = nanovdb::NanoGrid<BuildT>;
  using Root = nanovdb::NanoRoot<BuildT>;
  using Accessor = nanovdb::ReadAccessor<BuildT, 0, 1, 2>;

 public:
  explicit TypedGridSampler(const nanovdb::GridData &grid)
      : m_grid(grid), m_root(reinterpret_cast<const Grid &>(grid).tree().root())
  {
    m_wholeRange = storedValueRange();
    buildLocalRanges();
  }

  float sample(const float3 &index) const override
  {
    // One accessor per call: its node cache is not shared between threads.
    const Accessor accessor(m_root);
    return filtered(accessor, index);
  }

  void sampleLine(const float3 &start,
      const float3 &step,
      int count,
      float *values) const override
  {
    // One accessor for the whole line: neighbouring points share leaves.
    const Accessor accessor(m_root);
    for (int n = 0; n < count; n++)
      values[n] = filtered(accessor, start + step * float(n));
  }

  float2 valueRange(const int3 &lo, const int3 &hi) const override
  {
    float2 range{kInfinity, -kInfinity};
    if (leafSpanRange(lo, hi, range))
      return range;
    const int3 first = spanOf(lo);
    const int3 last = spanOf(hi);
    if (!m_hasLocalRanges || tooMany(first, last, kMaxRangeCellsPerQuery))
      return m_wholeRange;
    const Accessor accessor(m_root);
    for (int k = first.z; k <= last.z; k++)
      for (int j = first.y; j <= last.y; j++)
        for (int i = first.x; i <= last.x; i++) {
          const int3 cell{i, j, k};
          // Where no lower node is, one tile value (or the background)
          // covers the whole span; where one is, this is one of its values.
          const nanovdb::Coord origin(i * (1 << kLowerLog2Span),
              j * (1 << kLowerLog2Span),
              k * (1 << kLowerLog2Span));
          unite(range, float(accessor.getValue(origin)));
          const auto found = m_lowerRanges.find(keyOf(cell));
          if (found != m_lowerRanges.end()) {
            unite(range, found->second.x);
            unite(range, found->second.y);
          }
        }
    return range;
  }

 private:
  using Leaf = nanovdb::NanoLeaf<BuildT>;
  using Lower = nanovdb::NanoLower<BuildT>;
  using Upper = nanovdb::NanoUpper<BuildT>;
  static constexpr int kLowerLog2Span = Lower::TOTAL; // 128 voxels
  // Beyond these, a crafted grid (many references to a few nodes) or a
  // large region falls back to the whole grid's range.
  static constexpr uint64_t kMaxLowerReferences = uint64_t(1) << 20;
  static constexpr int64_t kMaxRangeCellsPerQuery = 4096;
  // A majorant cell with the cubic footprint spans 2 leaves per axis; a
  // region far larger reads the lower nodes' ranges instead.
  static constexpr int64_t kMaxLeafSpansPerQuery = 512;

  // The lower node span holding `voxel` (an arithmetic shift floors).
  static int3 spanOf(const int3 &voxel)
  {
    return {voxel.x >> kLowerLog2Span,
        voxel.y >> kLowerLog2Span,
        voxel.z >> kLowerLog2Span};
  }
  static void unite(float2 &range, float value)
  {
    range.x = std::min(range.x, value);
    range.y = std::max(range.y, value);
  }
  // Collisions only merge ranges, which stays conservative.
  static uint64_t keyOf(const int3 &cell)
  {
    const uint64_t mask = (uint64_t(1) << 21) - 1;
    return (uint64_t(uint32_t(cell.x)) & mask) << 42
           | (uint64_t(uint32_t(cell.y)) & mask) << 21
           | (uint64_t(uint32_t(cell.z)) & mask);
  }

  // The range over voxels lo..hi leaf span by leaf span (8^3 voxels): the
  // voxels themselves where the region covers part of a leaf, the leaf's
  // range where it covers all of it, the one tile value covering the span
  // where no leaf is. False (range untouched) for regions of more than
  // kMaxLeafSpansPerQuery spans, or a leaf the node arrays did not hold.
  bool leafSpanRange(const int3 &lo, const int3 &hi, float2 &range) const
  {
    const int3 first = leafSpanOf(lo);
    const int3 last = leafSpanOf(hi);
    if (!m_hasLocalRanges || tooMany(first, last, kMaxLeafSpansPerQuery))
      return false;
    const Accessor accessor(m_root);
    constexpr int kDim = int(Leaf::DIM);
    float2 found{kInfinity, -kInfinity};
    for (int k = first.z; k <= last.z; k++)
      for (int j = first.y; j <= last.y; j++)
        for (int i = first.x; i <= last.x; i++) {
          const int3 origin = int3{i, j, k} * kDim;
          const nanovdb::Coord coord(origin.x, origin.y, origin.z);
          const Leaf *leaf = accessor.probeLeaf(coord);
          if (!leaf) {
            unite(found, float(accessor.getValue(coord)));
            continue;
          }
          const int3 from = max(lo, origin) - origin;
          const int3 to = min(hi, origin + (kDim - 1)) - origin;
          if (to - from == int3{kDim - 1, kDim - 1, kDim - 1}) {
            const auto cached = m_leafRanges.find(leaf);
            if (cached == m_leafRanges.end())
              return false;
            unite(found, cached->second.x);
            unite(found, cached->second.y);
            continue;
          }
          // x-major offsets: (x << 6) | (y << 3) | z.
          for (int x = from.x; x <= to.x; x++)
            for (int y = from.y; y <= to.y; y++)
              for (int z = from.z; z <= to.z; z++)
                unite(found,
                    float(leaf->getValue(uint32_t((x * kDim + y) * kDim + z))));
        }
    range = found;
    return true;
  }
  // Whether the box of cells first..last holds more than `limit`.
  static bool tooMany(const int3 &first, const int3 &last, int64_t limit)
  {
    const int3 cells = last - first + 1;
    return double(cells.x) * cells.y * cells.z > double(limit);
  }
  static int3 leafSpanOf(const int3 &voxel)
  {
    constexpr int kLog2 = int(Leaf::TOTAL);
    return {voxel.x >> kLog2, voxel.y >> kLog2, voxel.z >> kLog2};
  }

  float filtered(const Accessor &accessor, const float3 &index) const
  {
    auto value = [&](int i, int j, int k) {
      return float(accessor.getValue(nanovdb::Coord(i, j, k)));
    };
    if constexpr (kFilter == FieldFilter::Nearest) {
      // floor(x + 1/2): ties round up.
      return value(int(std::floor(index.x + 0.5f)),
          int(std::floor(index.y + 0.5f)),
          int(std::floor(index.z + 0.5f)));
    }
    const float3 base = {
        std::floor(index.x), std::floor(index.y), std::floor(index.z)};
    const float3 t = index - base;
    const int i = int(base.x);
    const int j = int(base.y);
    const int k = int(base.z);
    if constexpr (kFilter == FieldFilter::Linear) {
      float corners[8];
      if (!leafCorners(accessor, i, j, k, corners)) {
        for (int c = 0; c < 8; c++)
          corners[c] = value(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2));
      }
      auto row = [&](int c) {
        return corners[c] + t.x * (corners[c + 1] - corners[c]);
      };
      const float y0 = row(0) + t.y * (row(2) - row(0));
      const float y1 = row(4) + t.y * (row(6) - row(4));
      return y0 + t.z * (y1 - y0);
    } else {
      // Catmull-Rom, as structuredRegular's cubic filter (NanoVDB's own
      // tricubic sampler needs gradients and does not bound overshoot).
      const auto wx = catmullRomWeights(t.x);
      const auto wy = catmullRomWeights(t.y);
      const auto wz = catmullRomWeights(t.z);
      float result = 0.f;
      for (int dk = 0; dk < 4; dk++) {
        float plane = 0.f;
        for (int dj = 0; dj < 4; dj++) {
          float line = 0.f;
          for (int di = 0; di < 4; di++)
            line += wx[di] * value(i - 1 + di, j - 1 + dj, k - 1 + dk);
          plane += wy[dj] * line;
        }
        result += wz[dk] * plane;
      }
      return result;
    }
  }

  // The 8 voxels (i + (c & 1), j + (c >> 1 & 1), k + (c >> 2)) read
  // straight from one leaf when they all lie in the same one (7 cells in
  // 8 along each axis): no tree walk per tap. False otherwise.
  static bool leafCorners(
      const Accessor &accessor, int i, int j, int k, float corners[8])
  {
    constexpr int kLast = Leaf::DIM - 1;
    if ((i & kLast) == kLast || (j & kLast) == kLast || (k & kLast) == kLast)
      return false;
    const Leaf *leaf = accessor.probeLeaf(nanovdb::Coord(i, j, k));
    if (!leaf)
      return false;
    // A leaf's values are x-major: offset (x << 6) | (y << 3) | z.
    const uint32_t first = Leaf::CoordToOffset(nanovdb::Coord(i, j, k));
    constexpr uint32_t dx = Leaf::DIM * Leaf::DIM, dy = Leaf::DIM;
    for (int c = 0; c < 8; c++) {
      const uint32_t offset =
          first + (c & 1) * dx + (c >> 1 & 1) * dy + uint32_t(c >> 2);
      corners[c] = float(leaf->getValue(offset));
    }
    return true;
  }

  // Every value stored anywhere in the grid, from the node arrays rather
  // than the child graph: a crafted grid whose children all point at one
  // node would make a walk visit it billions of times. Leaves
  // (variable-size for FpN) are reached through lower nodes, once each.
  float2 storedValueRange()
  {
    float2 range{float(m_root.background()), float(m_root.background())};
    const auto *root = m_root.data();
    for (uint32_t n = 0; n < root->mTableSize; n++) {
      if (root->tile(n)->child == 0)
        unite(range, float(root->tile(n)->value));
    }
    const auto &tree = *reinterpret_cast<const nanovdb::TreeData<3> *>(
        reinterpret_cast<const uint8_t *>(&m_grid) + sizeof(m_grid));
    const auto *upper = reinterpret_cast<const typename Upper::DataType *>(
        tree.mNodeCount[2] ? (const uint8_t *)&tree + tree.mNodeOffset[2]
                           : nullptr);
    for (uint32_t n = 0; n < tree.mNodeCount[2]; n++)
      uniteTileValues(range, upper[n]);
    const auto *lower = reinterpret_cast<const typename Lower::DataType *>(
        tree.mNodeCount[1] ? (const uint8_t *)&tree + tree.mNodeOffset[1]
                           : nullptr);
    for (uint32_t n = 0; n < tree.mNodeCount[1]; n++) {
      const float2 node = lowerNodeRange(lower[n], m_leafRanges);
      unite(range, node.x);
      unite(range, node.y);
    }
    return range;
  }

  // Per lower node's span, reached the way accessors reach it (every root
  // tile, duplicates included): the range of all its leaves' values,
  // active or not, and its tile values.
  void buildLocalRanges()
  {
    std::unordered_map<const typename Lower::DataType *, float2> nodeRanges;
    uint64_t references = 0;
    const auto *root = m_root.data();
    for (uint32_t n = 0; n < root->mTableSize; n++) {
      const auto *tile = root->tile(n);
      if (tile->child == 0)
        continue;
      const nanovdb::Coord upperOrigin = tile->origin();
      const auto *upper = root->getChild(tile)->data();
      for (auto child = upper->mChildMask.beginOn(); child; ++child) {
        if (++references > kMaxLowerReferences) {
          m_lowerRanges.clear();
          return;
        }
        const auto *lower = upper->getChild(*child)->data();
        auto [node, added] = nodeRanges.try_emplace(lower);
        if (added)
          node->second = lowerNodeRange(*lower, m_leafRanges);
        const nanovdb::Coord local = Upper::OffsetToLocalCoord(*child);
        const int3 cell{(upperOrigin[0] >> kLowerLog2Span) + local[0],
            (upperOrigin[1] >> kLowerLog2Span) + local[1],
            (upperOrigin[2] >> kLowerLog2Span) + local[2]};
        auto [range, fresh] =
            m_lowerRanges.try_emplace(keyOf(cell), node->second);
        if (!fresh) {
          unite(range->second, node->second.x);
          unite(range->second, node->second.y);
        }
      }
    }
    m_hasLocalRanges = true;
  }

  static float2 lowerNodeRange(const typename Lower::DataType &lower,
      std::unordered_map<const Leaf *, float2> &leafRanges)
  {
    float2 range{kInfinity, -kInfinity};
    uniteTileValues(range, lower);
    for (auto child = lower.mChildMask.beginOn(); child; ++child) {
      const Leaf *leaf = lower.getChild(*child);
      auto [cached, added] = leafRanges.try_emplace(leaf);
      if (added) {
        float2 values{kInfinity, -kInfinity};
        for (uint32_t v = 0; v < Leaf::SIZE; v++)
          unite(values, float(leaf->getValue(v)));
        cached->second = values;
      }
      unite(range, cached->second.x);
      unite(range, cached->second.y);
    }
    return range;
  }

  // The values of an internal node's entries that hold no child.
  template <typename NodeData>
  static void uniteTileValues(float2 &range, const NodeData &node)
  {
    for (auto tile = node.mChildMask.beginOff(); tile; ++tile)
      unite(range, float(node.mTable[*tile].value));
  }

  const nanovdb::GridData &m_grid;
  const Root &m_root;
  float2 m_wholeRange{};
  bool m_hasLocalRanges{false};
  std::unordered_map<uint64_t, float2> m_lowerRanges;
  // Every leaf's range of values (active or not), by address.
  std::unordered_map<const Leaf *, float2> m_leafRanges;
};

template <typename BuildT>
std::unique_ptr<NanoVdbGridSampler> makeTyped(
    const nanovdb::GridData &grid, FieldFilter filter)
{
  switch (filter) {
  case FieldFilter::Nearest:
    return std::make_unique<TypedGridSampler<BuildT, FieldFilter::Nearest>>(
        grid);
  case FieldFilter::Cubic:
    return std::make_unique<TypedGridSampler<BuildT, FieldFilter::Cubic>>(grid);
  case FieldFilter::Linear:
    break;
  }
  return std::make_unique<TypedGridSampler<BuildT, FieldFilter::Linear>>(grid);
}

} // namespace

std::unique_ptr<NanoVdbGridSampler> makeNanoVdbGridSampler(
    const nanovdb::GridData &grid, FieldFilter filter)
{
  std::unique_ptr<NanoVdbGridSampler> sampler;
  visitNanoVdbGridType(grid.mGridType, [&](auto buildType) {
    using BuildT = typename decltype(buildType)::type;
    sampler = makeTyped<BuildT>(grid, filter);
  });
  return sampler;
}

} // namespace prism
