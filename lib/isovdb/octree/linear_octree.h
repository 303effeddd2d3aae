// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file linear_octree.h
/// @brief The linear (pointerless) octree of one meta-cell: its leaves sorted in
///        Z order, found by binary search on Morton keys (paper 000, section 4.2.1).
///
/// Leaves tile the meta-cell cube [0, S]^3 completely (surface leaves and empty
/// ones). Positions are meta-cell offsets in voxels (voxel index space minus
/// the meta-cell origin); add origin() for global index coordinates.
/// Levels are both a depth under the meta-cell (root = 0) and a cell size in
/// voxels: size = S >> depth.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "isovdb/octree/morton.h"

namespace isovdb::octree {

/// @brief Cell side in voxels at `depth` in a meta-cell of `metaCellSize` voxels.
constexpr int cellSizeAtDepth(int metaCellSize, int depth) noexcept { return metaCellSize >> depth; }

/// @brief Depth whose cells are `cellSize` voxels wide (both powers of two, cellSize <= metaCellSize).
constexpr int depthForCellSize(int metaCellSize, int cellSize) noexcept {
  return std::bit_width(static_cast<unsigned>(metaCellSize)) - std::bit_width(static_cast<unsigned>(cellSize));
}

/// @brief True if the cell [origin, origin + size] touches the boundary of the
///        meta-cell [0, metaCellSize]^3 (meta-cell offsets): the seam, which is stitched
///        later, with the neighbouring block's cells.
constexpr bool touchesMetaCellBoundary(const std::array<int, 3>& origin, int size, int metaCellSize) noexcept {
  for (std::size_t a = 0; a < 3; ++a)
    if (origin[a] == 0 || origin[a] + size == metaCellSize) return true;
  return false;
}

/// @brief One leaf cell.
struct OctreeLeaf {
  MortonKey key = kInvalidKey;         ///< Morton key (root = 1)
  std::array<int, 3> origin{0, 0, 0};  ///< min corner, meta-cell offsets in voxels
  int size = 0;                        ///< side in voxels (S >> depth)
  std::uint8_t depth = 0;              ///< depth under the meta-cell root
  std::uint8_t cornerSigns = 0;        ///< bit c set iff corner c is inside (value <= iso); corner bits as octants
  bool surface = false;                ///< the surface crosses the leaf (its samples are not all one phase)
  bool complex = false;                ///< still topologically complex (only at the maximum depth)
  /// The dual vertex the adaptive construction's geometric criterion placed (QEF of
  /// all bipolar edges, global voxel index coordinates), which contouring reuses.
  std::array<float, 3> vertex{0.0f, 0.0f, 0.0f};
  float vertexTruncation = -1.0f;    ///< QEF truncation `vertex` was placed with; < 0: none placed
  bool vertexSharpFeatures = false;  ///< `vertex` was placed with sharp features (crease_crossing.h)

  /// Edges whose two corners differ in sign (bit e, numbering of morton.h).
  std::uint16_t bipolarEdges() const noexcept { return bipolarEdgeMask(cornerSigns); }
};

/// @brief Linear octree of one meta-cell.
///
/// Lookups are O(log n) binary searches on the Z-order codes of the leaves;
/// neighbours are found by key arithmetic (neighbourKey) followed by a lookup,
/// never by scanning or pointer chasing.
class LinearOctree {
 public:
  /// Returned by lookups that find no leaf.
  static constexpr std::int64_t kNone = -1;

  LinearOctree() = default;
  /// @brief Takes leaves in any order and sorts them in Z order.
  /// @param metaCellSize S (power of two).
  /// @param metaCellOrigin global index coordinate of the meta-cell's min corner.
  /// @param partial false: the leaves tile the meta-cell cube exactly (checked with
  ///        assert only); true: they need not (a seam's edge-octree, stitch/), and
  ///        lookups where no leaf lies return kNone.
  LinearOctree(int metaCellSize, std::array<int, 3> metaCellOrigin, std::vector<OctreeLeaf> leaves,
               bool partial = false);

  int metaCellSize() const noexcept { return size_; }
  /// Depth of 1-voxel cells, log2(S).
  int finestDepth() const noexcept { return finestDepth_; }
  const std::array<int, 3>& origin() const noexcept { return origin_; }

  /// Leaves in Z order (pre-order of the tree).
  const std::vector<OctreeLeaf>& leaves() const noexcept { return leaves_; }
  std::size_t leafCount() const noexcept { return leaves_.size(); }
  const OctreeLeaf& leaf(std::size_t index) const noexcept { return leaves_[index]; }

  /// @brief Index of the leaf whose key is exactly `key`, or kNone.
  std::int64_t findLeaf(MortonKey key) const noexcept;
  /// @brief Index of the leaf equal to `key` or an ancestor of it; kNone if
  ///        `key` is an internal node (subdivided further) or invalid.
  std::int64_t findLeafContaining(MortonKey key) const noexcept;
  /// @brief Index of the leaf containing the unit cell `voxel` (each in [0, S)); kNone outside.
  std::int64_t findLeafContainingVoxel(std::array<int, 3> voxel) const noexcept;
  /// @brief Index of the leaf containing `point` (meta-cell offsets, each in [0, S]);
  ///        points on a shared face go to the leaf on the max side (clamped at S).
  std::int64_t findLeafContaining(std::array<float, 3> point) const noexcept;

  /// @brief Leaves across face f (= 2 * axis + side) of leaf `index`: one leaf of
  ///        the same size or coarser, or the finer leaves touching that face, in Z order.
  ///        Empty at the meta-cell boundary.
  void leavesAcrossFace(std::size_t index, int face, std::vector<std::size_t>& out) const;

  /// @brief The (up to) 4 leaves around the unit edge segment that starts at
  ///        `start` (integer meta-cell offsets) along `axis`. Entry q has the
  ///        min side (bit clear) or max side (bit set) on the two other axes
  ///        u < v: bit 0 -> u, bit 1 -> v. An entry is kNone outside the
  ///        meta-cell; a coarser leaf appears in 2 entries (3 distinct leaves).
  /// @pre 0 <= start[axis] < S.
  std::array<std::int64_t, 4> leavesAroundEdge(std::array<int, 3> start, int axis) const noexcept;

  /// @brief Min corner (meta-cell offsets) and side of any key's cell.
  std::array<int, 3> cellOrigin(MortonKey key) const noexcept;
  int cellSize(MortonKey key) const noexcept { return size_ >> keyDepth(key); }

 private:
  int size_ = 0;
  int finestDepth_ = 0;
  std::array<int, 3> origin_{0, 0, 0};
  std::vector<OctreeLeaf> leaves_;
  std::vector<std::uint64_t> codes_;  // zOrderCode of each leaf at finestDepth_, ascending
  // The first leaf whose code >> bucketShift_ is at least b, for every b (and one past
  // the end): a lookup binary-searches one bucket (about one leaf) instead of all
  // leaves, which was a tenth of regular contouring's time.
  std::vector<std::uint32_t> bucketStart_;
  int bucketShift_ = 0;
};

}  // namespace isovdb::octree
