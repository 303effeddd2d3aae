// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file slice_sdf.h
/// @brief Signed distance of one slice, with OpenVDB's fast sweeping (paper 002 §3.3.3).
#pragma once

#include "isovdb/morph/plane.h"

namespace isovdb::morph {

/// @brief Signed distance to the boundary of `mask`, in pixels, NEGATIVE inside,
///        over the whole slice (not a narrow band): the morph speed needs it everywhere.
///
/// The mask becomes a fog volume one voxel thick (1 inside, 0 outside), and
/// openvdb::tools::fogToSdf solves |∇φ| = 1 from its 0.5 iso-contour (the boundary
/// lies half-way between an inside and an outside pixel centre); two passes, with
/// the background above and below taken as outside and then as inside, keep the
/// distances in-plane. Only the object's bounding box plus 16 pixels is swept;
/// beyond it the distance continues the box's border value (an upper bound). Holes are
/// respected because the sign comes from the mask itself. An empty slice gets
/// +(width + height) everywhere, a full one -(width + height).
Field2 signedDistance(const Mask2& mask);

}  // namespace isovdb::morph
