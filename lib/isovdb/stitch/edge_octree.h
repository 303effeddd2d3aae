// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file edge_octree.h
/// @brief The edge-octree of one seam: the kept cells of the meta-cells around
///        a meta-face (2) or a meta-edge (4) merged into one partial linear
///        octree by prefixing their Morton keys with their meta-cell's position
///        bits (paper 000, section 4.3, Table 4.1 and Fig. 4.10–4.11).
///
/// The seam's reference meta-cell R = (i, j, k) is the one with the smallest
/// index; a neighbour R + (dx, dy, dz), each d in {0, 1}, gets octant
/// dx | dy << 1 | dz << 2 (Table 4.1: B_{i+1,j,k} -> 001, B_{i,j+1,k} -> 010,
/// B_{i,j,k+1} -> 100). A cell with key 1 b under its meta-cell gets the key
/// 1 o b: one level deeper, in a root cube of 2S voxels whose origin is R's.
/// The tree is partial (only cells touching the seam), which LinearOctree's
/// lookups allow: a place without a cell reads as kNone.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "isovdb/contour/seam_cell.h"
#include "isovdb/octree/linear_octree.h"

namespace isovdb::stitch {

using MetaCellIndex = std::array<int, 3>;

/// One seam: a meta-face (`axis` = its normal, 2 meta-cells) or a meta-edge
/// (`axis` = its direction, 4 meta-cells), given by its reference meta-cell.
struct Seam {
  enum class Kind { Face, Edge };
  Kind kind = Kind::Face;
  MetaCellIndex reference{0, 0, 0};
  int axis = 0;

  /// Octants (relative positions) of the meta-cells around the seam.
  std::vector<int> octants() const;
  /// True if the edge at `start` (edge-octree offsets) along `edgeAxis` is one this
  /// seam contours: on the meta-face but off its border (Face), or on the meta-edge (Edge).
  bool ownsEdge(const std::array<int, 3>& start, int edgeAxis, int metaCellSize) const noexcept;
  /// True if the cell [origin, origin + size] (edge-octree offsets) touches the seam.
  bool touches(const std::array<int, 3>& origin, int size, int metaCellSize) const noexcept;
};

/// @brief Key of a cell of the meta-cell at `octant` in its seam's edge-octree (Table 4.1).
octree::MortonKey prefixKey(octree::MortonKey key, int octant) noexcept;

/// The partial octree of one seam and, per leaf, the kept cell it came from.
struct EdgeOctree {
  octree::LinearOctree tree;
  std::vector<contour::SeamCell*> cells;  ///< indexed like tree.leaves()
};

/// @brief Builds the edge-octree of `seam` from the kept cells of the meta-cells
///        around it (`around[i]` belongs to octant `seam.octants()[i]`; null if absent).
/// @param metaCellSize S.
EdgeOctree buildEdgeOctree(const Seam& seam, const std::vector<std::vector<contour::SeamCell>*>& around,
                           int metaCellSize);

}  // namespace isovdb::stitch
