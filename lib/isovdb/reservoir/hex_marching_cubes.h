// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file hex_marching_cubes.h
/// @brief Marching Cubes on the hexahedra of a corner-point grid, in each
/// cell's trilinear parameter space (paper 003 §5).
///
/// Each face is cut into segments from its own four corner values; a face
/// with four crossings is resolved with the asymptotic decider (the sign of
/// the bilinear saddle), so the two cells sharing a face always agree and the
/// surface has no holes between them. The segments of a cell's six faces form
/// closed loops, each triangulated as a fan from a vertex whose diagonals
/// cross the cell (never along a face, where the neighbour's fan could put the
/// same edge), or around a centre vertex when no such vertex exists. Vertices
/// lie on cell edges and are keyed by the edge's two geometric points, so
/// cells that touch share them (indexed, welded mesh); cells across a fault do not. Triangles face
/// lower values (the normal points out of the region above the iso-value) in
/// world space whatever the grid's handedness. Where a face lies on a fault (the cell
/// across holds other points there), the sheets of both sides end on the same pillar
/// plane and would cross: the vertices on such faces move a hundredth of the way to their
/// own cells' centres. Where a segment's chord would run far off its face's bilinear
/// patch (thin, twisted layers), it runs through a face point on the patch, which both
/// cells share (hex_cell_contour.cc, kFaceWarp). Cells run in parallel (TBB);
/// the output does not depend on the thread count.
#pragma once

#include <cstdint>

#include "isovdb/mesh/mesh.h"
#include "isovdb/progress.h"
#include "isovdb/reservoir/corner_point_grid.h"

namespace isovdb::reservoir {

struct HexContourOptions {
  double iso = 0.0;
  /// Per-vertex normals from the Jacobian-mapped gradient (jacobian_normals.h).
  bool normals = true;
  /// HexContourResult::triangleCells: the cell that made each triangle.
  bool triangleCells = false;
};

struct HexContourResult {
  mesh::Mesh mesh;                           ///< world (file) coordinates
  std::int64_t cutCells = 0;                 ///< usable cells the surface crosses
  std::int64_t ambiguousFaces = 0;           ///< faces resolved by the asymptotic decider (counted per cell)
  std::int64_t faultVertices = 0;            ///< vertices moved off fault faces into their own side
  std::int64_t cancelledTwins = 0;           ///< pairs of opposed triangles in a face, dropped (cancelOpposedTwins)
  std::int64_t facePoints = 0;               ///< vertices on twisted faces between two crossings (hex_cell_contour.cc)
  std::vector<std::uint32_t> triangleCells;  ///< with HexContourOptions::triangleCells: per triangle, its cell
};

/// @param interrupter  progress per group of cell blocks ("marching cubes") and cancellation
///                     (throws Interrupted); may be null.
HexContourResult contourHexahedra(const CornerPointGrid& grid, const CornerField& field,
                                  const HexContourOptions& options = {}, Interrupter* interrupter = nullptr);

}  // namespace isovdb::reservoir
