// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
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
///
/// Voxel topology (regular mode's default, voxel_dmc.h): the joined-face
/// table, three sector vertices for a tube cell, and instead of Wenger's fix
/// two split vertices on a doubled face whose neighbour is doubled too, owned
/// by the cell on the face's min side. A leaf's vertices are numbered: its
/// groups (or sectors), then its split vertices by axis of the split max face.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "isovdb/bit_count.h"
#include "isovdb/cell/dmc_table.h"
#include "isovdb/cell/dual_vertex.h"
#include "isovdb/octree/unit_edge_crossings.h"
#include "isovdb/contour/voxel_dmc.h"
#include "isovdb/mesh/mesh.h"
#include "isovdb/octree/linear_octree.h"
#include "isovdb/cell/meta_cell_samples.h"

namespace isovdb::contour {

/// Per leaf of one octree: configuration, grouping and vertex numbering.
struct LeafGroups {
  bool voxels = false;                     ///< RegularTopology::Voxels
  std::vector<std::uint8_t> configs;       ///< corner signs (bit c = corner c inside)
  std::vector<char> alternative;           ///< Wenger's alternative grouping is used (Mdmc)
  std::vector<std::uint8_t> splitFaces;    ///< voxels: bit a = the max face along axis a is split
  std::vector<std::uint32_t> firstVertex;  ///< leafCount + 1 prefix sums of the vertex counts
  std::int64_t manifoldFixes = 0;          ///< leaves with the alternative grouping (voxels: split faces)
  std::int64_t fixesBeyondApron = 0;       ///< doubled faces whose neighbour lies beyond the apron (left unfixed)

  const cell::DmcEntry& entry(std::size_t leaf) const noexcept {
    return voxels ? voxelDmcEntry(configs[leaf]) : cell::dmcEntry(configs[leaf], alternative[leaf] != 0);
  }
  /// Vertices of the leaf's groups (a tube's sectors), without its split vertices.
  int cellVertexCount(std::size_t leaf) const noexcept {
    return voxels ? voxelCellVertexCount(configs[leaf]) : entry(leaf).vertexCount;
  }
  /// Id of the leaf's split vertex `slot` on its max face along `axis` (that face must be split).
  std::uint32_t splitVertex(std::size_t leaf, int axis, int slot) const noexcept {
    const unsigned below = splitFaces[leaf] & ((1u << axis) - 1u);
    return firstVertex[leaf] + static_cast<std::uint32_t>(cellVertexCount(leaf) + 2 * countBits(below) + slot);
  }
  std::uint32_t vertexCount(std::size_t leaf) const noexcept { return firstVertex[leaf + 1] - firstVertex[leaf]; }
  std::uint32_t totalVertices() const noexcept { return firstVertex.back(); }
};

/// @brief Leaf `i`'s vertices as a cell around a bipolar edge (voxel_dmc.h; both readings,
///        split vertices in the voxel reading): vertex v of `groups`' numbering as `ids[v]`
///        (empty: v), with its position `positions[v]` where given (regular mode's quads).
VoxelEdgeCell voxelEdgeCell(const LeafGroups& groups, std::size_t i, const std::vector<std::uint32_t>& ids,
                            const std::vector<mesh::Vec3f>& positions);

/// @brief Groups the leaves with configurations `configs` (one per leaf of `tree`).
/// @param manifoldFix apply Wenger's fix, or split doubled faces with `topology` Voxels (false only in tests).
LeafGroups groupLeaves(const cell::MetaCellSamples& samples, const octree::LinearOctree& tree,
                       std::vector<std::uint8_t> configs, float iso, bool manifoldFix,
                       RegularTopology topology = RegularTopology::Mdmc);

/// @brief The dual vertex of every group (QEF of its edges; the mass point of
///        its crossings in a cell with several groups; the cell centre if it has
///        no usable crossing), of every tube sector and split face (the mass
///        point of their crossings), numbered by LeafGroups::firstVertex.
///        Parallel with TBB; deterministic. Global voxel index coordinates.
///        1-voxel leaves read their crossings from `crossings` if given (the same
///        values, found once per edge; unit_edge_crossings.h). Cells just beyond a face of
///        `capBox` (regular mode's caps, cell::ContourSettings::capBox) get the
///        mass point too, held within 2 * kInteriorMargin of that face (box_caps.h): there
///        it is the mean of the crossings as seen on the face, where a QEF minimiser could
///        land beside its neighbours' and fold the cap.
std::vector<mesh::Vec3f> placeGroupVertices(const cell::MetaCellSamples& samples, const octree::LinearOctree& tree,
                                            const LeafGroups& groups, const cell::DualVertexOptions& options,
                                            const octree::UnitEdgeCrossings* crossings = nullptr,
                                            const std::optional<cell::DataBox>& capBox = std::nullopt);

}  // namespace isovdb::contour
