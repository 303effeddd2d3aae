// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file stitch_seams.h
/// @brief Closes the mesh between meta-cells: for every meta-face and meta-edge
///        between contoured meta-cells, the edge-octree of their kept cells
///        (edge_octree.h) is contoured on the edges the meta-cells left out, by
///        the same per-edge routines as inside a meta-cell (regularEdgeQuad,
///        collectMinimalEdges / emitEdgeRecord) (paper 000, section 4.3).
///
/// Every sign-changing edge of the grid lies either inside one meta-cell, on a
/// meta-face (2 meta-cells) or on a meta-edge (4); meta-vertices hold no edge.
/// Edges on a meta-face's border belong to the meta-edge's seam, so each edge
/// is contoured exactly once. Where eight meta-cells meet, the twelve
/// meta-faces and six meta-edges around the meta-vertex are ordinary seams.
///
/// Deterministic: seams are visited by reference meta-cell in (z, y, x) order,
/// its meta-faces on +x, +y, +z first, then its meta-edges along x, y, z; new
/// vertices get ids in that order, whatever the number of threads. Memory: the kept cells (they follow the
/// surface's intersection with the meta-faces) plus one seam's edge-octree.
#pragma once

#include <array>
#include <cstdint>
#include <map>

#include "isovdb/cell/contour_settings.h"
#include "isovdb/contour/seam_cell.h"
#include "isovdb/contour/voxel_dmc.h"
#include "isovdb/mesh/mesh.h"
#include "isovdb/progress.h"
#include "isovdb/stitch/edge_octree.h"

namespace isovdb::stitch {

/// Kept cells of every contoured meta-cell, by meta-cell index (ordered z, y, x).
class SeamStore {
 public:
  /// Adds meta-cell `index`'s seam (ids already final, see contour::rebaseSeam).
  void add(const MetaCellIndex& index, contour::MetaCellSeam seam);
  /// The seam of `index`, or null.
  contour::MetaCellSeam* find(const MetaCellIndex& index);
  std::size_t metaCellCount() const noexcept { return seams_.size(); }
  std::size_t cellCount() const noexcept { return cells_; }
  /// Meta-cells in order (z, y, x).
  const std::map<std::array<int, 3>, contour::MetaCellSeam>& byZyx() const noexcept { return seams_; }

 private:
  std::map<std::array<int, 3>, contour::MetaCellSeam> seams_;  // key (k, j, i)
  std::size_t cells_ = 0;
};

struct StitchStats {
  std::int64_t metaFaces = 0;     ///< meta-face seams contoured (both meta-cells present)
  std::int64_t metaEdges = 0;     ///< meta-edge seams contoured (all four present)
  std::int64_t seamCells = 0;     ///< kept cells over all meta-cells
  std::int64_t edges = 0;         ///< sign-changing edges contoured by the stitcher
  std::int64_t fannedEdges = 0;   ///< adaptive: of them, with a Ju–Udeshi fan
  std::int64_t missingCells = 0;  ///< edges skipped because a cell around was not kept (must stay 0)
};

/// @brief Contours every seam of `store` with the per-edge routine of the method the
///        meta-cells used (settings.method; regular: settings.topology; adaptive:
///        settings.intersectionFree).
/// @param store  the kept cells; adaptive vertices added here are recorded in them.
/// @param metaCellSize  S of the partition.
/// @param vertexBase  number of vertices already in the output: new vertices get ids from there.
/// @param[out] out  new vertices (ids vertexBase + index) and every stitched triangle.
void stitchSeams(SeamStore& store, const cell::ContourSettings& settings, int metaCellSize, std::uint32_t vertexBase,
                 mesh::Mesh& out, StitchStats* stats = nullptr, Interrupter* interrupter = nullptr);

}  // namespace isovdb::stitch
