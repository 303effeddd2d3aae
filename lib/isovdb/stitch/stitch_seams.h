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
/// vertices get ids in that order, whatever the number of threads. Memory: about two
/// layers of kept cells (they follow the surface's intersection with the meta-faces),
/// the stitched mesh, and one seam's edge-octree.
#pragma once

#include <array>
#include <cstdint>
#include <map>

#include "isovdb/cell/contour_settings.h"
#include "isovdb/contour/adaptive_edges.h"
#include "isovdb/contour/seam_cell.h"
#include "isovdb/contour/voxel_dmc.h"
#include "isovdb/mesh/mesh.h"
#include "isovdb/progress.h"
#include "isovdb/stitch/edge_octree.h"

namespace isovdb::stitch {

/// Kept cells of contoured meta-cells, by meta-cell index (ordered z, y, x).
class SeamStore {
 public:
  /// Adds meta-cell `index`'s seam (ids already final, see contour::rebaseSeam).
  void add(const MetaCellIndex& index, contour::MetaCellSeam seam);
  /// The seam of `index`, or null.
  contour::MetaCellSeam* find(const MetaCellIndex& index);
  /// Drops the seams of the meta-cells whose z index is below `z`.
  void dropBelow(int z);
  std::size_t metaCellCount() const noexcept { return seams_.size(); }
  /// Kept cells added over the store's life, and held now.
  std::size_t cellCount() const noexcept { return cells_; }
  std::size_t heldCellCount() const noexcept { return held_; }
  /// Meta-cells in order (z, y, x).
  const std::map<std::array<int, 3>, contour::MetaCellSeam>& byZyx() const noexcept { return seams_; }

 private:
  std::map<std::array<int, 3>, contour::MetaCellSeam> seams_;  // key (k, j, i)
  std::size_t cells_ = 0, held_ = 0;
};

struct StitchStats {
  std::int64_t metaFaces = 0;      ///< meta-face seams contoured (both meta-cells present)
  std::int64_t metaEdges = 0;      ///< meta-edge seams contoured (all four present)
  std::int64_t seamCells = 0;      ///< kept cells over all meta-cells
  std::int64_t edges = 0;          ///< sign-changing edges contoured by the stitcher
  std::int64_t fannedEdges = 0;    ///< adaptive: of them, with a Ju–Udeshi fan
  std::int64_t missingCells = 0;   ///< edges skipped because a cell around was not kept (must stay 0)
  std::int64_t peakHeldCells = 0;  ///< the most kept cells held at once
};

/// @brief Contours the seams with the per-edge routine of the method the meta-cells used
///        (settings.method; regular: settings.topology; adaptive: settings.intersectionFree),
///        as their meta-cells arrive.
///
/// The seams of a reference meta-cell in z-layer r read layers r and r + 1 only, so
/// when a meta-cell of layer z arrives (meta-cells arrive in (z, y, x) order), every
/// seam whose reference lies below z - 1 is stitched and the kept cells below z - 1 are
/// dropped: the stitcher holds about two layers of kept cells, whatever the volume's
/// depth. The vertices it adds must follow every meta-cell's in the output, whose count
/// is known only at the end: they get provisional ids (from 2^31) that finish() moves
/// to `vertexBase`. The visiting order, hence the mesh, is that of stitching every seam
/// at the end.
class SeamStitcher {
 public:
  /// @param metaCellSize S of the partition.
  SeamStitcher(const cell::ContourSettings& settings, int metaCellSize);
  /// Adds meta-cell `index`'s seam (ids final, below 2^31) and stitches what it completes.
  /// @pre meta-cells arrive in (z, y, x) order.
  void add(const MetaCellIndex& index, contour::MetaCellSeam seam);
  /// Stitches the remaining seams and appends the vertices added (ids from `vertexBase`,
  /// the output's vertex count) and every stitched triangle to `out`.
  /// @throw InputError when the output would pass 2^31 vertices.
  void finish(std::uint32_t vertexBase, mesh::Mesh& out, Interrupter* interrupter = nullptr);
  const StitchStats& stats() const noexcept { return stats_; }
  const cell::ContourSettings& settings() const noexcept { return settings_; }

 private:
  /// Stitches the seams of every kept reference meta-cell whose z index is below `z`.
  void stitchBelow(int z, Interrupter* interrupter);

  cell::ContourSettings settings_;
  int metaCellSize_;
  SeamStore store_;
  contour::FaceVertexMap faceVertices_;  ///< adaptive: face points already mesh vertices
  mesh::Mesh tail_;                      ///< the stitcher's vertices and triangles, provisional ids
  StitchStats stats_;
  int stitchedBelow_;  ///< reference meta-cells below this z are stitched
  int lastZ_;          ///< z index of the latest meta-cell added
};

}  // namespace isovdb::stitch
