// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file surface_gap.h
/// @brief How far a point must at least be from the zero level of a distance
///        field, judged from the samples of a cell (the refinement criterion
///        of features: octree/build.h).
///
/// Why: the dual vertex of a coarse leaf on a curved sharp rim sits where the
/// tangent planes of its few crossings meet, outside the rim by up to about
/// r (1 / cos(theta / 2) - 1) for crossings theta apart. The planes fit almost
/// exactly, so the QEF residual cannot see it; neither can a trilinear
/// interpolation, which is not zero on a sharp edge either. A distance field is
/// 1-Lipschitz: a sample s at distance |f(s) - iso| from the surface is at most
/// |s - x| + dist(x, surface) from it, so
///   gap(x) = max over samples s of (|f(s) - iso| - |s - x|)
/// is a lower bound on dist(x, surface), and it is 0 (up to the field's error)
/// for any point on the surface, on a sharp edge or corner too.
/// Positions are meta-cell offsets (voxels).
#pragma once

#include <array>

#include "isovdb/cell/meta_cell_samples.h"

namespace isovdb::octree {

/// Samples beyond the cell that the bound also reads, per side (voxels; within the apron).
inline constexpr int kGapMargin = 2;

/// @brief gap(x) over the samples of the cell with min corner `origin` and side `size`,
///        grown by kGapMargin on each side (clipped to the block, apron included).
/// @pre the cell lies in [0, S]^3.
float surfaceGap(const cell::MetaCellSamples& samples, std::array<int, 3> origin, int size,
                 const std::array<float, 3>& x, float iso) noexcept;

}  // namespace isovdb::octree
