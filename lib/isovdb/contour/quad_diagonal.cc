// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/contour/quad_diagonal.h"

#include <Eigen/Geometry>
#include <algorithm>

namespace isovdb::contour {

namespace {

/// Shape quality of triangle (a, b, c), squared, up to a constant factor: (twice its area /
/// the sum of its squared edge lengths)^2, which orders triangles as 4 sqrt(3) area / sum
/// (1 = equilateral) does, without a square root. 0 for a degenerate triangle.
double squaredTriangleQuality(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) noexcept {
  const Eigen::Vector3d u = b - a, v = c - a, w = c - b;
  const double area2 = u.cross(v).squaredNorm();  // (twice the area)^2
  const double sum = u.squaredNorm() + v.squaredNorm() + w.squaredNorm();
  return sum > 0.0 ? area2 / (sum * sum) : 0.0;
}

}  // namespace

bool firstDiagonalIsBetter(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                           const Eigen::Vector3d& p3) noexcept {
  const double through02 = std::min(squaredTriangleQuality(p0, p1, p2), squaredTriangleQuality(p0, p2, p3));
  const double through13 = std::min(squaredTriangleQuality(p0, p1, p3), squaredTriangleQuality(p1, p2, p3));
  return through02 >= through13;
}

}  // namespace isovdb::contour
