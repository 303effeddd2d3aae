// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file adaptive_contour.h
/// @brief Adaptive mode: dual contouring of a meta-cell's octree on minimal
///        edges (Ju et al. 2002), made intersection-free with the fans of
///        Ju & Udeshi 2006 (paper 000, section 4.2.3.2; Tables 5.1–5.2).
///
/// One dual vertex per surface leaf and DMC group (QEF, kept strictly inside its cell).
/// Every sign-changing minimal edge (an edge of a leaf that contains no
/// smaller leaf edge) gives a polygon through the vertices of the leaves
/// around it: 4 leaves make a quad, 3 leaves (one of them coarser) a triangle.
/// The leaves are found by Morton-key neighbour arithmetic plus binary search
/// (LinearOctree::leavesAroundEdge), never by scanning. With
/// `intersectionFree`, each polygon whose trivial triangulation leaves the
/// edge's envelope is replaced by the fan through the edge point v_e, the face
/// points v_f and the cell vertices v_c (ju_udeshi.h).
///
/// Meta-cell boundary: an edge with fewer leaves around it than needed (it lies
/// on the meta-cell's boundary, LinearOctree returns kNone) is skipped and
/// counted in AdaptiveContourStats::boundaryEdges; contourAdaptiveMetaCell
/// keeps the leaves around such edges (and the face points made on faces that
/// touch the boundary) for stitch/, which contours them with the same per-edge
/// routine (adaptive_edges.h).
///
/// Topology: one vertex per leaf would let a minimal face whose four corners
/// alternate in sign (an ambiguous face, 4 bipolar edges) make its two cells'
/// vertices share 4 polygons: a non-manifold edge. So a leaf has one vertex per
/// Dual Marching Cubes group of its configuration, with Wenger's fix
/// (leaf_groups.h), as in regular mode; the adaptive construction subdivides
/// every coarser cell with several groups or a doubled face (octree/build.h),
/// so only leaves at the maximum depth have several vertices, and a polygon
/// uses, in each leaf around its edge, the vertex whose group holds the edge.
/// Complex leaves at the maximum depth (finest size > 1) are where the Euler
/// characteristic may still differ. Two sheets through one finest cell each
/// stay in their own edges' envelopes, but the envelopes of different groups
/// of one cell are not disjoint, so Ju–Udeshi's guarantee does not cover
/// them (the validator's exact count is the check).
///
/// Octree: adaptive construction with OctreeOptions::qefTolerance about 0.25
/// voxel and cells of at most 16 voxels at minDepth (smooth cells with 3-4
/// crossings fit their tangent planes almost exactly, so the QEF criterion
/// alone does not refine them): 5.5x fewer triangles than the regular tree on
/// the salt body at 64^3, mean vertex distance 0.12 voxel.
///
/// Output: global voxel index coordinates (meta-cell offsets plus
/// cell::MetaCellSamples::origin), triangles oriented outwards (from inside,
/// value <= iso, to outside), vertices shared (indexed), no unused vertex.
/// Deterministic: independent of the number of TBB threads.
/// Memory: O(leaves + output) beside the samples.
#pragma once

#include <cstdint>

#include "isovdb/contour/seam_cell.h"
#include "isovdb/octree/unit_edge_crossings.h"
#include "isovdb/mesh/mesh.h"
#include "isovdb/octree/linear_octree.h"
#include "isovdb/cell/contour_settings.h"
#include "isovdb/cell/meta_cell_samples.h"

namespace isovdb::contour {

/// What contourAdaptive did (figures for statistics, tests and paper 000's Tables 5.1–5.2).
struct AdaptiveContourStats {
  std::int64_t minimalEdges = 0;  ///< sign-changing minimal edges contoured
  std::int64_t quads = 0;         ///< of them, edges with 4 leaves around
  std::int64_t triangles3 = 0;    ///< of them, edges with 3 leaves around (one coarser)
  std::int64_t fannedEdges = 0;   ///< edges triangulated with a Ju–Udeshi fan through the edge point v_e
  std::int64_t uncrossedFaceEdges =
      0;  ///< edges with a face that the cell-to-cell segment misses (polygon through v_f)
  std::int64_t trianglesAddedByFans = 0;  ///< triangles beyond plain DC's (2 per quad, 1 per triangle): fans
                                          ///< and polygons routed through face points
  std::int64_t boundaryEdges = 0;         ///< sign-changing minimal edges skipped on the meta-cell boundary
  std::int64_t edgesWithoutVertex = 0;    ///< skipped because a leaf around had no dual vertex (should stay 0)
  std::int64_t seamCells = 0;             ///< leaves kept for stitching
  std::int64_t multiVertexCells = 0;      ///< leaves with more than one vertex (DMC groups, maximum depth only)
  std::int64_t manifoldFixes = 0;         ///< leaves with Wenger's alternative grouping (voxels: split faces)
  std::int64_t voxelEdges = 0;            ///< edges of leaves read as the voxel object (adaptiveReadsVoxels)

  /// Sums the figures of several meta-cells.
  AdaptiveContourStats& operator+=(const AdaptiveContourStats& o) noexcept {
    minimalEdges += o.minimalEdges;
    quads += o.quads;
    triangles3 += o.triangles3;
    fannedEdges += o.fannedEdges;
    uncrossedFaceEdges += o.uncrossedFaceEdges;
    trianglesAddedByFans += o.trianglesAddedByFans;
    boundaryEdges += o.boundaryEdges;
    edgesWithoutVertex += o.edgesWithoutVertex;
    seamCells += o.seamCells;
    multiVertexCells += o.multiVertexCells;
    voxelEdges += o.voxelEdges;
    manifoldFixes += o.manifoldFixes;
    return *this;
  }
};

/// @brief Contours the octree of one meta-cell (adaptive mode).
/// @param[in] samples  the meta-cell's samples, (S + 3)^3.
/// @param[in] tree     its octree (any construction; adaptive is the intended one).
/// @param[in] settings isovalue, intersection-free fans, manifold fix, QEF truncation, sharp features.
/// @param[out] stats   optional figures.
/// @return the mesh (global voxel index coordinates, outward, indexed; no normals).
/// @pre `tree` was built from `samples` with the same iso; tree.metaCellSize() == samples.size.
/// @throw InputError if the sizes differ.
mesh::Mesh contourAdaptive(const cell::MetaCellSamples& samples, const octree::LinearOctree& tree,
                           const cell::ContourSettings& settings, AdaptiveContourStats* stats = nullptr);

/// @brief contourAdaptive plus the seam (seam_cell.h): leaves with a sign change
///        that touch the meta-cell boundary, and the face points made into
///        vertices on faces that touch it.
/// @param crossings optional: the samples' unit-edge crossings (found once each), read by
///        the 1-voxel leaves instead of finding them again; the mesh is the same.
MetaCellMesh contourAdaptiveMetaCell(const cell::MetaCellSamples& samples, const octree::LinearOctree& tree,
                                     const cell::ContourSettings& settings, AdaptiveContourStats* stats = nullptr,
                                     const octree::UnitEdgeCrossings* crossings = nullptr);

}  // namespace isovdb::contour
