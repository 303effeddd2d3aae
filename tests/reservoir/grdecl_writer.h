// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file grdecl_writer.h
/// @brief Writes synthetic corner-point grids as real GRDECL text for the tests:
/// a regular box of cells, optionally with a fault throw or mirrored (left-handed).
#pragma once

#include <Eigen/Core>

#include <filesystem>
#include <functional>
#include <string>

namespace isovdb::test {

struct BoxGrid {
  int nx = 10, ny = 10, nz = 10;
  double cell = 1.0;   ///< cell edge length
  double layer = 0.0;  ///< cell height along z (0: `cell`), for thin layers
  Eigen::Vector3d origin{0, 0, 0};
  double faultThrow = 0.0;                                   ///< z offset of the cells with i >= nx/2 (a fault)
  bool mirrorX = false;                                      ///< x = origin - i*cell: a left-handed grid
  std::function<double(const Eigen::Vector3d&)> field = {};  ///< property at the cell centres
  std::function<bool(int, int, int)> active = {};            ///< empty: all active
  std::function<double(int, int)> pillarShift = {};          ///< z added to every node of pillar (i, j): twisted faces
  /// Thickness of layer k at pillar (i, j) (empty: `layer`, or `cell`); 0 where the layer pinches out.
  std::function<double(int, int, int)> thickness = {};
};

/// World position of node (i, j, k) of the cell column i (fault throw applied by column).
Eigen::Vector3d boxNode(const BoxGrid& grid, int i, int j, int k, int columnI);
/// GRDECL text with SPECGRID, COORD, ZCORN, ACTNUM and the property `name`.
std::string boxGrdecl(const BoxGrid& grid, const std::string& name = "PROP");

}  // namespace isovdb::test
