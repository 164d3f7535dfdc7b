#include "NanoVdbGridSampler.h"

#include "CatmullRom.h"
#include "NanoVdbGridTypes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_set>

namespace prism {

namespace {

template <typename BuildT, FieldFilter kFilter>
class TypedGridSampler : public NanoVdbGridSampler
{
  using Grid = nanovdb::NanoGrid<BuildT>;
  using Root = nanovdb::NanoRoot<BuildT>;
  using Accessor = nanovdb::ReadAccessor<BuildT, 0, 1, 2>;

 public:
  explicit TypedGridSampler(const nanovdb::GridData &grid)
      : m_grid(grid), m_root(reinterpret_cast<const Grid &>(grid).tree().root())
  {}

  float sample(const float3 &index) const override
  {
    // One accessor per call: its node cache is not shared between threads.
    const Accessor accessor(m_root);
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
      auto row = [&](int dj, int dk) {
        const float v0 = value(i, j + dj, k + dk);
        return v0 + t.x * (value(i + 1, j + dj, k + dk) - v0);
      };
      const float y0 = row(0, 0) + t.y * (row(1, 0) - row(0, 0));
      const float y1 = row(0, 1) + t.y * (row(1, 1) - row(0, 1));
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

  float2 storedValueRange() const override
  {
    float2 range{float(m_root.background()), float(m_root.background())};
    auto include = [&](float v) {
      range.x = std::min(range.x, v);
      range.y = std::max(range.y, v);
    };
    const auto *root = m_root.data();
    for (uint32_t n = 0; n < root->mTableSize; n++) {
      if (root->tile(n)->child == 0)
        include(float(root->tile(n)->value));
    }
    // Node arrays rather than the child graph: a crafted grid whose
    // children all point at one node would make a walk of the graph
    // visit that node billions of times. Leaves (variable-size for FpN)
    // are reached through lower nodes, each visited once.
    const auto &tree = *reinterpret_cast<const nanovdb::TreeData<3> *>(
        reinterpret_cast<const uint8_t *>(&m_grid) + sizeof(m_grid));
    const auto *upper = reinterpret_cast<const typename Upper::DataType *>(
        tree.mNodeCount[2] ? (const uint8_t *)&tree + tree.mNodeOffset[2]
                           : nullptr);
    for (uint32_t n = 0; n < tree.mNodeCount[2]; n++)
      includeTileValues(upper[n], include);
    const auto *lower = reinterpret_cast<const typename Lower::DataType *>(
        tree.mNodeCount[1] ? (const uint8_t *)&tree + tree.mNodeOffset[1]
                           : nullptr);
    std::unordered_set<const Leaf *> leavesSeen;
    for (uint32_t n = 0; n < tree.mNodeCount[1]; n++) {
      includeTileValues(lower[n], include);
      for (auto child = lower[n].mChildMask.beginOn(); child; ++child) {
        const Leaf *leaf = lower[n].getChild(*child);
        if (!leavesSeen.insert(leaf).second)
          continue;
        for (uint32_t v = 0; v < Leaf::SIZE; v++)
          include(float(leaf->getValue(v)));
      }
    }
    return range;
  }

 private:
  using Leaf = nanovdb::NanoLeaf<BuildT>;
  using Lower = nanovdb::NanoLower<BuildT>;
  using Upper = nanovdb::NanoUpper<BuildT>;

  // The values of an internal node's entries that hold no child.
  template <typename NodeData, typename Include>
  static void includeTileValues(const NodeData &node, const Include &include)
  {
    for (auto tile = node.mChildMask.beginOff(); tile; ++tile)
      include(float(node.mTable[*tile].value));
  }

  const nanovdb::GridData &m_grid;
  const Root &m_root;
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
