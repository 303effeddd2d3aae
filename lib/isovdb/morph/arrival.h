// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file arrival.h
/// @brief Time-of-arrival reparametrisation of a morph (after Nilsson, Breen and
///        Museth, 2005): every part of the contour progresses uniformly.
///
/// With the speed F = φ − φ_target the front approaches the target exponentially
/// (its speed is its distance to the target), so iterates spaced evenly in time
/// bunch up near the target (paper 002, conclusion). Instead, each pixel x the
/// front sweeps records its arrival time T(x) (fractional iteration of the sign
/// change) and the time T_end(x) at which the front reaches the target along the
/// same path (T at the target-contour point closest to x). The intermediate slice
/// at fraction s then shows, at each pixel, the iterate of time s · T_end(x): its
/// zero contour is {T / T_end = s}, every path covered in the same proportion.
#pragma once

#include "isovdb/morph/plane.h"

namespace isovdb::morph {

/// Records the last sign change of every pixel during a morph.
class ArrivalRecorder {
 public:
  explicit ArrivalRecorder(const Field2& initial);
  /// Call after each step with the previous and the new iterate; `iteration` is the new one's number (1, 2, ...).
  void record(const Field2& previous, const Field2& current, int iteration);
  /// T(x), or -1 where the sign never changed.
  const Field2& times() const { return times_; }

 private:
  Field2 times_;
};

/// @brief Per-pixel iteration scale T_end(x) for the reparametrised slices.
///
/// Swept pixels: the largest arrival time around the target-contour point closest
/// to x (found through ∇φ_target), at least T(x); where that point was never
/// reached, `iterations`. Other pixels take the value of the nearest swept pixel
/// (8-neighbour breadth-first), then two 3 × 3 box filters smooth the seams.
/// Without any swept pixel, `iterations` everywhere.
/// @param[in] times       ArrivalRecorder::times()
/// @param[in] target      the target's signed distance (same grid)
/// @param[in] iterations  iterations the morph took
Field2 arrivalScale(const Field2& times, const Field2& target, int iterations);

}  // namespace isovdb::morph
