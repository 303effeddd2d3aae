// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file slice_image.h
/// @brief Reading a monochrome slice image (PNG or BMP, 1-bit included) as the
///        object's inside, and writing a slice back as a PNG.
#pragma once

#include <cstdint>
#include <filesystem>

#include "isovdb/morph/plane.h"

namespace isovdb::morph {

/// True for the extensions readSliceImage accepts (.png, .bmp; any case).
bool isSliceImagePath(const std::filesystem::path& path);

/// @brief Reads a slice image and returns the inside of the object it shows.
///
/// Pixels are made grey and split at 50% intensity; the class that holds most of
/// the image border is the background (white-on-black and black-on-white both
/// work), the other class the drawing. The drawing may be filled regions or thin
/// closed 8-connected contours (contour_fill.h: a contour inside a contour is a hole).
/// Row 0 of the image is y = 0.
/// @throw IoError when the file cannot be read; InputError naming the file when it
///        is not a PNG/BMP image stb_image can decode (truncated, corrupt) or its
///        header declares more than `maxPixels` pixels (checked before decoding).
Mask2 readSliceImage(const std::filesystem::path& path, std::int64_t maxPixels = std::int64_t{1} << 28);

/// Writes `mask` as an 8-bit grey PNG (inside white), through a temporary file.
/// @throw IoError when the path is not writable.
void writeSliceImage(const std::filesystem::path& path, const Mask2& mask);

}  // namespace isovdb::morph
