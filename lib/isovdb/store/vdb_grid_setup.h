// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file vdb_grid_setup.h
/// @brief What every grid isovdb writes to a .vdb file carries: its world
///        transform, name, class and provenance metadata, and level-set values
///        in world units. Shared by writeVdb (a grid in memory) and
///        LeafwiseLevelSetWriter (a band streamed leaf by leaf).
///        Heavy (includes openvdb.h): include it only from .cc files.
#pragma once

#include <openvdb/openvdb.h>

#include <string>

#include "isovdb/volume/volume.h"

namespace isovdb::store {

/// openvdb::initialize(), once per process (thread-safe).
void initializeOpenVdb();

/// Factor from distances in voxels to the distances a level set is written with:
/// the voxel size when it is uniform (VFX tools expect world units), else 1
/// (distances stay in voxels and the grid says so, see describeGrid).
float levelSetWorldScale(const volume::Geometry& geometry);

/// Sets the grid's world transform, name, class (level set or not) and metadata
/// (`isovdb_source`; `isovdb_distance_units` = "voxels" for a level set with an
/// anisotropic voxel size).
void describeGrid(openvdb::GridBase& grid, const volume::Geometry& geometry, const std::string& name, bool levelSet,
                  const std::string& source);

}  // namespace isovdb::store
