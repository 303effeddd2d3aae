// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file crease_crossing.h
/// @brief An edge crossing near a crease of the distance field, placed and
///        oriented from the side of the crease that it lies on.
///
/// Why: a distance field is linear on each side of a sharp edge (a plane face)
/// or nearly so (a curved face), but not across it. Near the crease the
/// linear interpolation between the edge's two samples misplaces the crossing
/// (by up to about half a voxel: one sample reads the other face's distance),
/// and the Prewitt stencil (gradient.h) blends the normals of both faces, so
/// the tangent planes of the dual vertex's QEF lean across the crease and the
/// vertex leaves the feature line.
///
/// The unit voxels of the two end samples' 3x3x3 neighbourhoods (12 voxels
/// around the edge) each get a least-squares plane through their 8 corners.
/// Where every voxel's plane fits its corners and passes through the linearly
/// interpolated crossing, the field is smooth there and nothing changes.
/// Otherwise a voxel wholly on one side of the crease fits its corners exactly
/// (a face) or almost (a curved face), and the face that the crossing lies on
/// is the one whose plane predicts an end sample of the edge and meets the edge
/// between its samples: the crossing is that plane's zero on the edge and the
/// normal its gradient (averaged over the voxels that agree with it).
/// Positions are meta-cell offsets; gradients point outward for an SDF.
#pragma once

#include <array>

#include "isovdb/cell/gradient.h"
#include "isovdb/cell/meta_cell_samples.h"

namespace isovdb::cell {

/// A crossing taken from one side of a crease.
struct CreaseCrossing {
  float t = 0.0f;                    ///< along the edge from `sample0`, in [0, 1]
  Vec3f gradient{0.0f, 0.0f, 0.0f};  ///< of the face the crossing lies on (not normalised)
};

/// @brief Crossing on the unit edge from `sample0` along `axis`, linearly
///        interpolated at `t`, re-placed on the face of a nearby crease.
/// @return false where the field is smooth around the edge (keep `t` and the
///         Prewitt gradient) or no voxel plane qualifies.
/// @pre sample0 and sample0 + e_axis in [0, S]^3 (the apron covers the stencil); t in [0, 1].
bool crossingBesideCrease(const cell::MetaCellSamples& samples, std::array<int, 3> sample0, int axis, float t,
                          float iso, CreaseCrossing& out) noexcept;

}  // namespace isovdb::cell
