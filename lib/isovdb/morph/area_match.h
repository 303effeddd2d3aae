// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file area_match.h
/// @brief Sets the area of an intermediate slice: φ is shifted by one constant so
///        that exactly `area` pixels are inside (φ <= 0). The morph gives the shape,
///        this gives the size.
///
/// Why (bench/morph_eval.py, ARCHITECTURE.md "Where we depart from paper 002"): a
/// morph that moves each front point along its normal loses area wherever parts
/// of a section move sideways (the front lags where its normal is not the direction
/// to the target) and where a section grows from a small cap (a contour progressing
/// uniformly in distance grows its area quadratically, a smooth solid's cap
/// linearly). The cross-section area of a smooth solid is linear between two close
/// slices up to second order, so the slice at fraction s gets (1 - s) A_a + s A_b.
/// This is the global mass correction of level-set methods (one offset per slice).
#pragma once

#include <cstdint>

#include "isovdb/morph/plane.h"

namespace isovdb::morph {

/// @brief Shifts `phi` by the constant that leaves exactly `area` pixels at or below
///        zero (half-way between the area-th and the (area + 1)-th smallest values, so
///        pixels of equal value stay on one side). area <= 0 empties φ (its smallest
///        value goes to +0.5); no-op for area >= size or when φ is already empty.
/// @return the constant subtracted (pixels when φ is a distance).
double shiftToArea(Field2& phi, std::int64_t area);

}  // namespace isovdb::morph
