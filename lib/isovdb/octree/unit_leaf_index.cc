// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/octree/unit_leaf_index.h"

#include "isovdb/bit_count.h"
#include "isovdb/cell/cell_geometry.h"

namespace isovdb::octree {

UnitLeafIndex::UnitLeafIndex(const LinearOctree& tree)
    : tree_(tree), size_(tree.metaCellSize()), wordsPerRow_((tree.metaCellSize() + 63) / 64) {
  const std::size_t words =
      static_cast<std::size_t>(size_) * static_cast<std::size_t>(size_) * static_cast<std::size_t>(wordsPerRow_);
  rows_.assign(words, 0);
  before_.assign(words, 0);
  const auto wordOf = [&](const std::array<int, 3>& v) {
    return (static_cast<std::size_t>(v[2]) * static_cast<std::size_t>(size_) + static_cast<std::size_t>(v[1])) *
               static_cast<std::size_t>(wordsPerRow_) +
           static_cast<std::size_t>(v[0] >> 6);
  };
  std::size_t count = 0;
  for (const OctreeLeaf& l : tree.leaves())
    if (l.size == 1) {
      rows_[wordOf(l.origin)] |= std::uint64_t{1} << (l.origin[0] & 63);
      ++count;
    }
  std::uint32_t total = 0;
  for (std::size_t w = 0; w < words; ++w) {
    before_[w] = total;
    total += static_cast<std::uint32_t>(countBits(rows_[w]));
  }
  leafOfRank_.assign(count, 0);
  for (std::size_t i = 0; i < tree.leafCount(); ++i) {
    const OctreeLeaf& l = tree.leaf(i);
    if (l.size != 1) continue;
    const std::size_t w = wordOf(l.origin);
    const std::uint64_t below = (std::uint64_t{1} << (l.origin[0] & 63)) - 1;
    leafOfRank_[before_[w] + static_cast<std::uint32_t>(countBits(rows_[w] & below))] = static_cast<std::uint32_t>(i);
  }
}

std::int64_t UnitLeafIndex::findLeafContainingVoxel(const std::array<int, 3>& voxel) const noexcept {
  for (int a = 0; a < 3; ++a)
    if (voxel[a] < 0 || voxel[a] >= size_) return LinearOctree::kNone;
  const std::size_t w =
      (static_cast<std::size_t>(voxel[2]) * static_cast<std::size_t>(size_) + static_cast<std::size_t>(voxel[1])) *
          static_cast<std::size_t>(wordsPerRow_) +
      static_cast<std::size_t>(voxel[0] >> 6);
  const std::uint64_t bit = std::uint64_t{1} << (voxel[0] & 63);
  if ((rows_[w] & bit) == 0) return tree_.findLeafContainingVoxel(voxel);  // a larger leaf, or none
  return leafOfRank_[before_[w] + static_cast<std::uint32_t>(countBits(rows_[w] & (bit - 1)))];
}

std::array<std::int64_t, 4> UnitLeafIndex::leavesAroundEdge(const std::array<int, 3>& start, int axis) const noexcept {
  std::array<std::int64_t, 4> result{};
  for (int q = 0; q < 4; ++q)
    result[static_cast<std::size_t>(q)] = findLeafContainingVoxel(cell::edgeQuadrantVoxel(start, axis, q));
  return result;
}

}  // namespace isovdb::octree
