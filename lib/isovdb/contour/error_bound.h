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
#pragma once

#include <vector>

#include "isovdb/cell/meta_cell_samples.h"
#include "isovdb/mesh/mesh.h"
#include "isovdb/octree/linear_octree.h"

namespace isovdb::contour {

/// @brief Keys of the leaves of `tree` larger than `finestSize` voxels (the octree's
///        finest cells, which cannot be split) whose closed box holds a
///        vertex, triangle centroid or edge midpoint of `mesh` (global voxel index coordinates) farther
///        than `maxError` from the level `iso`: sorted, unique.
std::vector<octree::MortonKey> leavesBeyondErrorBound(const cell::MetaCellSamples& samples,
                                                      const octree::LinearOctree& tree, const mesh::Mesh& mesh,
                                                      float iso, float maxError, int finestSize = 1);

}  // namespace isovdb::contour
