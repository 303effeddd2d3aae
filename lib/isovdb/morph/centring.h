// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file centring.h
/// @brief Centring a pair of slices on their convex-hull centroids before the
///        morph, and resampling a field at an offset (paper 002 §3.3.2, §3.3.9).
#pragma once

#include <optional>

#include "isovdb/morph/plane.h"

namespace isovdb::morph {

/// @brief Centroid of the convex hull of all inside pixels (the pixels as unit
///        squares, so one pixel's centroid is its centre), as MATLAB's
///        bwconvhull + regionprops in the paper; several regions share one hull.
/// @return std::nullopt for an empty mask.
std::optional<Vec2> hullCentroid(const Mask2& mask);

/// out(x, y) = field.sample(x + offset.x, y + offset.y) on a width × height grid
/// (bilinear; beyond the field's border, see Field2::sample).
Field2 resample(const Field2& field, int width, int height, Vec2 offset);

}  // namespace isovdb::morph
