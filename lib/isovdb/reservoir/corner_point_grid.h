// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file corner_point_grid.h
/// @brief The corner-point grid model: 8 corner positions per cell (cells need
/// not share corners: faults), active flags, and the cell values of one
/// property averaged to the corners of the active cells (paper 003 §5.1).
///
/// Corner c of a cell is (ix, iy, iz) = (c & 1, (c >> 1) & 1, (c >> 2) & 1) in
/// the cell's trilinear parameter space. Corners of cells around the same grid
/// node that coincide (within a tolerance) form one geometric *point*, and so do a
/// cell's top and bottom corners on a pillar where it has no thickness (a pinch-out:
/// the nodes of two layers); the point ids let marching cubes weld vertices exactly
/// where cells touch.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <span>
#include <vector>

#include "isovdb/reservoir/grdecl_reader.h"

namespace isovdb::reservoir {

using Vec3d = Eigen::Vector3d;

struct CornerPointGrid {
  std::array<int, 3> dims{0, 0, 0};
  std::vector<std::array<Vec3d, 8>> corners;           ///< per cell, world (file) coordinates
  std::vector<std::uint8_t> active;                    ///< per cell, ACTNUM != 0
  std::vector<std::array<std::uint32_t, 8>> pointIds;  ///< per cell corner, id of its geometric point
  std::vector<Vec3d> points;                           ///< representative position of each point
  /// The cells sharing each point (cell indices), point after point: those of point p are
  /// pointCells[pointCellStart[p] .. pointCellStart[p + 1]) (one array, not a vector per point).
  std::vector<std::uint32_t> pointCellStart{0};
  std::vector<std::uint32_t> pointCells;
  /// Per cell: kPinchedCell, kInvertedCell (both bits where both hold) or 0.
  std::vector<std::uint8_t> cellShape;
  static constexpr std::uint8_t kPinchedCell = 1;   ///< Jacobian zero at some corners, not all (a pinch-out)
  static constexpr std::uint8_t kInvertedCell = 2;  ///< Jacobian of the other sign at some corner (folded)
  int orientation = 1;             ///< sign of the Jacobian of most active cells (-1: left-handed grid)
  std::int64_t invertedCells = 0;  ///< active cells whose Jacobian has the other sign at some corner
  std::int64_t pinchedCells = 0;   ///< active cells whose Jacobian is zero at some corners, not all (pinch-outs)
  std::int64_t activeCells = 0;
  std::vector<std::string> warnings;

  std::size_t cellCount() const { return corners.size(); }
  std::span<const std::uint32_t> cellsOfPoint(std::size_t point) const {
    return {pointCells.data() + pointCellStart[point], pointCells.data() + pointCellStart[point + 1]};
  }
  std::size_t cellIndex(int i, int j, int k) const { return (static_cast<std::size_t>(k) * dims[1] + j) * dims[0] + i; }
};

struct GridOptions {
  /// Corners closer than this fraction of the bounding-box diagonal are one point.
  double relativeTolerance = 1e-7;
  /// A cell's top and bottom corners that coincide on a pillar (a pinch-out) are one point.
  /// Off: each layer of nodes keeps its own points, as grids were built before (a test of
  /// the twin cancellation that such points caused on Reek).
  bool joinPinchOuts = true;
};

/// Builds the grid of a deck. @throw InputError naming the file when COORD,
/// ZCORN or ACTNUM do not match SPECGRID or hold NaN/infinite values.
CornerPointGrid buildCornerPointGrid(const GrdeclDeck& deck, const GridOptions& options = {});

/// One property averaged to the corners: per point, the mean of the values of
/// the usable cells sharing it (active, finite value); NaN when none.
struct CornerField {
  std::vector<double> pointValues;
  std::vector<std::uint8_t> usable;  ///< per cell: active and finite value
  std::vector<std::string> warnings;
  double value(const CornerPointGrid& grid, std::size_t cell, int corner) const {
    return pointValues[grid.pointIds[cell][corner]];
  }
  /// The usable cell across the face of cell `ijk` on `axis` (`side` 1: the face towards
  /// +axis, 0: towards -axis); nothing at the grid's border or where that cell is not usable.
  std::optional<std::size_t> usableNeighbour(const CornerPointGrid& grid, std::array<int, 3> ijk, int axis,
                                             int side) const {
    ijk[axis] += side ? 1 : -1;
    if (ijk[axis] < 0 || ijk[axis] >= grid.dims[axis]) return std::nullopt;
    const std::size_t neighbour = grid.cellIndex(ijk[0], ijk[1], ijk[2]);
    if (!usable[neighbour]) return std::nullopt;
    return neighbour;
  }
};

/// @throw InputError naming the file and keyword when the property is missing
/// or its length differs from the cell count. NaN cell values are excluded (warning).
CornerField averageToCorners(const CornerPointGrid& grid, const GrdeclDeck& deck, const std::string& property);
/// The same from explicit cell values (one per cell).
CornerField averageToCorners(const CornerPointGrid& grid, const std::vector<double>& cellValues,
                             const std::string& what);

}  // namespace isovdb::reservoir
