// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file nifti_reader.h
/// @brief NIfTI-1 volumes (`.nii`, `.nii.gz`): the format of most segmentation masks
///        in medical imaging (ITK, FSL, 3D Slicer, nibabel).
#pragma once

#include <filesystem>
#include <memory>

#include "isovdb/io/slice_stream.h"

namespace isovdb::io {

/// Opens a 3-D NIfTI-1 single-file volume (`.nii`, or `.nii.gz`: the whole file
/// gzip-compressed) for streaming, one z-slice at a time.
///
/// Read: the 348-byte header in either byte order (told by `sizeof_hdr`), `dim` (3-D; a
/// 4th to 7th dimension only of size 1), `datatype` (uint8, int8, int16, uint16, int32,
/// uint32, float32, float64), `vox_offset`, `scl_slope` / `scl_inter` (applied when the
/// slope is neither 0 nor 1 with intercept 0) and the voxel-to-world transform: the
/// sform when `sform_code` > 0, else the qform when `qform_code` > 0 (quaternion,
/// `pixdim` and `qfac`), else `pixdim` alone at the origin. The transform must be
/// axis-aligned (no rotation, no axis swap); an axis whose step is negative along x
/// or y (ITK's LPS images stored in NIfTI's RAS space: x and y flipped) is read
/// reversed so that every step is positive in world space; a negative z step is
/// refused (slices would have to be read backwards).
/// Memory: one slice plus the byte stream's buffers.
///
/// @throw IoError when the file is missing or unreadable; InputError naming the file
///        and the header field when it is not NIfTI-1 (NIfTI-2 and .hdr/.img pairs are
///        named as such), not 3-D, of an unsupported datatype or transform, or when the
///        data is shorter or longer than the dims need.
std::unique_ptr<SliceStream> openNifti(const std::filesystem::path& path);

}  // namespace isovdb::io
