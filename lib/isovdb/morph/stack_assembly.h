// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file stack_assembly.h
/// @brief The completed stack of 2-D signed distances → one 3-D narrow-band signed
///        distance field (an isovdb DistanceField volume) that the engine contours.
#pragma once

#include <string>
#include <vector>

#include "isovdb/morph/plane.h"
#include "isovdb/volume/volume.h"

namespace isovdb::morph {

/// @brief Stacks `planes` (plane k at voxel z = k) and closes the stack with an
///        empty plane below and above, then turns the planes' in-plane distances
///        into a 3-D signed distance with openvdb::tools::sdfToSdf (fast sweeping
///        from the zero crossings). Every voxel keeps its plane's sign, so each
///        original slice is reproduced exactly at its plane; the ends close half a
///        voxel beyond the first and last slice (where the clamped in-plane values
///        cross zero).
/// @param[in] planes     canvas-sized signed distances in pixels, NEGATIVE inside
/// @param[in] halfWidth  narrow-band half-width of the result, voxels
/// @param[in] geometry   index → world (pixel size, z step, origin of plane 0)
/// @return a DistanceField volume in voxel index space; no voxel inside if every plane is empty
volume::Volume assembleStack(const std::vector<Field2>& planes, float halfWidth, const volume::Geometry& geometry,
                             const std::string& name);

}  // namespace isovdb::morph
