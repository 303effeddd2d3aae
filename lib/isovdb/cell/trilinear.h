// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file trilinear.h
/// @brief The field between samples: trilinear interpolation of a meta-cell's
///        samples, its gradient, and the first-order distance to a level that
///        adaptive mode's error bound measures (octree/surface_deviation.h,
///        contour/error_bound.h), and a witness of the level near a point.
#pragma once

#include "isovdb/cell/meta_cell_samples.h"
#include "isovdb/vec3.h"

namespace isovdb::cell {

struct DualVertexOptions;  // dual_vertex.h

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

/// @brief True if the full-resolution surface at `options.iso` lies within `radius` of `point`
///        (meta-cell offsets): by the first-order distance to the level where the level
///        crosses the point's cell, or else shown by a witness, a vertex full-resolution
///        contouring places (manifold DMC's groups, a QEF vertex for a single group and mass
///        points for several, as the error bound's check places them) in a unit cell of the
///        meta-cell. The witness is a point of regular mode's mesh, which the bound is measured
///        against. Beside a thin structure the gradient nearly vanishes and the first-order
///        distance says nothing (points half a voxel from the frog's bones read as up to 7 voxels
///        away); in a cell the level does not cross it extrapolates (in a one-voxel gap between
///        two bodies it read 0.8 voxel where regular mode's mesh was 1.13 away); and the level's
///        own crossing, the witness before, is not a point of the mesh (on a body one voxel thin
///        regular mode's vertices lie about 0.3 voxel inside it).
bool levelWithin(const MetaCellSamples& samples, const Vec3f& point, const DualVertexOptions& options,
                 float radius) noexcept;

}  // namespace isovdb::cell
