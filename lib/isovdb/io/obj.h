// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file obj.h
/// @brief Writes triangle meshes as Wavefront OBJ text.
///
/// Positions are written as they are stored in the mesh: pipeline/ applies
/// the index-to-world transform before calling writeObj().
#pragma once

#include <filesystem>

#include "isovdb/mesh/mesh.h"

namespace isovdb::io {

/// @brief Writes `mesh` as an OBJ file: `v x y z` lines, `vn nx ny nz` lines
///        when the mesh has normals, then `f a b c` (or `f a//a b//b c//c`
///        with normals) with 1-based indices.
///
/// Numbers are the shortest decimal text that reads back to the same float
/// (std::to_chars), so a reader recovers every position bit for bit. Lines
/// are formatted in parallel blocks (TBB) and written in order, so the
/// output does not depend on the thread count. The file is written through
/// a temporary beside `path` and renamed at the end (AtomicFile): a failure
/// leaves no file. Memory: a few MB of text buffers beyond the mesh.
///
/// @param[in] path  output file; its directory must exist
/// @param[in] mesh  normals empty or one per position; indices below the vertex count
/// @throw InputError when the normals' count does not match the positions' or a
///        triangle references a missing vertex (nothing is written)
/// @throw IoError when the file cannot be created or written
void writeObj(const std::filesystem::path& path, const mesh::Mesh& mesh);

}  // namespace isovdb::io
