// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file mesh_file.h
/// @brief Mesh files chosen by extension: .ply (binary little-endian), .obj, .stl (binary) or
///        .glb (binary glTF 2.0).
#pragma once

#include <filesystem>

#include "isovdb/mesh/mesh.h"

namespace isovdb::io {

/// Refuses a path whose extension writeMesh does not accept (.ply, .obj, .stl, .glb; any case),
/// before any work. @throw InputError naming the path and the accepted extensions.
void checkMeshPath(const std::filesystem::path& path);

/// Writes PLY, OBJ, binary STL or GLB by extension, through a temporary file.
/// @throw InputError for another extension; IoError when not writable.
void writeMesh(const std::filesystem::path& path, const mesh::Mesh& mesh);

/// Reads a PLY, OBJ, STL (binary or ASCII), GLB or .gltf file by extension (glTF: the
/// default scene, node transforms applied; io/gltf_reader.h). @throw IoError / InputError (names the file).
mesh::Mesh readMesh(const std::filesystem::path& path);

}  // namespace isovdb::io
