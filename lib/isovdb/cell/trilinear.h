// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file trilinear.h
/// @brief The field between samples: trilinear interpolation of a meta-cell's
///        samples, its gradient, and the first-order distance to a level that
///        adaptive mode's error bound measures (octree/surface_deviation.h,
///        contour/error_bound.h).
#pragma once

#include "isovdb/cell/meta_cell_samples.h"
#include "isovdb/vec3.h"

namespace isovdb::cell {

/// The trilinear field at a point, minus the isovalue, and its gradient (per voxel).
struct TrilinearSample {
  float value = 0.0f;
  Vec3f gradient{0.0f, 0.0f, 0.0f};
};

/// @brief Trilinear interpolation at `point` (meta-cell offsets, clamped to the unit
///        cells of [0, S]^3), minus `iso`.
TrilinearSample trilinearAt(const MetaCellSamples& samples, const Vec3f& point, float iso) noexcept;

/// @brief First-order distance (voxels) from `point` to the level `iso`:
///        |f - iso| / |grad f| of the trilinear field (exact on a linear field, the
///        distance itself on a distance field); +infinity where the gradient vanishes
///        off the level.
float distanceToLevel(const MetaCellSamples& samples, const Vec3f& point, float iso) noexcept;

}  // namespace isovdb::cell
