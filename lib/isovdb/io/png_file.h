// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file png_file.h
/// @brief PNG pictures written whole or not at all (stb_image_write, io::AtomicFile).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace isovdb::io {

/// @brief Writes `width` x `height` pixels of `channels` (1 grey, 3 RGB) bytes each, rows from the top.
/// @throw InputError if the buffer does not hold that many bytes; IoError if the file cannot be written.
void writePng(const std::filesystem::path& path, int width, int height, int channels,
              const std::vector<std::uint8_t>& pixels);

}  // namespace isovdb::io
