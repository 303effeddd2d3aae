// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file hex_cell.h
/// @brief One cut cell of a corner-point grid gathered once for Marching Cubes: its
/// points, corner values and usable face neighbours. Its contouring reads them many
/// times (the Jacobian at the centre, each corner's gradient, the fault test of each
/// vertex, the fan depths), and the six neighbours replace up to 24 look-ups by the
/// corners' gradients and the vertices' fault tests.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "isovdb/reservoir/corner_point_grid.h"

namespace isovdb::reservoir {

struct HexCell {
  static constexpr std::size_t kNone = ~std::size_t{0};

  std::size_t index = 0;
  std::array<int, 3> ijk{0, 0, 0};
  const std::array<std::uint32_t, 8>* ids = nullptr;  ///< the grid's point ids of the corners
  std::array<Vec3d, 8> points;                        ///< grid.points of the corners
  std::array<double, 8> values{};                     ///< field.pointValues of the corners
  /// The usable cell across the face on [axis][side] (CornerField::usableNeighbour), or kNone.
  std::array<std::array<std::size_t, 2>, 3> across{};

  HexCell(const CornerPointGrid& grid, const CornerField& field, std::size_t cell, const std::array<int, 3>& at)
      : index(cell), ijk(at), ids(&grid.pointIds[cell]) {
    for (int c = 0; c < 8; ++c) {
      points[static_cast<std::size_t>(c)] = grid.points[(*ids)[static_cast<std::size_t>(c)]];
      values[static_cast<std::size_t>(c)] = field.pointValues[(*ids)[static_cast<std::size_t>(c)]];
    }
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side)
        across[static_cast<std::size_t>(axis)][static_cast<std::size_t>(side)] =
            field.usableNeighbour(grid, ijk, axis, side).value_or(kNone);
  }

  std::uint32_t id(int corner) const { return (*ids)[static_cast<std::size_t>(corner)]; }
  std::size_t neighbour(int axis, int side) const {
    return across[static_cast<std::size_t>(axis)][static_cast<std::size_t>(side)];
  }
};

}  // namespace isovdb::reservoir
