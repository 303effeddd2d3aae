// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/cell/qef.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace isovdb::cell {

float qefError(std::span<const Vec3f> points, std::span<const Vec3f> normals, const Vec3f& x) noexcept {
  double e = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    double d = 0.0;
    for (int a = 0; a < 3; ++a) d += static_cast<double>(normals[i][a]) * (static_cast<double>(x[a]) - points[i][a]);
    e += d * d;
  }
  return static_cast<float>(e);
}

namespace {

/// The mean of `points` (not empty), in double.
Eigen::Vector3d massPointOf(std::span<const Vec3f> points) {
  Eigen::Vector3d mass = Eigen::Vector3d::Zero();
  for (const Vec3f& p : points) mass += Eigen::Vector3d(p[0], p[1], p[2]);
  return mass / static_cast<double>(points.size());
}

Vec3f toVec3f(const Eigen::Vector3d& v) {
  return {static_cast<float>(v(0)), static_cast<float>(v(1)), static_cast<float>(v(2))};
}

}  // namespace

QefReach qefReach(std::span<const Vec3f> points, std::span<const Vec3f> normals, const QefOptions& options) {
  assert(points.size() == normals.size());
  QefReach r;
  if (points.empty()) return r;
  const Eigen::Vector3d mass = massPointOf(points);
  r.massPoint = toVec3f(mass);
  double residuals = 0.0;
  Eigen::Vector3d diagonal = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d n(normals[i][0], normals[i][1], normals[i][2]);
    const double d = n.dot(Eigen::Vector3d(points[i][0], points[i][1], points[i][2]) - mass);
    residuals += d * d;
    diagonal += n.cwiseProduct(n);
  }
  const double floor = static_cast<double>(options.singularValueThreshold) * diagonal.maxCoeff();
  r.reach = residuals == 0.0 ? 0.0
            : floor > 0.0    ? std::sqrt(3.0 * residuals / floor)
                             : std::numeric_limits<double>::infinity();
  return r;
}

QefSolution solveQef(std::span<const Vec3f> points, std::span<const Vec3f> normals, const QefOptions& options) {
  assert(points.size() == normals.size());
  QefSolution s;
  if (points.empty()) return s;
  const Eigen::Vector3d mass = massPointOf(points);
  // Work relative to the mass point (well conditioned at any index magnitude):
  // minimise |A c - r|^2 with r_i = n_i . (p_i - mass), then x = mass + c.
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atr = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d n(normals[i][0], normals[i][1], normals[i][2]);
    const Eigen::Vector3d p(points[i][0], points[i][1], points[i][2]);
    ata.noalias() += n * n.transpose();
    atr += n * n.dot(p - mass);
  }
  // A^T A is symmetric positive semi-definite: its singular value decomposition is
  // its eigendecomposition (U = V). Eigen's closed form (computeDirect: the roots of
  // the characteristic cubic, eigenvectors from cross products) takes half the time of
  // its iterative solver, which was a fifth of regular contouring (one QEF per surface
  // cell). Its error is absolute, up to ~1e-10 of the largest eigenvalue where small
  // ones cluster (an exact zero comes out as 1e-10): at a truncation of at least
  // kDirectMinThreshold (default 0.1) every kept value is exact to float precision and
  // no noise is kept; a smaller truncation keeps values that small, so it gets the
  // iterative solver, which resolves them to rounding.
  constexpr float kDirectMinThreshold = 1e-3f;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  if (options.singularValueThreshold >= kDirectMinThreshold)
    eigen.computeDirect(ata);
  else
    eigen.compute(ata);
  // Eigen orders eigenvalues increasingly; singular values are taken largest first.
  Eigen::Vector3d sigma;
  Eigen::Matrix3d v;
  for (int i = 0; i < 3; ++i) {
    sigma(i) = std::max(eigen.eigenvalues()(2 - i), 0.0);
    v.col(i) = eigen.eigenvectors().col(2 - i);
  }
  Eigen::Vector3d inv = Eigen::Vector3d::Zero();
  const double cutoff = sigma(0) * static_cast<double>(options.singularValueThreshold);
  int free = 0;
  for (int i = 0; i < 3; ++i)
    if (sigma(i) > 0.0 && sigma(i) >= cutoff) {
      inv(i) = 1.0 / sigma(i);
      ++s.rank;
    } else {
      const Eigen::Vector3d d = v.col(i);
      s.freeDirections[static_cast<std::size_t>(free++)] = {static_cast<float>(d(0)), static_cast<float>(d(1)),
                                                            static_cast<float>(d(2))};
    }
  const Eigen::Vector3d c = v * inv.asDiagonal() * v.transpose() * atr;
  const Eigen::Vector3d x = mass + c;
  s.point = toVec3f(x);
  s.massPoint = toVec3f(mass);
  s.error = qefError(points, normals, s.point);
  return s;
}

}  // namespace isovdb::cell
