// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file error_bound.h
/// @brief Adaptive mode's error bound, checked on the mesh a meta-cell's tree
///        gave: the leaves to split where a mesh point lies farther than the
///        bound from the surface.
///
/// The octree's own criterion (octree/surface_deviation.h) keeps the
/// full-resolution surface close to each leaf's vertex plane, but the mesh also
/// has points the tree never saw: Ju–Udeshi face points clamped into their face,
/// fan points, and the insides of triangles that span a coarse leaf and its
/// neighbours. Each vertex, triangle centroid and edge midpoint is measured against the
/// field to first order (cell/trilinear.h, distanceToLevel); the leaves coarser than
/// one voxel whose closed box holds a point beyond the bound are split, and the
/// meta-cell is built and contoured again (pipeline/octree_contour.cc).
///
/// The other way round, the full-resolution surface against the mesh: the vertices
/// full-resolution contouring would place in the unit cells of each coarse leaf
/// (manifold DMC's groups, the vertices of adaptive mode at one voxel), and the
/// sides of its quads between two such cells, must lie within the bound of the
/// meta-cell's mesh (exact point-triangle distances, mesh/triangle_grid.h). A side
/// matters where the mesh folds: on the rim of a thin sheet its midpoint lay 0.1
/// voxel farther from the mesh than either end. A coarse leaf's vertex on the level
/// set can still miss part of what regular mode meshes: the frog skeleton's one-voxel
/// slit of background along a 2-voxel leaf's edge, whose unit-cell vertices lie 0.6
/// voxel from the slit's crossings, stayed 0.57 voxel off at every bound before.
///
/// Both sides are sampled, so the check holds the mesh to the bound less a margin
/// (octree::kErrorBoundMargin) that covers what lies between the samples. The seam's
/// triangles, stitched later, are not in the mesh: they pass through the boundary leaves'
/// own vertices (the seam cells'), so a full-resolution vertex of a boundary leaf counts as
/// covered within the bound of the mesh or of those vertices (before, boundary leaves were
/// left out, and a one-voxel finger ending at a seam stayed 1.04 voxels from the adaptive
/// mesh at E = 1). The seam's own points against the level are not checked: the octree's
/// own criterion keeps the margin on the meta-cell's boundary.
#pragma once

#include <vector>

#include "isovdb/cell/dual_vertex.h"
#include "isovdb/cell/meta_cell_samples.h"
#include "isovdb/contour/seam_cell.h"
#include "isovdb/mesh/mesh.h"
#include "isovdb/octree/linear_octree.h"
#include "isovdb/octree/unit_edge_crossings.h"

namespace isovdb::contour {

/// @brief Keys of the leaves of `tree` larger than `finestSize` voxels (the octree's
///        finest cells, which cannot be split) whose closed box holds a
///        vertex, triangle centroid or edge midpoint of `mesh` (global voxel index
///        coordinates) farther than `maxError` from the level `options.iso`, or
///        which hold a full-resolution vertex (or side) farther than `maxError` from
///        `mesh` (or, on the meta-cell's boundary, from the leaf's vertices in `seam`,
///        which the seam's triangles stitched later pass through; without `seam` such
///        leaves are left out): sorted, unique. `options` place the vertices as contouring does.
/// `crossings` (optional) are the samples' unit-edge crossings, each found once (a unit edge
/// is shared by four unit cells); without them each cell finds its own. `phases` (optional)
/// are the samples' phases at `options.iso`, computed here without them.
std::vector<octree::MortonKey> leavesBeyondErrorBound(const cell::MetaCellSamples& samples,
                                                      const octree::LinearOctree& tree, const mesh::Mesh& mesh,
                                                      const cell::DualVertexOptions& options, float maxError,
                                                      int finestSize = 1,
                                                      const octree::UnitEdgeCrossings* crossings = nullptr,
                                                      const octree::SamplePhases* phases = nullptr,
                                                      const MetaCellSeam* seam = nullptr);

}  // namespace isovdb::contour
