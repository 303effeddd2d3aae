// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file obj.h
/// @brief Triangle meshes as Wavefront OBJ text (written and read).
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

/// @brief Reads the polygons of an OBJ file as triangles (a polygon of n corners
///        becomes a fan of n - 2 triangles from its first corner).
///
/// Reads `v` (the first three numbers; colours after them are ignored), `vn` and
/// `f` lines whose corners are `v`, `v/vt`, `v//vn` or `v/vt/vn`, with 1-based or
/// negative (relative) indices; other lines (`vt`, `g`, `o`, `s`, `usemtl`,
/// `mtllib`, `l`, comments) are skipped. Normals are kept when every corner's
/// normal index equals its vertex index (the layout writeObj() writes);
/// otherwise they are dropped, since the mesh holds one normal per vertex.
/// @throw IoError when the file cannot be opened or read
/// @throw InputError naming the file and line: a malformed or non-finite number,
///        a face with fewer than 3 corners, an index of no vertex
mesh::Mesh readObj(const std::filesystem::path& path);

}  // namespace isovdb::io
