// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file dmc_table.h
/// @brief The Dual Marching Cubes table (Nielson 2004) and the alternative
///        groupings of Wenger's Manifold DMC (paper 000, section 4.2.3.1,
///        Fig. 4.4–4.5; paper 003, section 3.3.2).
///
/// For each of the 256 corner sign configurations (bit c set iff corner c is
/// inside, value <= iso; corner, edge and face numbering of octree/morton.h),
/// the table lists the cell's dual vertices (0 to 4) and, for each, the group
/// of bipolar edges it represents: the edges cut by one Marching Cubes patch.
///
/// The table is generated at static initialisation from face-ambiguity
/// reasoning instead of being typed in: on every face, the surface curve
/// pairs the face's bipolar edges; a face with two bipolar edges pairs them,
/// an ambiguous face (inside corners on one diagonal, outside corners on the
/// other) pairs the two edges around each INSIDE corner (inside separated,
/// outside joined — the same decision on both sides of the face, since it
/// depends only on the face's four corners). The groups are the connected
/// components of these pairings (each a closed cycle of edges).
///
/// Manifold fix (MDMC): in 36 configurations a single group passes twice
/// through the cell's one ambiguous face — Wenger's 2B-I and 3B-I (cases 4 and
/// 7 of Fig. 4.4, counting outside corners as positive): two or three outside
/// corners, two of them on the ambiguous face's diagonal. When two such cells
/// share that face, their two vertices would share four quads (a non-manifold
/// edge); both cells then use the alternative grouping, which resolves that
/// face the other way (outside corners separated) and splits the group in two.
#pragma once

#include <array>
#include <cstdint>

namespace isovdb::cell {

/// @brief The dual vertices of one cell configuration.
struct DmcEntry {
  std::uint8_t vertexCount = 0;                ///< 0..4 dual vertices
  std::array<std::uint16_t, 4> groups{};       ///< bipolar edges of each vertex (bit e); ordered by lowest edge
  std::array<std::int8_t, 12> vertexOfEdge{};  ///< vertex representing edge e, -1 if e is not bipolar
  /// Face (0..5) through which one group passes twice (2B-I / 3B-I), or -1.
  /// Meaningful in the base table only.
  std::int8_t doubleFace = -1;
};

/// @brief Table entry of `config` (bit c = corner c inside).
/// @param alternative true for Wenger's alternative grouping (the doubled
///        face resolved the other way); equal to the base entry when
///        `dmcEntry(config).doubleFace < 0`.
const DmcEntry& dmcEntry(std::uint8_t config, bool alternative = false) noexcept;

/// @brief Index (0..3) of the dual vertex of a cell with corner signs `config`
///        (and grouping `alternative`) that represents its cell edge along `axis`
///        on which the cell sits in quadrant `quadrant` around that edge
///        (bit 0 = the cell is on the +u side, bit 1 = +v; u < v the other axes);
///        -1 if that edge is not bipolar.
inline int dmcVertexOfEdge(std::uint8_t config, bool alternative, int axis, int quadrant) noexcept {
  // The edge is the cell's local edge 4 * axis + (3 - quadrant): the cell on the
  // +u side has the edge on its min-u side.
  return dmcEntry(config, alternative).vertexOfEdge[static_cast<std::size_t>(4 * axis + (3 - quadrant))];
}

/// @brief True if face f (0..5) of `config` is ambiguous: its inside corners are
///        the two ends of one diagonal.
bool isAmbiguousFace(std::uint8_t config, int face) noexcept;

namespace detail {

/// @brief Builds one entry from scratch (what the static table holds).
/// @param flippedFaces bit f set: resolve ambiguous face f with the outside
///        corners separated instead of the inside ones.
DmcEntry buildDmcEntry(std::uint8_t config, std::uint8_t flippedFaces) noexcept;

}  // namespace detail

}  // namespace isovdb::cell
