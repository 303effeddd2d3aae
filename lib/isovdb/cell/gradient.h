// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file gradient.h
/// @brief Prewitt 3x3x3 gradient of the distance field (paper 000, section 4.2.2).
///
/// The x derivative at a sample is the mean over the 3 x 3 samples of the
/// (y, z) neighbourhood of the central difference (v(i+1) - v(i-1)) / 2, in
/// value units per voxel; likewise for y and z. For an SDF (negative inside)
/// the gradient points outward. Positions are meta-cell offsets.
#pragma once

#include <array>

#include "isovdb/cell/meta_cell_samples.h"
#include "isovdb/vec3.h"

namespace isovdb::cell {

using isovdb::Vec3f;

/// @brief Prewitt gradient at sample offset (i, j, k); on a face of the data's box, the
///        one kept before the samples beyond it were overwritten (samples.boxRim).
/// @pre i, j, k in [0, S] (the apron supplies the outer neighbours).
Vec3f prewittGradient(const cell::MetaCellSamples& samples, int i, int j, int k) noexcept;

/// @brief Keeps the Prewitt gradients of the samples on the faces of the inclusive index box
///        [boxMin, boxMax] (global index coordinates) that lie inside it, as the values are now,
///        in samples.boxRim, where the block holds samples beyond a face; prewittGradient returns
///        them from then on. Called before the samples beyond the box are overwritten.
void keepBoxRimGradients(cell::MetaCellSamples& samples, const std::array<int, 3>& boxMin,
                         const std::array<int, 3>& boxMax);

/// @brief Gradient at the point `sample0 + t * e_axis` of a grid line, linearly
///        interpolated between the Prewitt gradients of its two end samples.
/// @pre sample0 and sample0 + e_axis in [0, S]^3; t in [0, 1].
Vec3f prewittGradientOnEdge(const cell::MetaCellSamples& samples, std::array<int, 3> sample0, int axis,
                            float t) noexcept;

/// @brief The gradient at parameter t of a grid line whose end samples have gradients `g0`
///        and `g1`, as prewittGradientOnEdge interpolates them (g0 itself at t <= 0).
inline Vec3f gradientBetween(const Vec3f& g0, const Vec3f& g1, float t) noexcept {
  if (t <= 0.0f) return g0;
  return {g0[0] + t * (g1[0] - g0[0]), g0[1] + t * (g1[1] - g0[1]), g0[2] + t * (g1[2] - g0[2])};
}

/// @brief Dot product.
inline float dot(const Vec3f& a, const Vec3f& b) noexcept { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// @brief Unit vector of v, or (0, 0, 0) when |v| is 0 or not finite.
Vec3f normalized(const Vec3f& v) noexcept;

}  // namespace isovdb::cell
