// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file png_check.h
/// @brief A PNG file's chunks and compressed image data checked against its header
///        before a decoder (stb_image) allocates for them.
///
/// stb_image grows its output as the image data inflates, doubling the buffer: the
/// fuzzer's damaged 8 x 8 PNG made it ask for 2 GB. Walking the chunks (each within the
/// file) and inflating the IDAT data once with zlib, counting bytes into a small
/// scratch buffer, bounds what the data can produce by what the header declares.
#pragma once

#include <string>
#include <string_view>

namespace isovdb::io {

/// @brief Checks PNG `bytes` (from `source`, named in messages) before decoding: every
///        chunk lies within the file, and the image data does not inflate beyond the
///        filtered rows the header's size, depth, colour type and interlacing declare.
///        Other files (BMP) and data zlib cannot inflate are left to the decoder.
/// @throw InputError naming the file and the chunk or the sizes.
void checkPngData(std::string_view bytes, const std::string& source);

}  // namespace isovdb::io
