// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file regular_contour.h
/// @brief Regular mode: Dual Marching Cubes with Wenger's manifold fix (MDMC)
///        on the regular-construction octree of one meta-cell (paper 000,
///        section 4.2.3.1 and Algorithm 4.1; paper 003, section 3.3.2).
///
/// Every surface leaf of a regular octree is at the maximum depth, so every
/// interior bipolar edge is shared by exactly four leaves of the same size.
/// Each surface leaf gets up to four dual vertices (dmc_table.h), each placed
/// by the QEF of its own edge group (mass point when the QEF minimiser leaves
/// the cell; always inside the cell). Each interior bipolar edge makes one
/// quad of the four vertices that the table assigns to that edge, split into
/// two triangles along the diagonal with the better-shaped triangles. Every
/// edge is emitted once, by its owner: the leaf for which it is the cell edge
/// at the min corner of the two other axes (the leaf on the +u,+v side).
///
/// Sign convention: a sample is inside iff value <= iso (an exact-iso sample
/// counts as inside everywhere, which keeps the output manifold). Triangles
/// are oriented with their normals pointing from inside to outside.
///
/// Meta-cell boundary: edges with fewer than four leaves around them (on the
/// meta-cell's boundary faces) are skipped; contourRegularMetaCell keeps the
/// leaves around them as SeamCells for stitch/ (seam_cell.h), which contours
/// them with regularEdgeQuad, the same routine. Wenger's fix looks at the
/// neighbour cell across the meta-cell boundary through the samples' apron
/// (give an apron of at least the finest cell size), so a cell's grouping is
/// final when its meta-cell is contoured.
///
/// Output: positions in global voxel index coordinates, shared (indexed)
/// vertices, no normals. Parallel with TBB and deterministic: the result
/// depends only on the inputs, not on the thread count. Memory: O(leaves) plus
/// the mesh.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "isovdb/contour/seam_cell.h"
#include "isovdb/contour/voxel_dmc.h"
#include "isovdb/mesh/mesh.h"
#include "isovdb/octree/linear_octree.h"
#include "isovdb/octree/sample_phases.h"
#include "isovdb/cell/contour_settings.h"
#include "isovdb/cell/meta_cell_samples.h"

namespace isovdb::contour {

/// Figures of one contourRegular call.
struct RegularContourStats {
  std::int64_t cells = 0;             ///< surface leaves that received dual vertices
  std::int64_t vertices = 0;          ///< dual vertices (= mesh positions)
  std::int64_t quads = 0;             ///< interior bipolar edges contoured (two triangles each; voxels: 2-6)
  std::int64_t manifoldFixes = 0;     ///< cells that used Wenger's alternative grouping (voxels: split faces)
  std::int64_t tubeCells = 0;         ///< voxels: cells joining two body-diagonal inside corners by a tube
  std::int64_t seamCells = 0;         ///< leaves kept for stitching (touch the boundary, have dual vertices)
  std::int64_t boundaryEdges = 0;     ///< bipolar edges left to stitching (on the meta-cell boundary)
  std::int64_t fixesBeyondApron = 0;  ///< doubled faces on the boundary whose neighbour lies beyond the
                                      ///< samples' apron (left unfixed; 0 with an apron >= the finest cell)

  /// Sums the figures of several meta-cells.
  RegularContourStats& operator+=(const RegularContourStats& o) noexcept {
    cells += o.cells;
    vertices += o.vertices;
    quads += o.quads;
    manifoldFixes += o.manifoldFixes;
    tubeCells += o.tubeCells;
    seamCells += o.seamCells;
    boundaryEdges += o.boundaryEdges;
    fixesBeyondApron += o.fixesBeyondApron;
    return *this;
  }
};

/// @brief Contours one meta-cell's regular octree with manifold Dual Marching Cubes.
/// @param[in] samples the meta-cell's dense samples.
/// @param[in] regularTree octree built from `samples` with the same settings (method Regular).
/// @param[in] settings isovalue, reading of ambiguous cells (topology), manifold fix, QEF truncation.
/// @param[out] stats optional figures.
/// @return the mesh: closed and manifold wherever the surface stays off the meta-cell boundary.
/// @pre every leaf whose corners differ in sign has the same size as the leaves around its bipolar edges
///      (true for a regular construction).
/// @throw InputError if `samples.size` differs from the tree's meta-cell size or a leaf's corner
///        signs differ from the samples at `settings.iso` (tree built with another isovalue).
mesh::Mesh contourRegular(const cell::MetaCellSamples& samples, const octree::LinearOctree& regularTree,
                          const cell::ContourSettings& settings, RegularContourStats* stats = nullptr);

/// @brief contourRegular plus the seam: the leaves with dual vertices that touch
///        the meta-cell boundary, in key order (see seam_cell.h). `phases` (optional):
///        the samples' phases at settings.iso, computed here where needed without them.
MetaCellMesh contourRegularMetaCell(const cell::MetaCellSamples& samples, const octree::LinearOctree& regularTree,
                                    const cell::ContourSettings& settings, RegularContourStats* stats = nullptr,
                                    const octree::SamplePhases* phases = nullptr);

/// @brief The two triangles of one bipolar edge's quad (Algorithm 4.1), oriented
///        outward, split along the diagonal whose worse triangle is better shaped.
/// @param vertices   the four cells' vertex ids by quadrant (bit 0 = +u, bit 1 = +v)
/// @param positions  their positions
/// @param axis       the edge's axis
/// @param minEndInside the edge's min end is inside (value <= iso)
std::array<mesh::Triangle, 2> regularEdgeQuad(const std::array<std::uint32_t, 4>& vertices,
                                              const std::array<mesh::Vec3f, 4>& positions, int axis,
                                              bool minEndInside) noexcept;

/// A dual vertex as one cell gives it to an edge: its mesh id and position.
struct EdgeVertex {
  std::uint32_t id = kNoVertex;
  mesh::Vec3f position{};
};

/// @brief Regular mode's quad of one bipolar edge, the same inside a meta-cell and on a
///        seam: `vertexOfCell(q)` gives the vertex cell q around the edge (quadrant as in
///        regularEdgeQuad) has for it, or std::nullopt when that cell is missing.
/// @return false, with nothing appended, when a cell is missing.
template <typename VertexOfCell>
bool appendRegularEdgeQuad(VertexOfCell&& vertexOfCell, int axis, bool minEndInside, std::vector<mesh::Triangle>& out) {
  std::array<std::uint32_t, 4> ids{};
  std::array<mesh::Vec3f, 4> positions{};
  for (int q = 0; q < 4; ++q) {
    const std::optional<EdgeVertex> vertex = vertexOfCell(q);
    if (!vertex) return false;
    ids[static_cast<std::size_t>(q)] = vertex->id;
    positions[static_cast<std::size_t>(q)] = vertex->position;
  }
  const auto triangles = regularEdgeQuad(ids, positions, axis, minEndInside);
  out.insert(out.end(), triangles.begin(), triangles.end());
  return true;
}

}  // namespace isovdb::contour
