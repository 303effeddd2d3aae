// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file seam_cell.h
/// @brief What one meta-cell's contouring hands to seam stitching: the surface
///        leaves around its deferred edges, with their dual vertices, and the
///        face points it already made into mesh vertices (paper 000, section 4.3).
///
/// A meta-cell's contourer skips every sign-changing edge that lies on the
/// meta-cell's boundary (some of the leaves around it belong to a neighbour)
/// and keeps, as SeamCells, its leaves that have a sign change and touch the
/// boundary: exactly the leaves that can lie around such an edge (a leaf with
/// equal corner signs has no crossing on its faces, see octree/criteria.h).
/// Everything else is freed with the meta-cell.
///
/// Unlike the paper, edges of boundary leaves that lie inside the meta-cell
/// are contoured with the meta-cell, not deferred: our meta-cell samples carry
/// an apron (octree/meta_cell_samples.h), so a boundary leaf's Prewitt
/// normals, dual vertices and (regular mode) Wenger grouping are already exact
/// there, and the stitcher needs only the vertices, never the samples.
///
/// Vertex ids are local to the meta-cell's mesh until the pipeline appends it
/// to the output; it then offsets them (rebaseSeam) so they become output ids.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "isovdb/mesh/mesh.h"
#include "isovdb/octree/linear_octree.h"
#include "isovdb/octree/morton.h"

namespace isovdb::contour {

/// Id of a vertex not (yet) in the output.
inline constexpr std::uint32_t kNoVertex = std::numeric_limits<std::uint32_t>::max();

/// A surface leaf kept for stitching.
struct SeamCell {
  octree::MortonKey key = octree::kInvalidKey;  ///< key under its meta-cell's root
  std::array<int, 3> origin{0, 0, 0};           ///< min corner, global voxel index coordinates
  int size = 0;                                 ///< side in voxels
  std::uint8_t cornerSigns = 0;                 ///< bit c set iff corner c is inside

  /// Wenger's alternative grouping was used (both modes group a leaf's bipolar
  /// edges by cell::dmcEntry(cornerSigns, alternative); see leaf_groups.h).
  bool alternative = false;
  /// Mesh id of the dual vertex of each group. Regular: all set. Adaptive:
  /// kNoVertex until a polygon uses it (the stitcher then adds positions[g]).
  std::array<std::uint32_t, 4> vertices{kNoVertex, kNoVertex, kNoVertex, kNoVertex};
  /// Positions of the (up to 4) dual vertices: regular mode chooses quad
  /// diagonals with them, adaptive mode's envelopes use them (strictly inside the cell).
  std::array<mesh::Vec3f, 4> positions{};
  /// Regular mode, voxel topology (voxel_dmc.h): bit a = the cell's max face along
  /// axis a is split, and the ids of those faces' split vertices (by splitVertexSlot).
  std::uint8_t splitFaces = 0;
  std::array<std::uint32_t, 6> splitVertices{kNoVertex, kNoVertex, kNoVertex, kNoVertex, kNoVertex, kNoVertex};
  /// Crossing of each bipolar cell edge, voxels from its start (NaN for the others): the edge
  /// points of adaptive mode's Ju–Udeshi fans and of the voxel reading's fanned polygons.
  std::array<float, 12> edgeCrossing{};
};

/// A minimal face in global voxel index coordinates: the square of side `size`
/// on the plane x[axis] = min[axis] whose min corner is `min`. `part` tells
/// apart the dual segments that cross one face (a 1-voxel ambiguous face is
/// crossed twice): the group of the vertex on the face's own leaf (the smaller
/// one, or the min-side one of two equal leaves).
struct FaceKey {
  std::array<int, 3> min{0, 0, 0};
  std::int32_t size = 0;
  std::int32_t axis = 0;
  std::int32_t part = 0;
  friend auto operator<=>(const FaceKey&, const FaceKey&) = default;
};

/// A face point v_f that became a mesh vertex, on a face touching the meta-cell boundary.
struct SeamFace {
  FaceKey face;
  std::uint32_t vertex = kNoVertex;
};

/// Everything one meta-cell leaves to the stitcher.
struct MetaCellSeam {
  std::vector<SeamCell> cells;  ///< in the Z order of the meta-cell's octree
  std::vector<SeamFace> faces;  ///< adaptive only
};

/// @brief A SeamCell with what both modes fill alike: the key, global origin, size and
///        corner signs of `leaf` (in the meta-cell whose min corner is `metaCellOrigin`)
///        and its grouping; vertices, positions and the mode's own fields are left to fill.
SeamCell seamCellOf(const octree::OctreeLeaf& leaf, const std::array<int, 3>& metaCellOrigin, bool alternative);

/// @brief Adds `base` to every vertex id of `seam` (when its mesh is appended after `base` vertices).
void rebaseSeam(MetaCellSeam& seam, std::uint32_t base) noexcept;

/// @brief The mesh of one meta-cell and what it leaves to the stitcher.
struct MetaCellMesh {
  mesh::Mesh mesh;  ///< global voxel index coordinates; ids local to this mesh
  MetaCellSeam seam;
  /// Adaptive mode: a leaf coarser than a voxel in a quad that could not take regular mode's
  /// triangulation, and how far that quad's triangles lie from regular mode's (voxels;
  /// adaptive_edges.h, EdgeRecord::apartFromRegular). The error bound splits it where that
  /// is beyond the bound.
  struct LeafApart {
    std::int64_t leaf = 0;  ///< index in the meta-cell's tree
    float distance = 0.0f;
  };
  std::vector<LeafApart> apartFromRegular;
};

}  // namespace isovdb::contour
