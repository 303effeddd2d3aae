// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file surface_deviation.h
/// @brief How far the full-resolution surface inside a coarse cell strays from
///        the plane its one dual vertex stands for: adaptive mode's error bound
///        (`--max-error`).
///
/// A coarse leaf's vertex comes from the crossings on the leaf's twelve edges
/// only, so a bump, a sagitta or a rounded corner inside the leaf does not show
/// in its QEF residual. This reads what regular mode would mesh there instead:
/// the crossing on every bipolar unit edge of the closed cell (linear
/// interpolation, as cell/edge_intersection.h). The reference plane goes
/// through the vertex; its normal is the field's gradient there (trilinear,
/// cell/trilinear.h) or, where that vanishes, the area-weighted mean of the
/// surface's normals read off the same edges: a plane with unit normal n is
/// crossed by |n_a| unit edges along axis a per unit of area, each rising in the
/// direction of n_a's sign, so summing those signs gives n times the area.
#pragma once

#include <array>

#include "isovdb/cell/meta_cell_samples.h"
#include "isovdb/octree/sample_phases.h"
#include "isovdb/vec3.h"

namespace isovdb::octree {

/// @brief Largest distance (voxels) from a crossing on a bipolar unit edge of
///        the closed cell [origin, origin + size]^3 to the plane through
///        `vertex` (meta-cell offsets) with the field's normal there;
///        0 if no unit edge is bipolar, +infinity if their normals cancel out.
/// @pre the cell lies in [0, S]^3; `phases` were computed from `samples` at `iso`.
float surfaceDeviation(const cell::MetaCellSamples& samples, const SamplePhases& phases, std::array<int, 3> origin,
                       int size, const Vec3f& vertex, float iso);

/// @brief surfaceDeviation(...) > allowed, decided at the first crossing beyond
///        `allowed` where the field has a normal at the vertex (the octree's plane
///        test: a tenth of the cells it reads are split, most of them early on).
bool surfaceDeviatesBeyond(const cell::MetaCellSamples& samples, const SamplePhases& phases, std::array<int, 3> origin,
                           int size, const Vec3f& vertex, float iso, float allowed);

}  // namespace isovdb::octree
