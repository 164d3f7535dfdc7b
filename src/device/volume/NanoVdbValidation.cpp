#include "NanoVdbValidation.h"

#include "NanoVdbGridTypes.h"

#include <cmath>
#include <cstring>

namespace prism {

namespace {

// A level's nodes: byte offsets (from the grid's start) of the first node
// and of the end of the last; nodeSize 0 marks variable-size (FpN) leaves.
struct NodeArray
{
  uint64_t begin{0};
  uint64_t end{0};
  uint64_t nodeSize{0};
};

constexpr uint64_t kTreeOffset = sizeof(nanovdb::GridData);

// Bytes of the FpN leaf at `offset`, or 0 if its header is corrupt.
template <typename BuildT>
uint64_t variableLeafBytes(
    const uint8_t *grid, const NodeArray &leaves, uint64_t offset)
{
  using LeafData = typename nanovdb::NanoLeaf<BuildT>::DataType;
  if (offset > leaves.end || leaves.end - offset < sizeof(LeafData))
    return 0;
  const auto *leaf = reinterpret_cast<const LeafData *>(grid + offset);
  // Bit widths 1, 2, 4, 8, 16 are the codes 0..4 (NanoVDB's getValue).
  if ((leaf->mFlags >> 5) > 4)
    return 0;
  const uint64_t bytes = leaf->memUsage();
  return leaves.end - offset < bytes ? 0 : bytes;
}

// Whether a child pointer (`offset` from the grid's start) lands on a whole
// node of `nodes`.
template <typename BuildT>
bool holdsNode(const uint8_t *grid, const NodeArray &nodes, uint64_t offset)
{
  if (offset < nodes.begin || offset >= nodes.end)
    return false;
  if (nodes.nodeSize)
    return (offset - nodes.begin) % nodes.nodeSize == 0;
  return offset % NANOVDB_DATA_ALIGNMENT == 0
         && variableLeafBytes<BuildT>(grid, nodes, offset) != 0;
}

// The nodes of one level as the tree header declares them.
bool readNodeArray(uint64_t treeRelativeOffset,
    uint32_t count,
    uint64_t nodeSize,
    uint64_t gridSize,
    NodeArray &nodes)
{
  if (count == 0) {
    nodes = {};
    return true;
  }
  if (treeRelativeOffset > gridSize - kTreeOffset
      || treeRelativeOffset % NANOVDB_DATA_ALIGNMENT != 0)
    return false;
  nodes.begin = kTreeOffset + treeRelativeOffset;
  nodes.nodeSize = nodeSize;
  if (nodeSize == 0) {
    nodes.end = gridSize;
    return true;
  }
  // count < 2^32 and nodeSize < 2^20: no overflow.
  if (uint64_t(count) * nodeSize > gridSize - nodes.begin)
    return false;
  nodes.end = nodes.begin + uint64_t(count) * nodeSize;
  return true;
}

// Every child of every node in `parents` lands on a node of `children`.
template <typename BuildT, typename NodeT>
bool internalChildrenAreSound(
    const uint8_t *grid, const NodeArray &parents, const NodeArray &children)
{
  using Data = typename NodeT::DataType;
  for (uint64_t at = parents.begin; at < parents.end; at += parents.nodeSize) {
    const auto *node = reinterpret_cast<const Data *>(grid + at);
    for (auto child = node->mChildMask.beginOn(); child; ++child) {
      // Wrapping arithmetic: any wrapped value outside the array is caught.
      const uint64_t target = at + uint64_t(node->mTable[*child].child);
      if (!holdsNode<BuildT>(grid, children, target))
        return false;
    }
  }
  return true;
}

template <typename BuildT>
std::string whyTreeIsUnreadable(const uint8_t *grid, uint64_t gridSize)
{
  using Leaf = nanovdb::NanoLeaf<BuildT>;
  using Lower = nanovdb::NanoLower<BuildT>;
  using Upper = nanovdb::NanoUpper<BuildT>;
  using RootData = typename nanovdb::NanoRoot<BuildT>::DataType;
  using TreeData = nanovdb::TreeData<3>;
  if (gridSize - kTreeOffset < sizeof(TreeData))
    return "the grid is too small for its tree header";
  const auto *tree = reinterpret_cast<const TreeData *>(grid + kTreeOffset);

  const uint64_t rootOffset = tree->mNodeOffset[3];
  if (rootOffset > gridSize - kTreeOffset
      || rootOffset % NANOVDB_DATA_ALIGNMENT != 0
      || gridSize - kTreeOffset - rootOffset < sizeof(RootData))
    return "the root node lies outside the grid or is misaligned";
  const uint64_t rootAt = kTreeOffset + rootOffset;
  const auto *root = reinterpret_cast<const RootData *>(grid + rootAt);
  const uint64_t tableBytes =
      uint64_t(root->mTableSize) * sizeof(typename RootData::Tile);
  if (tableBytes > gridSize - rootAt - sizeof(RootData))
    return "the root's tile table runs past the grid's end";

  NodeArray upper, lower, leaves;
  const uint64_t leafSize = Leaf::DataType::FIXED_SIZE ? sizeof(Leaf) : 0;
  if (!readNodeArray(tree->mNodeOffset[2],
          tree->mNodeCount[2],
          sizeof(Upper),
          gridSize,
          upper)
      || !readNodeArray(tree->mNodeOffset[1],
          tree->mNodeCount[1],
          sizeof(Lower),
          gridSize,
          lower)
      || !readNodeArray(tree->mNodeOffset[0],
          tree->mNodeCount[0],
          leafSize,
          gridSize,
          leaves))
    return "a node array lies outside the grid or is misaligned";

  for (uint32_t n = 0; n < root->mTableSize; n++) {
    const auto *tile = root->tile(n);
    if (tile->child == 0)
      continue;
    const uint64_t target = rootAt + uint64_t(tile->child);
    if (!holdsNode<BuildT>(grid, upper, target))
      return "a root tile's child is not an upper node of the grid";
  }
  if (!internalChildrenAreSound<BuildT, Upper>(grid, upper, lower))
    return "an upper node's child is not a lower node of the grid";
  if (!internalChildrenAreSound<BuildT, Lower>(grid, lower, leaves))
    return "a lower node's child is not a leaf of the grid";
  return {};
}

// The map must be finite and invertible (index <-> object space).
bool isSoundMap(const nanovdb::Map &map)
{
  for (double v : map.mMatD)
    if (!std::isfinite(v))
      return false;
  for (double v : map.mVecD)
    if (!std::isfinite(v))
      return false;
  const double *m = map.mMatD;
  const double determinant = m[0] * (m[4] * m[8] - m[5] * m[7])
                             - m[1] * (m[3] * m[8] - m[5] * m[6])
                             + m[2] * (m[3] * m[7] - m[4] * m[6]);
  return std::isfinite(determinant) && std::abs(determinant) > 1e-300;
}

} // namespace

std::string whyNanoVdbGridIsUnreadable(const uint8_t *grid, uint64_t size)
{
  if (!grid || size < sizeof(nanovdb::GridData))
    return "the buffer is smaller than a NanoVDB grid header";
  const auto *header = reinterpret_cast<const nanovdb::GridData *>(grid);
  if (header->mMagic != NANOVDB_MAGIC_NUMBER)
    return "the buffer does not start with NanoVDB's magic number";
  if (header->mVersion.getMajor() != NANOVDB_MAJOR_VERSION_NUMBER) {
    return "NanoVDB major version "
           + std::to_string(header->mVersion.getMajor()) + " is not supported "
           + "(only " + std::to_string(NANOVDB_MAJOR_VERSION_NUMBER) + ")";
  }
  const uint64_t gridSize = header->mGridSize;
  if (gridSize > size || gridSize < kTreeOffset)
    return "the grid's size (" + std::to_string(gridSize)
           + " bytes) does not fit the buffer (" + std::to_string(size)
           + " bytes)";
  const auto gridClass = header->mGridClass;
  if (gridClass != nanovdb::GridClass::Unknown
      && gridClass != nanovdb::GridClass::LevelSet
      && gridClass != nanovdb::GridClass::FogVolume
      && gridClass != nanovdb::GridClass::VoxelVolume) {
    return std::string("grid class ")
        + (uint32_t(gridClass) < uint32_t(nanovdb::GridClass::End)
                ? nanovdb::toStr(gridClass)
                : "(corrupt)")
        + " is not a scalar field (accepted: unknown, level set, fog "
          "volume, voxel volume)";
  }
  if (!isSoundMap(header->mMap))
    return "the grid's map (index to world) is not finite and invertible";

  std::string why;
  const bool supported =
      visitNanoVdbGridType(header->mGridType, [&](auto buildType) {
        using BuildT = typename decltype(buildType)::type;
        why = whyTreeIsUnreadable<BuildT>(grid, gridSize);
      });
  if (!supported) {
    const auto type = header->mGridType;
    return std::string("grid type ")
           + (uint32_t(type) < uint32_t(nanovdb::GridType::End)
                   ? nanovdb::toStr(type)
                   : "(corrupt)")
           + " is not supported (accepted: " + kNanoVdbSupportedGridTypes + ")";
  }
  return why;
}

} // namespace prism
