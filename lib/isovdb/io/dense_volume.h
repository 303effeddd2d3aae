// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file dense_volume.h
/// @brief Opens any dense volume file (NRRD, MetaImage or headerless raw) as a SliceStream.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>

#include "isovdb/io/raw_reader.h"
#include "isovdb/io/slice_stream.h"

namespace isovdb::io {

/// True when the extension names a dense volume format this library reads:
/// .nrrd, .nhdr, .mhd, .mha, .nii, .nii.gz or .raw (case-insensitive). Other files may still be
/// read as raw through openDenseVolume() with RawOptions.
bool isDenseVolumePath(const std::filesystem::path& path);

/// Opens a dense volume, choosing the reader by extension (case-insensitive):
/// .nrrd/.nhdr → openNrrd(), .mhd/.mha → openMetaImage(), .nii/.nii.gz → openNifti(),
/// anything else → openRaw(),
/// which needs `raw`. `raw` is ignored for NRRD and MetaImage files.
/// Memory: one slice plus 1-2 MiB of buffers, whatever the format.
/// @throw IoError "'path': no such file" when `path` does not exist (or the OS reason
///        when it cannot be read); InputError "'x.raw': raw volumes need --dims and
///        --type" for a raw file without `raw`, and the readers' InputErrors.
std::unique_ptr<SliceStream> openDenseVolume(const std::filesystem::path& path,
                                             const std::optional<RawOptions>& raw = std::nullopt);

}  // namespace isovdb::io
