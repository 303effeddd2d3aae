/// @file grids.h
/// @brief Typed access to a Volume's OpenVDB grid. Heavy (includes openvdb.h):
///        include it only from .cc files.
#pragma once

#include <openvdb/openvdb.h>

#include "isovdb/errors.h"
#include "isovdb/volume/volume.h"

namespace isovdb::volume {

using MaskGrid = openvdb::BoolGrid;
using FieldGrid = openvdb::FloatGrid;

/// The mask grid of a VolumeKind::Mask volume. @throw InputError for another kind.
const MaskGrid& maskGrid(const Volume& volume);
/// The float grid of a Scalar or DistanceField volume. @throw InputError for a mask.
const FieldGrid& fieldGrid(const Volume& volume);
FieldGrid::Ptr fieldGridPtr(const Volume& volume);

}  // namespace isovdb::volume
