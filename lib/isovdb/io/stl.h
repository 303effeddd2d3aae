// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file stl.h
/// @brief Triangle meshes as STL files (binary written; binary and ASCII read).
///
/// STL stores each triangle with its own three corners and a facet normal, so
/// it carries no connectivity and no vertex normals: reading welds corners whose
/// positions are bit-identical (mesh/weld.h), which restores the indexed mesh
/// that was written, vertex order aside.
#pragma once

#include <filesystem>

#include "isovdb/mesh/mesh.h"

namespace isovdb::io {

/// @brief Writes `mesh` as a binary STL file: an 80-byte header naming isovdb,
///        the triangle count, then per triangle its unit facet normal (from the
///        winding; zero for a degenerate triangle), its three corners and a zero
///        attribute word, all little-endian float32.
///
/// Vertex normals are not written (the format has none). The file is written
/// through a temporary beside `path` (AtomicFile): a failure leaves no file.
/// @throw InputError when a triangle references a missing vertex, or the mesh has
///        more than 2^32 - 1 triangles (nothing is written)
/// @throw IoError when the file cannot be created or written
void writeStl(const std::filesystem::path& path, const mesh::Mesh& mesh);

/// @brief Reads a binary or ASCII STL file into an indexed triangle mesh.
///
/// A file is binary when its size is 84 + 50 × the count at bytes 80–83 (ASCII
/// files begin with "solid", but so do some binary ones); otherwise it must be
/// ASCII (`solid` … `facet normal` … `outer loop`, three `vertex x y z`,
/// `endloop`, `endfacet` … `endsolid`). Corners are welded by exact position in
/// order of first appearance; facet normals are ignored (the winding orients
/// each triangle).
/// @throw IoError when the file cannot be opened or read
/// @throw InputError naming the file and the problem: a size that fits neither
///        form, a truncated or malformed facet, a non-finite coordinate
mesh::Mesh readStl(const std::filesystem::path& path);

}  // namespace isovdb::io
