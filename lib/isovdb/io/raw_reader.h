// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file raw_reader.h
/// @brief Headerless raw volumes: the caller gives dims, sample type and byte order.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>

#include "isovdb/io/sample_type.h"
#include "isovdb/io/slice_stream.h"

namespace isovdb::io {

/// What a raw file cannot say about itself (CLI: --dims, --type, --big-endian,
/// --spacing, --header-bytes).
struct RawOptions {
  std::array<std::int64_t, 3> dims{0, 0, 0};     ///< samples along x, y, z (each > 0); x fastest
  SampleType type = SampleType::UInt8;           ///< sample type of the file
  bool bigEndian = false;                        ///< byte order of multi-byte samples
  std::array<double, 3> spacing{1.0, 1.0, 1.0};  ///< world units per voxel (each finite and > 0)
  std::int64_t headerBytes = 0;                  ///< bytes to skip before the first sample (>= 0)
};

/// Opens a raw volume for streaming, one z-slice at a time (origin (0,0,0)).
/// Memory: one slice plus a 1 MiB buffer.
/// @param[in] path the raw file; its size must be exactly
///            headerBytes + dims[0]*dims[1]*dims[2]*sampleSize(type).
/// @throw IoError "'path': no such file" (or the OS reason) when it cannot be opened;
///        InputError naming the file and the field for a non-positive or overflowing
///        dim, a negative headerBytes, a bad spacing, or a file size that does not
///        match (the message gives both sizes).
std::unique_ptr<SliceStream> openRaw(const std::filesystem::path& path, const RawOptions& options);

}  // namespace isovdb::io
