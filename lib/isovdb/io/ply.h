// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file ply.h
/// @brief Reads and writes triangle meshes as PLY (Stanford polygon files).
///
/// Positions are written as they are stored in the mesh: pipeline/ applies
/// the index-to-world transform before calling writePly().
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "isovdb/mesh/mesh.h"

namespace isovdb::io {

/// @brief Writes `mesh` as binary little-endian PLY 1.0.
///
/// Layout: `element vertex` with `float x y z` (and `float nx ny nz` when the
/// mesh has normals), then `element face` with
/// `property list uchar uint vertex_indices`. The file is written through a
/// temporary beside `path` and renamed at the end (AtomicFile), so a failure
/// leaves no file and never a partial one. Memory: O(1) beyond the mesh.
///
/// @param[in] path  output file; its directory must exist
/// @param[in] mesh  normals empty or one per position; indices below the vertex count
/// @throw InputError when the normals' count does not match the positions' or a
///        triangle references a missing vertex (nothing is written)
/// @throw IoError when the file cannot be created or written
void writePly(const std::filesystem::path& path, const mesh::Mesh& mesh);

/// @brief Reads a PLY file into a triangle mesh.
///
/// Accepts `ascii`, `binary_little_endian` and `binary_big_endian` format 1.0.
/// The `vertex` element must have `x`, `y` and `z` properties; `nx`, `ny`,
/// `nz` are read when all three are present; every property may have any
/// numeric type (doubles are rounded to float) and other properties are
/// skipped. The `face` element (optional) must have a list property named
/// `vertex_indices` (or `vertex_index`) with integer count and index types;
/// polygons with more than three corners are fan-triangulated from their
/// first corner. Other elements are skipped.
///
/// @param[in] path  input file
/// @return the mesh; `normals` is empty when the file has none
/// @throw IoError when the file cannot be opened or read
/// @throw InputError naming the file and the problem: a bad or unsupported
///        header, a missing x/y/z or face list property, truncated or
///        malformed data, a face with fewer than three corners, an index out
///        of range, a non-finite coordinate
mesh::Mesh readPly(const std::filesystem::path& path);

namespace detail {

/// @brief The header writePly and PlyStreamWriter write: binary little-endian,
///        float x y z (+ nx ny nz), uchar/uint face lists, and a comment line of
///        spaces that keeps room for the largest counts: its size does not depend
///        on the counts, so the streamed writer rewrites them in place, and a mesh
///        written whole or streamed is the same bytes.
std::string binaryPlyHeader(std::uint64_t vertices, std::uint64_t triangles, bool normals,
                            const std::vector<std::string>& comments = {});

}  // namespace detail

}  // namespace isovdb::io
