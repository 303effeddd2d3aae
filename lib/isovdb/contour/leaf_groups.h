/// @file leaf_groups.h
/// @brief The dual vertices of a meta-cell's leaves as Dual Marching Cubes
///        groups their bipolar edges (dmc_table.h), with Wenger's manifold fix;
///        shared by regular mode and adaptive mode.
///
/// A leaf has one dual vertex per group of its configuration: up to four. In
/// adaptive mode only leaves at the maximum depth can have more than one (the
/// construction subdivides every coarser cell whose configuration has several
/// groups or a doubled face, octree/build.h), so a coarse leaf's one vertex
/// stands for every minimal edge around it.
///
/// Wenger's fix: a leaf whose single group passes twice through an ambiguous
/// face (2B-I / 3B-I) takes the alternative grouping when the cell of the same
/// size across that face does too. That cell's configuration is read from the
/// samples (the apron included), so a leaf's grouping is final with its
/// meta-cell, also next to the meta-cell boundary.
#pragma once

#include <cstdint>
#include <vector>

#include "isovdb/contour/dmc_table.h"
#include "isovdb/contour/dual_vertex.h"
#include "isovdb/mesh/mesh.h"
#include "isovdb/octree/linear_octree.h"
#include "isovdb/octree/meta_cell_samples.h"

namespace isovdb::contour {

/// Per leaf of one octree: configuration, grouping and vertex numbering.
struct LeafGroups {
  std::vector<std::uint8_t> configs;        ///< corner signs (bit c = corner c inside)
  std::vector<char> alternative;            ///< Wenger's alternative grouping is used
  std::vector<std::uint32_t> firstVertex;   ///< leafCount + 1 prefix sums of the vertex counts
  std::int64_t manifoldFixes = 0;           ///< leaves with the alternative grouping
  std::int64_t fixesBeyondApron = 0;        ///< doubled faces whose neighbour lies beyond the apron (left unfixed)

  const DmcEntry& entry(std::size_t leaf) const noexcept { return dmcEntry(configs[leaf], alternative[leaf] != 0); }
  std::uint32_t vertexCount(std::size_t leaf) const noexcept { return firstVertex[leaf + 1] - firstVertex[leaf]; }
  std::uint32_t totalVertices() const noexcept { return firstVertex.back(); }
};

/// @brief Groups the leaves with configurations `configs` (one per leaf of `tree`).
/// @param manifoldFix apply Wenger's fix (false only in tests).
LeafGroups groupLeaves(const octree::MetaCellSamples& samples, const octree::LinearOctree& tree,
                       std::vector<std::uint8_t> configs, float iso, bool manifoldFix);

/// @brief The dual vertex of every group (QEF of its edges; the mass point of
///        its crossings in a cell with several groups; the cell centre if it has
///        no usable crossing), numbered by LeafGroups::firstVertex.
///        Parallel with TBB; deterministic. Global voxel index coordinates.
std::vector<mesh::Vec3f> placeGroupVertices(const octree::MetaCellSamples& samples, const octree::LinearOctree& tree,
                                            const LeafGroups& groups, const DualVertexOptions& options);

}  // namespace isovdb::contour
