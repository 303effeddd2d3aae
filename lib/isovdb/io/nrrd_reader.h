// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file nrrd_reader.h
/// @brief NRRD volumes (NRRD0001..NRRD0005), attached (.nrrd) or detached (.nhdr).
#pragma once

#include <filesystem>
#include <memory>

#include "isovdb/io/slice_stream.h"

namespace isovdb::io {

/// Opens a 3-D NRRD volume for streaming, one z-slice at a time.
///
/// Fields read: `type`, `dimension` (must be 3), `sizes`, `endian` (required for
/// multi-byte types), `encoding` (raw, gzip or gz, bzip2 or bz2), `spacings` or `space directions`
/// (axis-aligned with positive steps only), `space origin`, `byte skip` (>= 0, or
/// -1 with raw encoding: data at the end of the file), `line skip` and `data file`
/// (one file, relative to the header's folder). Without `data file` the data follows
/// the header's blank line. Comments (`#`), `key:=value` pairs and other fields
/// (kinds, labels, units, ...) are skipped. Raw data must hold exactly the bytes the
/// sizes need; compressed data must decompress to the byte skip plus exactly that many
/// bytes (checked at the end). Memory: one slice plus 1-2 MiB of buffers (libbz2: up to
/// 3.5 MiB more); compressed data is decompressed as it is read.
///
/// @throw IoError when the header or the data file is missing or unreadable
///        ("'path': no such file"); InputError naming the file and the field when a
///        field is missing, malformed, unsupported or contradicts another, or when
///        the data size does not match `sizes`.
std::unique_ptr<SliceStream> openNrrd(const std::filesystem::path& path);

}  // namespace isovdb::io
