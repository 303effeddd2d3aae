// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file contour_fill.h
/// @brief Foreground pixels of a slice image → the object's inside, accepting both
///        filled regions and thin closed contours (paper 002 §3.3.3, MATLAB imfill
///        'holes' with its contour-inside-contour rule).
#pragma once

#include "isovdb/morph/plane.h"

namespace isovdb::morph {

/// @brief Fills a slice drawn as regions and/or thin closed contours.
///
/// Foreground pixels form 8-connected components; background pixels 4-connected
/// ones (so an 8-connected contour is closed for them). A component with no pixel
/// whose four neighbours are all foreground is a *thin contour*: crossing it
/// toggles inside/outside, so the region enclosed by a contour is filled and a
/// contour inside it bounds a hole (nesting parity). Any other component is a
/// *filled region*: its pixels are inside and the background it encloses stays
/// as outside as the background around it (a hole). Contour pixels are inside.
///
/// @param[in] foreground  the drawn pixels (1), any size
/// @return the inside, same size
Mask2 fillContours(const Mask2& foreground);

}  // namespace isovdb::morph
