// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/cell/qef.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <optional>

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

/// The QEF's minimiser offset from the mass point when A^T A (`ata`) keeps one singular
/// value under the truncation `threshold`, the usual case (a smooth surface's normals in
/// one cell are nearly parallel): c = v (v . atr) / s with (s, v) the dominant eigenpair,
/// found by power iteration (each step divides the error by s / s2, at least 1 / threshold).
/// The other two eigenvalues follow from the trace and the principal minors, which tells
/// whether they are truncated. Empty where that is not certain (rank 2 or 3, a value
/// near the cutoff, no convergence): the eigendecomposition decides then.
/// Returns the kept eigenvector in `kept`. Half the time of Eigen's closed form.
std::optional<Eigen::Vector3d> rankOneOffset(const Eigen::Matrix3d& ata, const Eigen::Vector3d& atr, double threshold,
                                             Eigen::Vector3d& kept) {
  const double trace = ata.trace();
  if (!(trace > 0.0) || !(threshold > 0.0)) return std::nullopt;
  Eigen::Index start = 0;
  ata.diagonal().maxCoeff(&start);
  Eigen::Vector3d v = ata.col(start).normalized();  // sum_i n_i n_i[start]: near the dominant direction
  double s = 0.0;
  // Converged when |A^T A v - s v| <= 10^-7 s: v is then within 10^-7 / (1 - threshold)
  // radians of the eigenvector, far below a float coordinate's rounding.
  constexpr int kMaxSteps = 32;
  constexpr double kResidual = 1e-7;
  for (int step = 0;; ++step) {
    const Eigen::Vector3d w = ata * v;
    s = v.dot(w);
    if ((w - s * v).squaredNorm() <= kResidual * kResidual * s * s) break;
    if (step == kMaxSteps) return std::nullopt;
    v = w.normalized();
  }
  // The other two eigenvalues: their sum and product from the trace and the sum of A^T A's
  // principal 2x2 minors (the characteristic polynomial's coefficients).
  const double minors = ata(0, 0) * ata(1, 1) - ata(0, 1) * ata(0, 1) + ata(0, 0) * ata(2, 2) - ata(0, 2) * ata(0, 2) +
                        ata(1, 1) * ata(2, 2) - ata(1, 2) * ata(1, 2);
  const double sum = trace - s, product = minors - s * sum;
  const double second = 0.5 * (sum + std::sqrt(std::max(sum * sum - 4.0 * product, 0.0)));
  // `second` is exact to about 3e-8 s (the square root of the minors' rounding), so values
  // within 1e-7 s of the cutoff go to the eigendecomposition.
  if (second >= (threshold - 1e-7) * s) return std::nullopt;
  kept = v;
  return v * (v.dot(atr) / s);
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
  Eigen::Vector3d kept;
  if (const std::optional<Eigen::Vector3d> c = rankOneOffset(ata, atr, options.singularValueThreshold, kept)) {
    s.rank = 1;
    s.point = toVec3f(mass + *c);
    s.massPoint = toVec3f(mass);
    if (options.positionOnly) return s;
    // The truncated directions span the plane normal to the kept one; any unit basis of it.
    const Eigen::Vector3d u = kept.unitOrthogonal(), w = kept.cross(u);
    s.freeDirections[0] = toVec3f(u);
    s.freeDirections[1] = toVec3f(w);
    s.error = qefError(points, normals, s.point);
    return s;
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
  if (!options.positionOnly) s.error = qefError(points, normals, s.point);
  return s;
}

}  // namespace isovdb::cell
