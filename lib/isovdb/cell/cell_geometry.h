// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file cell_geometry.h
/// @brief The numbering of a cell's corners, edges and faces that the octree's
///        keys, the DMC table and the dual vertices share. Header-only, constexpr.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "isovdb/bit_count.h"

namespace isovdb::cell {

/// @name Cell corners, edges and faces (shared numbering for octree and contour)
/// Corner c (0..7) is at offset ((c & 1), (c >> 1) & 1, (c >> 2) & 1) * cellSize,
/// like the octants. Edge e (0..11) runs along axis e / 4; its 2-bit index
/// q = e % 4 gives the position on the two other axes u < v (bit 0 -> u,
/// bit 1 -> v). Face f (0..5) is 2 * axis + side (side 0 = min, 1 = max).
/// @{

/// @brief The two axes other than `axis`, ascending.
constexpr std::array<int, 2> otherAxes(int axis) noexcept {
  return axis == 0 ? std::array<int, 2>{1, 2} : axis == 1 ? std::array<int, 2>{0, 2} : std::array<int, 2>{0, 1};
}

/// @brief The voxel of quadrant q around the unit edge that starts at `start` along `axis`:
///        bit 0 of q the side on u, bit 1 on v (u < v the other axes; clear = min side, where
///        the edge lies on the voxel's max side).
constexpr std::array<int, 3> edgeQuadrantVoxel(std::array<int, 3> start, int axis, int q) noexcept {
  const auto uv = otherAxes(axis);
  start[static_cast<std::size_t>(uv[0])] += (q & 1) - 1;
  start[static_cast<std::size_t>(uv[1])] += ((q >> 1) & 1) - 1;
  return start;
}

/// @brief Axis of cell edge e.
constexpr int cellEdgeAxis(int edge) noexcept { return edge >> 2; }

/// @brief Corner at end 0 (min) or 1 (max) of cell edge e.
constexpr int cellEdgeCorner(int edge, int end) noexcept {
  const int axis = edge >> 2, q = edge & 3;
  const auto uv = otherAxes(axis);
  return ((q & 1) << uv[0]) | (((q >> 1) & 1) << uv[1]) | (end << axis);
}

/// @brief The start (min end) of cell edge e of the cell of side `size` whose min corner is `origin`.
constexpr std::array<int, 3> cellEdgeStart(std::array<int, 3> origin, int size, int edge) noexcept {
  const int c0 = cellEdgeCorner(edge, 0);
  for (std::size_t a = 0; a < 3; ++a) origin[a] += ((c0 >> a) & 1) * size;
  return origin;
}

/// @brief Cell edge index from its axis and the min corner's bits on the other two axes.
constexpr int cellEdgeIndex(int axis, int cornerBits) noexcept {
  const auto uv = otherAxes(axis);
  return axis * 4 + ((cornerBits >> uv[0]) & 1) + (((cornerBits >> uv[1]) & 1) << 1);
}

/// @brief Bit mask of the 4 cell edges lying on face f.
constexpr std::uint16_t cellFaceEdgeMask(int face) noexcept {
  const int axis = face >> 1, side = face & 1;
  std::uint16_t mask = 0;
  for (int e = 0; e < 12; ++e)
    if (cellEdgeAxis(e) != axis && ((cellEdgeCorner(e, 0) >> axis) & 1) == side)
      mask = static_cast<std::uint16_t>(mask | (1u << e));
  return mask;
}

/// @brief Bit mask of the (two) edges of face f that end at `corner` (a corner of f).
constexpr std::uint16_t cellFaceEdgesAtCorner(int face, int corner) noexcept {
  std::uint16_t mask = 0;
  const std::uint16_t onFace = cellFaceEdgeMask(face);
  for (int e = 0; e < 12; ++e)
    if (((onFace >> e) & 1) && (cellEdgeCorner(e, 0) == corner || cellEdgeCorner(e, 1) == corner))
      mask = static_cast<std::uint16_t>(mask | (1u << e));
  return mask;
}

/// @brief Edges whose end corners have different inside/outside signs
///        (bit e set), from an 8-bit corner sign configuration (bit c = corner c inside).
constexpr std::uint16_t bipolarEdgeMask(std::uint8_t cornerSigns) noexcept {
  std::uint16_t mask = 0;
  for (int e = 0; e < 12; ++e)
    if (((cornerSigns >> cellEdgeCorner(e, 0)) & 1) != ((cornerSigns >> cellEdgeCorner(e, 1)) & 1))
      mask = static_cast<std::uint16_t>(mask | (1u << e));
  return mask;
}

/// @brief True for the four configurations whose only inside corners are the two ends of a body diagonal.
constexpr bool isTubeConfig(std::uint8_t cornerSigns) noexcept {
  const auto bits = static_cast<unsigned>(cornerSigns);
  if (countBits(bits) != 2) return false;  // (std::popcount is a libgcc call on Debian's x86-64)
  return ((bits >> (std::countr_zero(bits) ^ 7)) & 1u) != 0;
}

/// @brief True where the voxel reading of masks (26-connected inside, 6-connected outside;
///        contour/voxel_dmc.h) and Wenger's manifold DMC can read a cell differently: a face
///        whose inside corners are the two ends of one diagonal, or inside corners that are
///        only the two ends of a body diagonal (a tube). Every other configuration has one
///        reading: its DMC groups.
constexpr bool voxelReadingDiffers(std::uint8_t cornerSigns) noexcept {
  const auto inside = [cornerSigns](int c) { return ((cornerSigns >> c) & 1) != 0; };
  for (int face = 0; face < 6; ++face) {
    const int axis = face >> 1, side = face & 1;
    const auto uv = otherAxes(axis);
    const auto corner = [&](int du, int dv) { return (side << axis) | (du << uv[0]) | (dv << uv[1]); };
    const bool a = inside(corner(0, 0)), b = inside(corner(1, 0)), c = inside(corner(0, 1)), d = inside(corner(1, 1));
    if (a == d && b == c && a != b) return true;
  }
  return isTubeConfig(cornerSigns);
}
/// @}

}  // namespace isovdb::cell
