// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file unit_leaf_index.h
/// @brief Constant-time lookup of a LinearOctree's 1-voxel leaves by position.
///
/// Regular contouring finds the four cells around each bipolar edge, millions of
/// lookups per volume, and its cells are 1-voxel leaves. A binary search in Z
/// order misses the cache on every neighbour across y or z (they lie far apart
/// in Z order) and was a tenth of regular mode's time. Here each row of cells
/// along x is a bit mask; a leaf's rank in row order is the set bits before it
/// (a prefix count per 64-bit word plus a popcount), and a table maps the rank
/// to the leaf's index in Z order. The masks of neighbouring rows are close in
/// memory.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "isovdb/octree/linear_octree.h"

namespace isovdb::octree {

class UnitLeafIndex {
 public:
  /// @brief Indexes the 1-voxel leaves of `tree` (kept by reference for the other leaves).
  explicit UnitLeafIndex(const LinearOctree& tree);

  /// @brief True where the index pays for its memory: its bit rows (S^2 words per 64 cells
  ///        along x) take no more than a few words per leaf of the tree, as on every
  ///        meta-cell; not for one large block around a thin surface (--meta-cell 0).
  static bool pays(int size, std::size_t leaves) noexcept {
    const auto s = static_cast<std::size_t>(size);
    return s * s * ((s + 63) / 64) <= 8 * leaves + 4096;
  }

  /// @brief tree.findLeafContainingVoxel(voxel), in constant time where a 1-voxel leaf lies.
  std::int64_t findLeafContainingVoxel(const std::array<int, 3>& voxel) const noexcept;

  /// @brief tree.leavesAroundEdge(start, axis), with these lookups.
  std::array<std::int64_t, 4> leavesAroundEdge(const std::array<int, 3>& start, int axis) const noexcept;

 private:
  const LinearOctree& tree_;
  int size_ = 0;                           // S
  int wordsPerRow_ = 0;                    // 64-bit words per row of S cells
  std::vector<std::uint64_t> rows_;        // bit x of row (y, z): a 1-voxel leaf at (x, y, z)
  std::vector<std::uint32_t> before_;      // set bits before each word
  std::vector<std::uint32_t> leafOfRank_;  // row-order rank -> leaf index (Z order)
};

}  // namespace isovdb::octree
