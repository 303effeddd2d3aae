// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/reservoir/jacobian_normals.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace isovdb::reservoir {

Vec3d cornerGradient(const CornerPointGrid& grid, const CornerField& field, const HexCell& cell, int corner) {
  const double v = cell.values[static_cast<std::size_t>(corner)];
  std::array<Vec3d, 3> jacobian;  // columns
  Vec3d gradientU;
  double largest = 0;
  for (int a = 0; a < 3; ++a) {
    const int bit = (corner >> a) & 1;
    const int other = corner ^ (1 << a);
    const double sign = bit ? 1.0 : -1.0;  // +u lies towards the neighbour when bit is 1
    jacobian[a] = sign * (cell.points[static_cast<std::size_t>(corner)] - cell.points[static_cast<std::size_t>(other)]);
    largest = std::max(largest, jacobian[a].cwiseAbs().maxCoeff());
    const double near = cell.values[static_cast<std::size_t>(other)];
    double derivative = sign * (v - near);
    // The neighbour cell along this axis on the side of the corner: its corner with the
    // same bits lies one cell further along the axis.
    if (const std::size_t neighbour = cell.neighbour(a, bit); neighbour != HexCell::kNone) {
      const double far = field.value(grid, neighbour, corner);
      if (std::isfinite(far)) derivative = 0.5 * sign * (far - near);
    }
    gradientU[a] = derivative;
  }
  // J^-T g from the cofactors: the columns of J^-T are (j1 x j2, j2 x j0, j0 x j1) / det J.
  const Vec3d c0 = jacobian[1].cross(jacobian[2]), c1 = jacobian[2].cross(jacobian[0]),
              c2 = jacobian[0].cross(jacobian[1]);
  const double det = jacobian[0].dot(c0);
  if (!(std::abs(det) > 1e-12 * largest * largest * largest)) return Vec3d::Zero();
  return (gradientU[0] * c0 + gradientU[1] * c1 + gradientU[2] * c2) / det;
}

}  // namespace isovdb::reservoir
