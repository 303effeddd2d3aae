// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file vdb_file.h
/// @brief Reading and writing OpenVDB `.vdb` files (any file version OpenVDB 10 reads,
///        including old half-float files).
///
/// On read, the grid is moved to voxel index space: its transform becomes the
/// identity and the axis-aligned scale/translation goes to Volume::geometry();
/// level-set values are divided by the voxel size so distances are in voxels.
/// On write, the reverse happens, so VFX tools see world units.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "isovdb/volume/sampled_box.h"
#include "isovdb/volume/volume.h"

namespace isovdb::store {

/// One grid of a .vdb file, as listed by `isovdb info`.
struct VdbGridInfo {
  std::string name;
  std::string valueType;  ///< "float", "bool", "vec3s", ...
  std::string gridClass;  ///< "level set", "fog volume", "unknown", ...
};

/// Lists the grids of a .vdb file (reads only the headers).
/// @throw IoError when the file is missing; InputError when it is not a .vdb file.
std::vector<VdbGridInfo> listVdbGrids(const std::filesystem::path& path);

/// Reads one grid. `gridName` empty: the first float, double or bool grid.
/// Level sets become DistanceField volumes, other float/double grids Scalar,
/// bool and mask grids Mask.
/// @throw InputError naming the file when the grid is missing, of an unsupported
///        type, or has a transform that is not an axis-aligned scale + translation.
volume::Volume readVdb(const std::filesystem::path& path, const std::string& gridName = {});

/// The same grid, only the voxels whose index z lies in [zWindow[0], zWindow[1]) (one
/// slab of a distributed run): the leaves' buffers outside are not read (OpenVDB's
/// clipped read), the rest is clipped exactly in index space. `fileBox` (optional)
/// receives the whole grid's active box as the file records it (OpenVDB's
/// file_bbox_min/max), or stays empty when it records none.
volume::Volume readVdb(const std::filesystem::path& path, const std::string& gridName,
                       const std::array<std::int64_t, 2>& zWindow, std::optional<volume::IndexBox>* fileBox);

struct VdbWriteOptions {
  std::string gridName;  ///< empty: "sdf", "mask" or "field" by kind
};

/// Writes the volume as one grid with its world transform (level sets as
/// GRID_LEVEL_SET in world units when the spacing is uniform; with anisotropic
/// spacing, distances stay in voxels and the metadata "isovdb_distance_units"
/// says so). Written through a temporary file: nothing partial is left on failure.
/// @throw IoError when the path is not writable.
void writeVdb(const std::filesystem::path& path, const volume::Volume& volume, const VdbWriteOptions& options = {});

}  // namespace isovdb::store
