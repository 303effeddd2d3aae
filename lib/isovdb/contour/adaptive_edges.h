// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file adaptive_edges.h
/// @brief The per-edge routine of adaptive mode, shared by a meta-cell's
///        contouring and by seam stitching: find the sign-changing minimal
///        edges a leaf owns, build their Ju–Udeshi envelopes, and turn them
///        into triangles (paper 000, sections 4.2.3.2 and 4.3).
///
/// The routine sees an octree only through AdaptiveTree: a LinearOctree (a
/// meta-cell's, or the partial edge-octree of a seam) plus, per leaf, its
/// cell point and the crossings on its edges. Faces are named by global
/// coordinates (FaceKey), so the face point v_f of a face that two passes
/// share (a meta-cell and a seam) becomes one mesh vertex.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <map>
#include <vector>

#include "isovdb/contour/ju_udeshi.h"
#include "isovdb/contour/seam_cell.h"
#include "isovdb/contour/voxel_dmc.h"
#include "isovdb/mesh/mesh.h"
#include "isovdb/octree/linear_octree.h"
#include "isovdb/octree/unit_leaf_index.h"

namespace isovdb::contour {

/// Cell vertices and edge points keep this fraction of the cell / edge size
/// away from the cell boundary / edge ends, so that the envelopes are not
/// degenerate (the dual vertex solver returns points in the closed cell).
inline constexpr double kInteriorMargin = 1e-3;

/// An octree as the edge routine sees it.
///
/// Vertices: a leaf has one cell vertex per Dual Marching Cubes group of its
/// configuration (leaf_groups.h): several only at the maximum depth. The
/// vertex a polygon uses is the one whose group holds the polygon's edge; a
/// leaf coarser than the edge has a single vertex.
struct AdaptiveTree {
  const octree::LinearOctree* tree = nullptr;
  std::array<int, 3> origin{0, 0, 0};  ///< global index coordinate of the tree's offset (0, 0, 0)
  /// Per leaf + 1: first of the leaf's vertices in `cellPoints` (LeafGroups::firstVertex).
  const std::vector<std::uint32_t>* firstVertex = nullptr;
  const std::vector<Vec3d>* cellPoints = nullptr;  ///< per vertex: v_c, global coordinates, strictly inside its cell
  const std::vector<char>* alternative = nullptr;  ///< per leaf: Wenger's alternative grouping
  /// Crossing on edge e of leaf l, in voxels from the edge's start corner; NaN if unknown (mid-edge is used).
  std::function<double(std::size_t leaf, int edge)> crossing;
  /// Which edges to contour, by start (tree offsets) and axis; empty = every edge with all leaves around.
  std::function<bool(const std::array<int, 3>& start, int axis)> inRegion;
  /// The tree holds only a seam's kept cells (stitch/): a place without a leaf is a finer
  /// leaf without a sign change, so an edge next to it is not minimal.
  bool partial = false;
  /// Constant-time lookups of `tree`'s 1-voxel leaves (optional: the tree's own search otherwise).
  const octree::UnitLeafIndex* unitLeaves = nullptr;
  /// Per leaf: read as the voxel object (cell::ContourSettings::adaptiveReadsVoxels). The
  /// edges of such leaves are left to emitVoxelReadingEdge (optional: none).
  const std::vector<char>* voxelCells = nullptr;
  /// Regular mode's vertex (global coordinates) of the unit cell in quadrant `quadrant` around
  /// the unit edge (start, axis) (tree offsets), where that cell has one vertex in every
  /// reading; else none. Optional: without it a quad's diagonal is chosen by its own corners.
  std::function<std::optional<Vec3d>(const std::array<int, 3>& start, int axis, int quadrant)> regularVertex;
};

/// One sign-changing minimal edge, ready to be triangulated.
struct EdgeRecord {
  int cellCount = 0;
  std::array<std::int64_t, 4> cells{};  ///< leaf indices in polygon order (outward orientation)
  std::array<std::int8_t, 4> groups{};  ///< per cell: its vertex (DMC group) that the polygon uses
  std::array<FaceKey, 4> faces{};       ///< the minimal face between cell i and i + 1
  std::array<Vec3d, 4> facePoints{};
  Vec3d edgePoint{0, 0, 0};
  std::array<bool, 4> crossed{true, true, true, true};  ///< per face: the cell-to-cell segment crosses it
  EdgeTriangulation how;
  bool uncrossedFace = false;  ///< a face's cell-to-cell segment misses it
  /// A quad of one-voxel leaves and a coarser one (AdaptiveTree::regularVertex) whose envelope
  /// refused regular mode's triangulation: how far its triangles lie from regular mode's
  /// (voxels, sampled; adaptive_edges.cc); else 0.
  float apartFromRegular = 0.0f;
};

/// Records of one leaf's owned edges plus its skip counters.
struct LeafEdges {
  std::vector<EdgeRecord> records;
  std::int32_t boundary = 0;       ///< owned edges with a leaf missing around (left to stitching)
  std::int32_t withoutVertex = 0;  ///< owned edges with a leaf around that has no vertex
};

/// @brief v_c of a leaf: its dual vertex clamped strictly inside the cell and rounded
///        to float, so the mesh vertex, a seam cell's copy and the envelopes agree
///        (global coordinates; `treeOrigin` = global coordinate of the tree's offset 0).
Vec3d cellPointInside(const mesh::Vec3f& vertex, const octree::OctreeLeaf& leaf, const std::array<int, 3>& treeOrigin);

/// @brief The sign-changing minimal edges that `leafIndex` owns (the first
///        quadrant around the edge holding a leaf of the edge's size), with
///        their envelopes and triangulations.
void collectMinimalEdges(const AdaptiveTree& source, std::size_t leafIndex, bool intersectionFree, LeafEdges& out);

/// Mesh vertices of the face points v_f that polygons go through, by face.
using FaceVertexMap = std::map<FaceKey, std::uint32_t>;

/// Adds a mesh vertex and returns its id.
using VertexAdder = std::function<std::uint32_t(const Vec3d& position)>;

/// @brief Appends the triangles of `record` to `triangles`.
/// @param cellVertex  the mesh vertex of a leaf's group (the caller adds it on first use).
/// @param addVertex  adds face points (first use of a face) and edge points (fans).
/// @param faceVertices  face points already in the mesh; new ones are added to both.
/// @return the number of triangles appended.
/// Mesh vertex of group `group` of leaf `leaf`.
using CellVertexFn = std::function<std::uint32_t(std::int64_t leaf, int group)>;

std::size_t emitEdgeRecord(const EdgeRecord& record, const CellVertexFn& cellVertex, const VertexAdder& addVertex,
                           FaceVertexMap& faceVertices, std::vector<mesh::Triangle>& triangles);

/// One edge of a leaf read as the voxel object (AdaptiveTree::voxelCells), between four
/// 1-voxel leaves: its polygon is the voxel reading's (voxel_dmc.h), with the face point of
/// each face between two leaves not read as voxels where the cell-to-cell segment misses
/// it, as adaptive mode's polygons have it there; fanned from the edge's crossing, or, with
/// four corners and every face crossed, split along a diagonal that stays in the edge's
/// envelope (voxelQuadTriangles).
struct VoxelReadingEdge {
  std::array<VoxelEdgeCell, 4> cells{};  ///< by quadrant around the edge; vertices are mesh ids
  std::array<bool, 4> voxelCell{};       ///< the quadrant's leaf is read as voxels
  std::array<Vec3d, 4> points{};         ///< v_c of each leaf's vertex on the edge (a tube's: any)
  std::array<int, 4> groups{};           ///< that vertex's group
  std::array<int, 3> start{0, 0, 0};     ///< the edge's min end, global index coordinates
  int axis = 0;
  double crossing = 0.5;  ///< the surface's crossing, voxels from `start` (NaN: unknown)
};

/// @brief Appends the triangles of `edge` (outward), adding its face points (shared through
///        `faceVertices`, as emitEdgeRecord's) and its edge point.
/// @return the number of triangles appended.
std::size_t emitVoxelReadingEdge(const VoxelReadingEdge& edge, const VertexAdder& addVertex,
                                 FaceVertexMap& faceVertices, std::vector<mesh::Triangle>& triangles);

/// @brief Calls `visit(owner, axis, around)` for each bipolar edge that a 1-voxel leaf of
///        `tree` owns (its local edge 4 * axis: the owner in quadrant 3, as regular mode
///        finds its edges), that `wanted(origin, axis)` accepts and that touches a leaf read as
///        voxels (`voxelCells`): the edges emitVoxelReadingEdge makes, in leaf order.
///        `leavesAround(origin, axis)` gives the four leaves around the edge by quadrant
///        (LinearOctree::kNone where `tree` has none), as LinearOctree::leavesAroundEdge does.
template <typename Wanted, typename LeavesAround, typename Visit>
void forEachVoxelReadingEdge(const octree::LinearOctree& tree, const std::vector<char>& voxelCells, Wanted&& wanted,
                             LeavesAround&& leavesAround, Visit&& visit) {
  for (std::size_t i = 0; i < tree.leafCount(); ++i) {
    const octree::OctreeLeaf& leaf = tree.leaf(i);
    if (leaf.size != 1) continue;
    const std::uint16_t bipolar = octree::bipolarEdgeMask(leaf.cornerSigns);
    for (int axis = 0; axis < 3; ++axis) {
      if (((bipolar >> (4 * axis)) & 1) == 0 || !wanted(leaf.origin, axis)) continue;
      const std::array<std::int64_t, 4> around = leavesAround(leaf.origin, axis);
      if (std::any_of(around.begin(), around.end(), [&](std::int64_t l) {
            return l != octree::LinearOctree::kNone && voxelCells[static_cast<std::size_t>(l)] != 0;
          }))
        visit(i, axis, around);
    }
  }
}

/// @brief A VertexAdder that appends to `mesh.positions` (ids = positions' indices + `base`).
VertexAdder appendingTo(mesh::Mesh& mesh, std::uint32_t base = 0);

}  // namespace isovdb::contour
