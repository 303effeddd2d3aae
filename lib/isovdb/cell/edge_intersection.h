// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file edge_intersection.h
/// @brief Where the surface crosses a cell edge: scan the samples along the
///        edge for the inside/outside transition and interpolate linearly
///        between the two transition samples (paper 000, section 4.2.2).
///
/// Sign convention: inside iff value <= iso. Positions are meta-cell offsets.
#pragma once

#include <array>

#include "isovdb/cell/gradient.h"
#include "isovdb/cell/meta_cell_samples.h"

namespace isovdb::cell {

/// @brief A surface crossing on an edge.
struct EdgeIntersection {
  Vec3f point{0.0f, 0.0f, 0.0f};   ///< crossing, meta-cell offsets (voxels)
  Vec3f normal{0.0f, 0.0f, 0.0f};  ///< unit gradient there (outward; Prewitt's, or the face's beside a
                                   ///< crease with sharpFeatures); 0 if the gradient vanishes
  int transitions = 0;             ///< sign changes seen along the whole edge (1 for a simple edge)
};

/// @brief Finds the first inside/outside transition along the edge from `start`
///        over `length` unit steps on `axis`; the point is the linear
///        interpolation of the iso value between the two transition samples.
/// @param sharpFeatures  near a crease of the field, place and orient the crossing
///        from the face it lies on (crease_crossing.h) instead.
/// @return false if the samples along the edge are all one phase.
/// @pre the edge lies in [0, S]^3 (so that gradients are defined).
bool intersectEdge(const cell::MetaCellSamples& samples, std::array<int, 3> start, int axis, int length, float iso,
                   EdgeIntersection& out, bool sharpFeatures = false) noexcept;

/// @brief Where the level crosses between two samples on either side of it (one <= iso <
///        other), as a fraction of the way from the first, in [0, 1].
inline float crossingFraction(float v0, float v1, float iso) noexcept {
  const float t = (iso - v0) / (v1 - v0);  // v1 != v0: they lie on either side of iso
  return t < 0.0f ? 0.0f : (t > 1.0f ? 1.0f : t);
}

/// @brief intersectEdge's crossing of a bipolar unit edge (length 1, without sharp features)
///        with the Prewitt gradients of its two samples given (`g0` at `start`, `g1` one step
///        along `axis`): the same point and normal, bit for bit, for a caller that finds each
///        sample's gradient once (octree/unit_edge_crossings.cc).
/// @pre the edge is bipolar at `iso` and lies in [0, S]^3.
EdgeIntersection unitEdgeCrossing(const cell::MetaCellSamples& samples, const std::array<int, 3>& start, int axis,
                                  float iso, const Vec3f& g0, const Vec3f& g1) noexcept;

}  // namespace isovdb::cell
