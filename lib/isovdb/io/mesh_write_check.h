// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file mesh_write_check.h
/// @brief Internal checks of a mesh before the mesh writers (obj.cc, ply.cc)
///        open their file. Not part of the public API.
#pragma once

#include <filesystem>

#include "isovdb/mesh/mesh.h"

namespace isovdb::io::detail {

/// Checks that `mesh` has no normals or one per position.
/// @throw InputError naming `path` and both counts otherwise.
void checkNormalCount(const std::filesystem::path& path, const mesh::Mesh& mesh);

/// Checks that every triangle of `mesh` references existing vertices.
/// @throw InputError naming `path`, the first bad triangle and its vertex otherwise.
void checkTriangleIndices(const std::filesystem::path& path, const mesh::Mesh& mesh);

}  // namespace isovdb::io::detail
