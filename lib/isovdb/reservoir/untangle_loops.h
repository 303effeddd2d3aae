// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file untangle_loops.h
/// @brief After Marching Cubes on hexahedra (hex_marching_cubes.h): the loops of the cells
/// whose triangles cross others, fanned again where another fan crosses fewer.
///
/// A cell's triangles cover its loops (one fan per loop, from an apex on the loop or from a
/// centre vertex), chosen by how deep their diagonals stay in the cell. Between two thin
/// cells with twisted faces the surface can run almost along the face they share, and the
/// sheets on both sides, each inside its own cell at the diagonals, still crossed each
/// other between them (Reek: 29 pairs over 21 iso-values). The exact test of the result
/// settles it: any fan of a loop keeps its boundary, so the mesh stays closed, manifold and
/// consistently oriented whichever fan a loop takes.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "isovdb/mesh/mesh.h"

namespace isovdb::reservoir {

struct UntangleResult {
  std::int64_t pairsBefore = 0;  ///< self-intersecting pairs of the mesh as contoured
  std::int64_t pairsAfter = 0;   ///< and after the loops were fanned again
  std::int64_t loopsRefanned = 0;
  /// More pairs than 1,000 + 1 % of the triangles: the grid's cells fold over each other,
  /// which no fan undoes; nothing was fanned again.
  bool skipped = false;
  /// The pairs that remain (triangle indices of the final mesh, smaller first, sorted).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> remainingPairs;
};

/// Each loop (the boundary cycle of a cell's edge-connected triangles) of a cell that holds
/// a triangle of a self-intersecting pair is fanned from the apex whose triangles cross the
/// fewest triangles around the loop and each other (exact predicates), where that is
/// strictly fewer than its triangles now cross; else it stays. Cells are taken in index
/// order, each seeing the loops changed before it, for up to three passes while pairs
/// remain and a pass changed something: the result does not depend on the thread count.
/// Not tried where the pairs are too many (UntangleResult::skipped).
/// Vertices no triangle uses any more (centres of loops fanned from an apex) are removed,
/// with their normals. `triangleCells` (the cell of each triangle) stays aligned.
UntangleResult untangleLoops(mesh::Mesh& mesh, std::vector<std::uint32_t>& triangleCells);

}  // namespace isovdb::reservoir
