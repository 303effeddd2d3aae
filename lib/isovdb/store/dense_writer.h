// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file dense_writer.h
/// @brief Writes a sparse volume back out as a dense float32 volume (NRRD), for
///        interchange with tools that read plain arrays (numpy, ParaView, ...).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>

#include "isovdb/volume/volume.h"

namespace isovdb::store {

/// What writeDenseVolume() wrote.
struct DenseWriteResult {
  std::array<std::int64_t, 3> dims{0, 0, 0};  ///< samples along x, y, z (x fastest in the file)
  std::array<int, 3> indexMin{0, 0, 0};       ///< grid index of the first sample
  std::filesystem::path header;               ///< the NRRD header (the .nrrd itself when attached)
};

/// True for the extensions writeDenseVolume() writes: .raw and .nrrd.
bool isDenseOutputPath(const std::filesystem::path& path);

/// Writes the volume's sampled box (volume/sampled_box.h; the active bounding box
/// when it has none) as little-endian float32 samples, x fastest, then y, then z:
/// the grid's value at every voxel (inactive voxels read as the background; masks
/// as 1 inside and 0 outside). `OUT.nrrd` gets an attached NRRD header; `OUT.raw`
/// holds the bare samples and a detached header `OUT.nhdr` beside it gives dims,
/// type, byte order, spacings and origin. Both read back with openDenseVolume().
/// Memory: one z-slice. Written through temporary files: nothing partial on failure.
/// @throw InputError for an empty volume or another extension; IoError when a
///        file cannot be written.
DenseWriteResult writeDenseVolume(const std::filesystem::path& path, const volume::Volume& volume);

}  // namespace isovdb::store
