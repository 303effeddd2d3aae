// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file unit_edge_crossings.h
/// @brief The surface crossings of a meta-cell's bipolar unit edges, each found
///        once.
///
/// Every unit edge is shared by four 1-voxel cells, and each cell's dual vertex
/// reads the crossings of its bipolar edges: found cell by cell, every crossing
/// and its two Prewitt gradients were computed four times, a third of regular
/// contouring. Here they are found once, edge by edge, and looked up in O(1):
/// the bipolar edges of each row of samples are a bit mask (neighbouring phase
/// bits XORed), and an edge's index is the set bits before it (a prefix count
/// per 64-bit word plus a popcount), as Flying Edges indexes its edge cases.
/// The crossings are intersectEdge's, so the vertices are bit for bit the same; each
/// sample's Prewitt gradient is computed once too (a sample beside the surface ends two or
/// three bipolar edges).
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "isovdb/cell/cell_geometry.h"
#include "isovdb/cell/dual_vertex.h"
#include "isovdb/cell/edge_intersection.h"
#include "isovdb/cell/meta_cell_samples.h"
#include "isovdb/octree/sample_phases.h"

namespace isovdb::octree {

class UnitEdgeCrossings {
 public:
  /// @brief Finds the crossing of every bipolar unit edge of the cells of
  ///        [0, S]^3 (inside iff value <= iso), as cell::intersectEdge does.
  UnitEdgeCrossings(const cell::MetaCellSamples& samples, float iso, bool sharpFeatures);

  /// @brief The same from the samples' phases at `iso`, already computed (each block's
  ///        phases are read by the tree, this table and the error bound).
  UnitEdgeCrossings(const cell::MetaCellSamples& samples, const SamplePhases& phases, float iso, bool sharpFeatures);

  /// @brief The crossing on the unit edge from sample `start` (meta-cell
  ///        offsets) along `axis`, or nullptr if the edge is not bipolar.
  /// @pre the edge lies in [0, S]^3.
  const cell::EdgeIntersection* find(const std::array<int, 3>& start, int axis) const noexcept;

  /// @brief The crossing intersectEdge finds on the edge of `length` unit edges from
  ///        `start` along `axis` (meta-cell offsets): that of its first bipolar unit
  ///        edge, or nullptr if none is bipolar.
  /// @pre the edge lies in [0, S]^3.
  const cell::EdgeIntersection* findFirst(std::array<int, 3> start, int axis, int length) const noexcept;

  /// @brief True where the table pays for its memory: its bit rows (3 (S+1)^2 words per
  ///        64 samples along x, 12 bytes each) stay within a few hundred bytes per cell the
  ///        surface crosses, as on every meta-cell the surface really crosses; not for one
  ///        large block around a small surface (--meta-cell 0).
  static bool pays(int size, std::size_t surfaceCells) noexcept {
    return surfaceCells > 0 && bitRowWords(size) <= 24 * surfaceCells + 65536;
  }

  /// @brief True where the table's bit rows (3 (S+1)^2 words per 64 samples along x, 12
  ///        bytes each) take at most 16 MiB, as on meta-cells up to 256 voxels: worth
  ///        building before knowing how much surface the block holds.
  static bool smallEnough(int size) noexcept { return bitRowWords(size) * 12 <= (std::size_t{16} << 20); }

  /// Bipolar unit edges found.
  std::size_t size() const noexcept { return crossings_[0].size() + crossings_[1].size() + crossings_[2].size(); }

 private:
  /// Words of the bit rows for S = `size`: 3 axes, (S + 1)^2 rows, one word per 64 edge starts.
  static std::size_t bitRowWords(int size) noexcept {
    const auto s = static_cast<std::size_t>(size);
    return 3 * (s + 1) * (s + 1) * ((s + 64) / 64);
  }

  int size_ = 0;         // S
  int wordsPerRow_ = 0;  // 64-bit words per row of S + 1 edge starts along x
  // Per axis: bit i of row (j, k) is the edge from sample (i, j, k); the set bits
  // before each word; the crossings in row and bit order.
  std::array<std::vector<std::uint64_t>, 3> bipolar_;
  std::array<std::vector<std::uint32_t>, 3> before_;
  std::array<std::vector<cell::EdgeIntersection>, 3> crossings_;
};

/// @brief cell::computeDualVertex of the cell of `size` at `origin` (meta-cell offsets)
///        with these bipolar `edges`, its crossings read from `crossings` where there is a
///        table: the same vertex, bit for bit. A cell edge longer than a voxel whose ends
///        lie on opposite sides has intersectEdge's crossing, which is its first bipolar
///        unit edge's: the octree's coarse cells then compute no gradient of their own
///        (Prewitt gradients and their normals were a tenth of adaptive mode's run).
/// @pre `crossings` (if any) were found from `samples` at options.iso, with options.sharpFeatures.
inline cell::DualVertex cellDualVertex(const cell::MetaCellSamples& samples, const std::array<int, 3>& origin, int size,
                                       std::uint16_t edges, const cell::DualVertexOptions& options,
                                       const UnitEdgeCrossings* crossings) {
  if (crossings == nullptr) return cell::computeDualVertex(samples, origin, size, edges, options);
  if (size == 1)
    return cell::dualVertexOfCrossings(
        samples, origin, 1, edges, options,
        [&](const std::array<int, 3>& start, int axis) { return crossings->find(start, axis); });
  return cell::dualVertexOfCrossings(
      samples, origin, size, edges, options,
      [&](const std::array<int, 3>& start, int axis) -> const cell::EdgeIntersection* {
        std::array<int, 3> end = start;
        end[static_cast<std::size_t>(axis)] += size;
        if (cell::isInside(samples.value(start), options.iso) == cell::isInside(samples.value(end), options.iso))
          return nullptr;  // an even number of crossings: computeDualVertex takes none
        return crossings->findFirst(start, axis, size);
      });
}

/// @brief Where the surface crosses edge `e` of the cell of `size` at `origin` (meta-cell
///        offsets), in voxels from the edge's start corner; NaN where the samples show no
///        crossing. Read from `crossings` where there is a table (intersectEdge's point:
///        that of the edge's first bipolar unit edge, found once), else intersectEdge.
/// @pre `crossings` (if any) were found from `samples` at `iso`, with `sharpFeatures`.
inline double leafEdgeCrossing(const cell::MetaCellSamples& samples, const std::array<int, 3>& origin, int size, int e,
                               float iso, bool sharpFeatures, const UnitEdgeCrossings* crossings) {
  const int axis = cell::cellEdgeAxis(e);
  const std::array<int, 3> start = cell::cellEdgeStart(origin, size, e);
  cell::EdgeIntersection ix;
  const cell::EdgeIntersection* hit = &ix;
  if (crossings != nullptr)
    hit = crossings->findFirst(start, axis, size);
  else if (!cell::intersectEdge(samples, start, axis, size, iso, ix, sharpFeatures))
    hit = nullptr;
  if (hit == nullptr) return std::numeric_limits<double>::quiet_NaN();
  return static_cast<double>(hit->point[static_cast<std::size_t>(axis)] -
                             static_cast<float>(start[static_cast<std::size_t>(axis)]));
}

}  // namespace isovdb::octree
