// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file mesh_file.h
/// @brief Mesh files chosen by extension: .ply (binary little-endian) or .obj.
#pragma once

#include <filesystem>

#include "isovdb/mesh/mesh.h"

namespace isovdb::io {

/// True for the extensions writeMesh accepts (.ply, .obj; any case).
bool isMeshPath(const std::filesystem::path& path);

/// Writes PLY or OBJ by extension, through a temporary file.
/// @throw InputError for another extension; IoError when not writable.
void writeMesh(const std::filesystem::path& path, const mesh::Mesh& mesh);

/// Reads a PLY file. @throw IoError / InputError (names the file).
mesh::Mesh readMesh(const std::filesystem::path& path);

}  // namespace isovdb::io
