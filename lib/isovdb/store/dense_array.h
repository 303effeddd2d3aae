// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file dense_array.h
/// @brief Copies a box of a sparse volume into a caller's dense array (numpy arrays at
///        the Python boundary; the dense writer's default box).
#pragma once

#include "isovdb/volume/sampled_box.h"
#include "isovdb/volume/volume.h"

namespace isovdb::store {

/// The box a dense export covers by default: the volume's sampled box (its file's
/// dims, volume/sampled_box.h), or its active bounding box when it has none
/// (empty, max < min, for an empty volume).
volume::IndexBox defaultDenseBox(const volume::Volume& volume);

/// Copies the values in `box` (index space, inclusive) into `out`, C order
/// [x][y][z] (z fastest), as OpenVDB's tools::copyToDense does: inactive voxels
/// read as the grid's background. Parallel (TBB).
/// @param[out] out  (max-min+1) per axis, multiplied, floats
/// @pre `volume.kind()` is Scalar or DistanceField; box not empty
/// @throw InputError for a mask volume.
void copyToDense(const volume::Volume& volume, const volume::IndexBox& box, float* out);

/// The same for a mask: true inside.
/// @throw InputError for a Scalar or DistanceField volume.
void copyToDense(const volume::Volume& volume, const volume::IndexBox& box, bool* out);

}  // namespace isovdb::store
