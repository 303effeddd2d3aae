// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/contour/quad_diagonal.h"

#include <Eigen/Geometry>
#include <algorithm>

namespace isovdb::contour {

double squaredTriangleQuality(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) noexcept {
  const Eigen::Vector3d u = b - a, v = c - a, w = c - b;
  const double area2 = u.cross(v).squaredNorm();  // (twice the area)^2
  const double sum = u.squaredNorm() + v.squaredNorm() + w.squaredNorm();
  return sum > 0.0 ? area2 / (sum * sum) : 0.0;
}

bool firstDiagonalIsBetter(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                           const Eigen::Vector3d& p3) noexcept {
  const double through02 = std::min(squaredTriangleQuality(p0, p1, p2), squaredTriangleQuality(p0, p2, p3));
  const double through13 = std::min(squaredTriangleQuality(p0, p1, p3), squaredTriangleQuality(p1, p2, p3));
  return through02 >= through13;
}

}  // namespace isovdb::contour
