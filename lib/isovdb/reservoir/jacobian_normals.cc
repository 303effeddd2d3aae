// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/reservoir/jacobian_normals.h"

#include <Eigen/Dense>

#include <cmath>

namespace isovdb::reservoir {

Vec3d cornerGradient(const CornerPointGrid& grid, const CornerField& field, std::size_t cell, int corner) {
  const std::array<int, 3> ijk{static_cast<int>(cell % grid.dims[0]),
                               static_cast<int>((cell / grid.dims[0]) % grid.dims[1]),
                               static_cast<int>(cell / (static_cast<std::size_t>(grid.dims[0]) * grid.dims[1]))};
  const auto& p = grid.corners[cell];
  const double v = field.value(grid, cell, corner);
  Eigen::Matrix3d jacobian;
  Vec3d gradientU;
  for (int a = 0; a < 3; ++a) {
    const int bit = (corner >> a) & 1;
    const int other = corner ^ (1 << a);
    const double sign = bit ? 1.0 : -1.0;  // +u lies towards the neighbour when bit is 1
    jacobian.col(a) = sign * (p[corner] - p[other]);
    const double own = sign * (v - field.value(grid, cell, other));
    // The neighbour cell along this axis on the side of the corner.
    std::array<int, 3> n = ijk;
    n[a] += bit ? 1 : -1;
    double derivative = own;
    if (n[a] >= 0 && n[a] < grid.dims[a]) {
      const std::size_t neighbour = grid.cellIndex(n[0], n[1], n[2]);
      if (field.usable[neighbour]) {
        // Its corner with the same bits lies one cell further along the axis.
        const double far = field.value(grid, neighbour, corner);
        const double near = field.value(grid, cell, other);
        if (std::isfinite(far)) derivative = 0.5 * sign * (far - near);
      }
    }
    gradientU[a] = derivative;
  }
  const double det = jacobian.determinant();
  if (!(std::abs(det) >
        1e-12 * jacobian.cwiseAbs().maxCoeff() * jacobian.cwiseAbs().maxCoeff() * jacobian.cwiseAbs().maxCoeff()))
    return Vec3d::Zero();
  return jacobian.transpose().inverse() * gradientU;
}

}  // namespace isovdb::reservoir
