// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file voxel_dmc.h
/// @brief Regular mode's reading of ambiguous cells that keeps the topology of
///        the voxel object: 26-connected inside, 6-connected outside (the
///        reading of volume/digital_topology.h), so a mesh of a binary mask has
///        Euler characteristic 2 chi(object).
///
/// Three changes to Manifold DMC (dmc_table.h, regular_contour.h):
/// - Ambiguous faces join their two inside corners (face-diagonal voxels are
///   26-adjacent): the DMC table of `detail::buildDmcEntry(config, 0x3f)`.
/// - Doubled faces are split, not regrouped. Where both cells across an
///   ambiguous face have one group passing twice through it (the inside
///   diagonal is a bridge and the outside goes round it on both sides), their
///   two vertices would share four quads. Wenger's fix separates the bridge,
///   which changes the topology; here each of the face's two surface curves
///   gets its own vertex on the face (the mass point of its two crossings),
///   inserted between the two cells' vertices in the polygons of the face's
///   four edges, so the two cells meet along two distinct mesh edges: the
///   tube around the bridge.
/// - Vertex contacts become tubes. A cell whose only inside corners are the two
///   ends of a body diagonal (26-adjacent voxels) holds an annulus, not two
///   disks. It gets three vertices, one per sector: sector k covers the
///   segment on the k-th face at one inside corner and on the (k+1)-th face at
///   the other, so every bipolar edge separates two sectors and contributes
///   both to its polygon; the three sectors close the tube.
///
/// A bipolar edge's polygon lists, counter-clockwise, each cell's vertices on
/// the faces it shares with its two neighbours around the edge, and a split
/// vertex between two cells whose shared face is split: 4 to 8 corners. Four
/// are a quad (the better diagonal where it stays in the edge's Ju–Udeshi
/// envelope); more are fanned from the edge's crossing, a vertex of its own,
/// which creates no edge between corners that could already exist (two cells
/// sharing a face are joined only through their shared curves). See
/// voxelEdgeTriangles.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "isovdb/cell/cell_geometry.h"
#include "isovdb/cell/contour_settings.h"
#include "isovdb/cell/dmc_table.h"
#include "isovdb/contour/seam_cell.h"
#include "isovdb/mesh/mesh.h"

namespace isovdb::cell {
struct MetaCellSamples;
struct DualVertexOptions;
}  // namespace isovdb::cell
namespace isovdb::octree {
class UnitEdgeCrossings;
}  // namespace isovdb::octree

namespace isovdb::contour {

/// How regular mode reads ambiguous configurations.
using cell::RegularTopology;  // which reading: cell/contour_settings.h

/// @brief The DMC entry of `config` with ambiguous faces joining the inside
///        corners; `doubleFace` as in dmc_table.h.
const cell::DmcEntry& voxelDmcEntry(std::uint8_t config) noexcept;

/// @brief Regular mode's vertex (global coordinates) of the unit cell at `cell` (meta-cell
///        offsets, each in [0, S)) for the group holding its bipolar edge (`axis`, `quadrant`
///        as cell::dmcVertexOfEdge), where the cell has that one vertex in Wenger's reading
///        and in the voxel one alike; none elsewhere (several vertices, the edge not
///        bipolar, no crossing, outside the block). `crossings` as octree::cellDualVertex.
std::optional<Vec3f> unambiguousUnitVertex(const cell::MetaCellSamples& samples, const std::array<int, 3>& cell,
                                           int axis, int quadrant, const cell::DualVertexOptions& options,
                                           const octree::UnitEdgeCrossings* crossings = nullptr);

/// True for the four configurations whose only inside corners are the two ends of a body
/// diagonal (cell/cell_geometry.h; inline: the quad loop asks it of four cells per edge).
using cell::isTubeConfig;

/// Sectors of a tube cell.
struct TubeSectors {
  std::array<std::uint16_t, 3> edges{};       ///< bipolar edges of sector k (its two faces' edges)
  std::array<std::int8_t, 6> sectorOfFace{};  ///< the sector holding face f's segment
};

/// @brief Sectors of a tube configuration (meaningful only if isTubeConfig).
const TubeSectors& tubeSectors(std::uint8_t config) noexcept;

/// @brief Vertices of a cell in voxel mode, without split vertices: the groups, or 3 for a tube.
int voxelCellVertexCount(std::uint8_t config) noexcept;

/// @brief The bipolar edges of each of the two split vertices of face f of a
///        cell with `config` (the two face edges at each outside corner, lower corner first).
std::array<std::uint16_t, 2> splitVertexEdges(std::uint8_t config, int face) noexcept;

/// @brief Index (0..5) of a split vertex among a cell's: 2 * axis + slot, for its max face along `axis`.
inline int splitVertexSlot(int axis, int slot) noexcept { return 2 * axis + slot; }

/// One of the four cells around a bipolar edge, as voxelEdgeTriangles reads it.
struct VoxelEdgeCell {
  std::uint8_t config = 0;
  std::uint8_t splitFaces = 0;              ///< bit a: its max face along axis a is split (this cell owns the vertices)
  std::array<std::uint32_t, 4> vertices{};  ///< vertex ids of its groups (tube: sectors)
  std::array<mesh::Vec3f, 4> positions{};   ///< their positions (quads choose their diagonal with them)
  std::array<std::uint32_t, 6> splitVertices{};  ///< ids of its split vertices, by splitVertexSlot
};

/// Adds the vertex at an edge's crossing and returns its id (empty: no such vertex).
using EdgePointFn = std::function<std::uint32_t()>;

/// The polygon of a bipolar edge in the voxel reading: around the edge counter-clockwise
/// (u, v), each cell's corners (its vertex on the face towards the previous cell, then
/// the one towards the next if another), then the split vertex of the face to the next
/// cell if that face is split.
struct VoxelEdgePolygon {
  std::array<std::uint32_t, 16> corners{};
  std::size_t size = 0;
  int apex = -1;          ///< the first split vertex (-1: none)
  bool plainQuad = true;  ///< four corners, one per cell
  bool minEndInside = false;
  bool reversed = false;  ///< the outward orientation walks the corners backwards
};

/// A corner to put between the corners of the cells in quadrants q and `next` where their
/// shared face is not split, or kNoVertex (adaptive mode's face points).
using FaceCornerFn = std::function<std::uint32_t(int q, int next)>;

/// @brief The polygon of the bipolar edge along `axis` between `cells` (as in
///        voxelEdgeTriangles), with `between`'s corners where it gives one.
VoxelEdgePolygon voxelEdgePolygon(const std::array<VoxelEdgeCell, 4>& cells, int axis,
                                  const FaceCornerFn& between = {});

/// @brief Appends the fan of `polygon` around the vertex `centre` (the edge's crossing), outward.
/// @return the number of triangles appended.
int fanVoxelEdgePolygon(const VoxelEdgePolygon& polygon, std::uint32_t centre, std::vector<mesh::Triangle>& out);

/// @brief Appends the triangles (outward) of the polygon of the bipolar edge from
///        `edgeStart` (global index coordinates) along `axis`, between four cells of side
///        `cellSize` (cells[q]: bit 0 of q = +u side, bit 1 = +v; the edge is cell q's
///        local edge 4 * axis + 3 - q).
///
/// With `edgePoint`: polygons of more than four corners are fanned from the edge's crossing
/// (a vertex `edgePoint` adds, called only when needed): each triangle joins it to two
/// consecutive corners, which lie in one cell (a tube's two sectors; a cell vertex and a
/// split vertex on its face) or in two cells across their shared face, so it stays within
/// them. A fan from one of the corners spans the four cells and crossed its neighbours'
/// triangles (frog skeleton: 67 self-intersecting pairs, each with such a triangle; with
/// the edge point: none). Quads go to voxelQuadTriangles. Without `edgePoint` (the caller's
/// `--no-intersection-free`), polygons are fanned from their first split vertex, else their
/// first corner, and quads take the better diagonal (regularEdgeQuad).
/// @return the number of triangles appended.
int voxelEdgeTriangles(const std::array<VoxelEdgeCell, 4>& cells, int axis, const std::array<int, 3>& edgeStart,
                       int cellSize, std::vector<mesh::Triangle>& out, const EdgePointFn& edgePoint);

/// @brief The voxel reading's quad of one edge (four cells, one vertex each; `vertices` and
///        `positions` by quadrant as in regularEdgeQuad): the better diagonal if its two
///        triangles stay inside the edge's Ju–Udeshi envelope (contour/ju_udeshi.h), else the
///        other if they do, else the fan of four triangles through the edge's crossing
///        (`edgePoint`). Without `edgePoint`, the better diagonal (no test).
/// @return the number of triangles appended (2 or 4).
int voxelQuadTriangles(const std::array<std::uint32_t, 4>& vertices, const std::array<mesh::Vec3f, 4>& positions,
                       int axis, bool minEndInside, const std::array<int, 3>& edgeStart, int cellSize,
                       const EdgePointFn& edgePoint, std::vector<mesh::Triangle>& out);

}  // namespace isovdb::contour
