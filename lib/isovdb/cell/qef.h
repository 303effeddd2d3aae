// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file qef.h
/// @brief Quadratic error function of dual contouring, minimised towards the
///        mass point with the SVD pseudo-inverse (paper 000, eq. 4-1 and 4-2;
///        Schaefer and Warren 2003).
///
/// E(x) = sum_i (n_i . (x - p_i))^2 ; with A the rows n_i and b_i = n_i . p_i,
/// x = p + (A^T A)^+ (A^T b - A^T A p), p the mass point (mean of the p_i).
/// Singular values of A^T A below `singularValueThreshold` times the largest
/// are truncated, so flat or degenerate systems move the vertex only along
/// the well-determined directions.
#pragma once

#include <array>
#include <span>

#include "isovdb/vec3.h"

namespace isovdb::cell {

using isovdb::Vec3f;

/// Options of solveQef.
struct QefOptions {
  float singularValueThreshold = 0.1f;  ///< relative to the largest singular value of A^T A;
                                        ///< higher = smoother (fewer sharp features), lower = sharper but less stable
  /// Only the point, the mass point and the rank are wanted: error and freeDirections stay 0.
  bool positionOnly = false;
};

/// @brief Minimiser of a QEF.
struct QefSolution {
  Vec3f point{0.0f, 0.0f, 0.0f};      ///< minimiser nearest the mass point
  Vec3f massPoint{0.0f, 0.0f, 0.0f};  ///< mean of the points
  float error = 0.0f;                 ///< E(point), squared distance units
  int rank = 0;                       ///< singular values kept (0..3)
  /// Directions along which E is (nearly) flat: 3 - rank unit vectors spanning the truncated
  /// singular vectors' space (at rank 1 any orthonormal basis of it; at rank 2 the truncated
  /// vector itself); every point + sum t_i freeDirections[i] fits about as well.
  std::array<Vec3f, 3> freeDirections{};
};

/// @brief Solves the QEF of `points` and unit `normals` (same count).
/// @pre points.size() == normals.size(); an empty input returns all zeros.
QefSolution solveQef(std::span<const Vec3f> points, std::span<const Vec3f> normals, const QefOptions& options = {});

/// @brief The mass point of a QEF and how far solveQef's minimiser can lie from it, found
///        without the eigendecomposition.
struct QefReach {
  Vec3f massPoint{0.0f, 0.0f, 0.0f};  ///< mean of the points (as solveQef's, to rounding)
  /// Upper bound of |solveQef(...).point - massPoint| (exact arithmetic); +infinity where
  /// the threshold or the normals give none.
  double reach = 0.0;
};

/// @brief qefReach: the minimiser is massPoint + c with c in the span of the kept
///        eigenvectors v_j of A^T A, whose eigenvalues s_j are at least the threshold
///        times the largest, itself at least A^T A's largest diagonal entry D. With
///        d_i = n_i . (p_i - massPoint), v_j . A^T d = sum_i (v_j . n_i) d_i is at most
///        sqrt(s_j) |d| (Cauchy-Schwarz), so |c|^2 <= |d|^2 sum_j 1 / s_j
///        <= 3 |d|^2 / (threshold D). A point clamped into a box that holds the mass
///        point moves no farther from it.
QefReach qefReach(std::span<const Vec3f> points, std::span<const Vec3f> normals, const QefOptions& options = {});

/// @brief E(x) for the given planes.
float qefError(std::span<const Vec3f> points, std::span<const Vec3f> normals, const Vec3f& x) noexcept;

}  // namespace isovdb::cell
