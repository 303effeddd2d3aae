// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file metaimage_reader.h
/// @brief MetaImage volumes (ITK/VTK): .mhd header with a detached data file, or
///        .mha with the data after the header (ElementDataFile = LOCAL).
#pragma once

#include <filesystem>
#include <memory>

#include "isovdb/io/slice_stream.h"

namespace isovdb::io {

/// Opens a 3-D MetaImage volume for streaming, one z-slice at a time.
///
/// Fields read (names case-insensitive): `NDims` (must be 3), `DimSize`,
/// `ElementType` (MET_CHAR, MET_UCHAR, MET_SHORT, MET_USHORT, MET_INT, MET_UINT,
/// MET_FLOAT, MET_DOUBLE), `BinaryDataByteOrderMSB` / `ElementByteOrderMSB`,
/// `ElementSpacing` (or `ElementSize`), `Offset` / `Origin` / `Position`,
/// `HeaderSize` (bytes from the start of the data file; -1 = data at the end of the
/// file), `CompressedData` (True: one zlib stream, e.g. `.zraw`), `CompressedDataSize`
/// (only used with HeaderSize = -1: real files carry stale values, so the stream is
/// read to its own end), `TransformMatrix` / `Rotation` / `Orientation` (identity
/// only) and `ElementDataFile` (LOCAL or one file relative to the header's folder;
/// the last field). Other fields are skipped. Raw data must hold exactly the bytes
/// DimSize needs; compressed data must inflate to exactly that many (checked at the end).
/// Memory: one slice plus 1-2 MiB of buffers.
///
/// @throw IoError when the header or the data file is missing or unreadable;
///        InputError naming the file and the field when a field is missing,
///        malformed, unsupported or contradicts another, or the data size is wrong.
std::unique_ptr<SliceStream> openMetaImage(const std::filesystem::path& path);

}  // namespace isovdb::io
