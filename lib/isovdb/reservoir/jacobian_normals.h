// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file jacobian_normals.h
/// @brief Gradient of the corner field at a cell corner (paper 003 Fig. 5.4–5.5):
/// central differences in parameter space (i, j, k) with the corner of the
/// neighbour cell one step further along each axis (one-sided at the grid
/// border and next to unusable cells), mapped to world space with the inverse
/// transpose of the trilinear map's Jacobian at that corner.
#pragma once

#include "isovdb/reservoir/corner_point_grid.h"
#include "isovdb/reservoir/hex_cell.h"

namespace isovdb::reservoir {

/// World-space gradient of `field` at corner `corner` of `cell`; zero when the cell's
/// Jacobian is singular there (a collapsed cell).
Vec3d cornerGradient(const CornerPointGrid& grid, const CornerField& field, const HexCell& cell, int corner);

}  // namespace isovdb::reservoir
