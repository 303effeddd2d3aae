// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file whole_file.h
/// @brief Reads a whole file into memory: the mesh readers (PLY, STL, OBJ, GLB)
///        parse from one contiguous buffer.
#pragma once

#include <filesystem>
#include <string>

namespace isovdb::io {

/// The bytes of `path`: one read of the size the file system reports, then more if
/// the file grew meanwhile. @throw IoError naming the file when it cannot be opened or read
std::string readWholeFile(const std::filesystem::path& path);

}  // namespace isovdb::io
