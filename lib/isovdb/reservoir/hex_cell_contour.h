// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file hex_cell_contour.h
/// @brief One hexahedron of Marching Cubes on a corner-point grid (hex_marching_cubes.h):
/// its faces' segments, loops and fans, recorded as weld keys for contourHexahedra to
/// weld; and the edge crossings both share.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "isovdb/reservoir/corner_point_grid.h"
#include "isovdb/reservoir/hex_marching_cubes.h"

namespace isovdb::reservoir::hex {

/// What the cells of one thread make, block after block. A vertex is recorded by its weld
/// key alone, once per cell that makes it; positions are computed once per distinct vertex
/// after welding (they depend on the key only), so the records stay small. The arrays grow
/// into huge pages (huge_pages.h): on a virtual machine a 4 KiB page fault costs
/// microseconds, and vectors per block, grown by doubling, faulted in twice their size and
/// took as long as the contouring itself on a first run.
struct ThreadOutput {
  std::vector<std::uint64_t> keys;                                 // one per vertex a cell makes
  std::vector<Vec3d> gradients;                                    // beside keys (with normals)
  std::vector<std::pair<std::uint64_t, Eigen::Vector3f>> centres;  // centre vertices' positions
  std::vector<std::array<std::uint32_t, 3>> triangles;             // into keys, from its block's first
  std::vector<std::uint32_t> triangleCells;                        // beside triangles (HexContourOptions)
  std::vector<std::pair<std::uint64_t, Vec3d>>
      faultSides;  // crossings moved off fault faces (edgeSharing), with their sides
  // Positions placed by their cell: face points (kFaceKey) and lone crossings (kLoneEdgeKey)
  std::vector<std::pair<std::uint64_t, Eigen::Vector3f>> placedPoints;
};

/// What a block of consecutive cells made: where it lies in its thread's arrays.
struct BlockOutput {
  const ThreadOutput* thread = nullptr;
  std::size_t firstKey = 0, keyCount = 0, firstCentre = 0, centreCount = 0, firstTriangle = 0, triangleCount = 0,
              firstFaultSide = 0, faultSideCount = 0, firstPlacedPoint = 0, placedPointCount = 0;
  std::int64_t cutCells = 0;
  int ambiguousFaces = 0;

  std::span<const std::uint64_t> keys() const { return {thread->keys.data() + firstKey, keyCount}; }
  std::span<const Vec3d> gradients() const { return {thread->gradients.data() + firstKey, keyCount}; }
  std::span<const std::pair<std::uint64_t, Eigen::Vector3f>> centres() const {
    return {thread->centres.data() + firstCentre, centreCount};
  }
  std::span<const std::array<std::uint32_t, 3>> triangles() const {
    return {thread->triangles.data() + firstTriangle, triangleCount};
  }
  /// Empty unless HexContourOptions::triangleCells.
  std::span<const std::uint32_t> triangleCells() const {
    if (thread->triangleCells.empty()) return {};
    return {thread->triangleCells.data() + firstTriangle, triangleCount};
  }
  std::span<const std::pair<std::uint64_t, Vec3d>> faultSides() const {
    return {thread->faultSides.data() + firstFaultSide, faultSideCount};
  }
  std::span<const std::pair<std::uint64_t, Eigen::Vector3f>> placedPoints() const {
    return {thread->placedPoints.data() + firstPlacedPoint, placedPointCount};
  }
};

/// Weld keys: an edge crossing is keyed by its edge's two point ids (lower first); these
/// bits mark the other three kinds.
constexpr std::uint64_t kCornerKey = std::uint64_t{1} << 62;  ///< the vertex is a grid point
constexpr std::uint64_t kCentreKey = std::uint64_t{1} << 63;  ///< a loop's centre inside a cell
/// A point on a twisted face between two of its crossings (contourCell), made alike by
/// both cells that share the face: (the lower cell << 4) | (its face << 1) | segment.
constexpr std::uint64_t kFaceKey = std::uint64_t{1} << 61;
/// A crossing on an edge whose cells fall apart into groups joined by whole shared faces
/// (a cell diagonal across it with the cells beside across a fault or unusable, or a cell
/// beside that shares the edge and not the rest of the face): their sheets met only there,
/// at a non-manifold vertex, so each group of one or two cells makes its own, (its lowest
/// cell << 4) | that cell's edge, moved into the group's cells like a crossing on a fault face.
constexpr std::uint64_t kLoneEdgeKey = std::uint64_t{1} << 60;
/// The vertices that are not keyed by their edge's points.
constexpr std::uint64_t kSpecialKeys = kCornerKey | kCentreKey | kFaceKey | kLoneEdgeKey;

/// Where the surface crosses the edge between points `a` and `b`: its weld key and its
/// place `t` along the edge from the lower id. The same in every cell that holds the edge.
struct EdgeCrossing {
  std::uint64_t key;
  std::uint32_t from, to;  ///< point ids, from < to
  double t;
  bool nearCorner = false;  ///< t held off a corner at (or a rounding error from) the iso-value
};

/// The crossing on the edge between points `a` and `b` (any order) at `iso`.
EdgeCrossing crossEdge(const CornerPointGrid& grid, const CornerField& field, double iso, std::uint32_t a,
                       std::uint32_t b);
/// Where the crossing lies: in double precision (fan choices), and as the mesh's float.
Vec3d crossingPoint(const CornerPointGrid& grid, const EdgeCrossing& crossing);
Eigen::Vector3f crossingPosition(const CornerPointGrid& grid, const EdgeCrossing& crossing);

/// Contours usable cell `cell` at grid indices `ijk`, appending its records to `out` and
/// its counts to `block` (whose first key numbers the triangles' corners).
void contourCell(const CornerPointGrid& grid, const CornerField& field, std::size_t cell, const std::array<int, 3>& ijk,
                 const HexContourOptions& options, ThreadOutput& out, BlockOutput& block);

}  // namespace isovdb::reservoir::hex
