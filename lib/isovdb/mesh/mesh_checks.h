// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file mesh_checks.h
/// @brief Internal input checks shared by the mesh analyses (validate.cc,
///        self_intersection.cc). Not part of the public API.
#pragma once

#include <atomic>
#include <cstddef>
#include <string_view>

#include "isovdb/mesh/mesh.h"

namespace isovdb::mesh::detail {

/// True when a corner of `tri` is not a vertex of `mesh` or a corner's position
/// has a non-finite coordinate.
bool invalidTriangle(const Mesh& mesh, const Triangle& tri);

/// Checks that `mesh` has no normals or one per vertex and that every triangle
/// references one of its vertices: what the writers and the welder need before they
/// touch the arrays.
/// @param caller prefixes the message (`weldVertices`, `cannot write 'out.ply'`).
/// @throw InputError naming both counts, or the first bad triangle and its vertex.
void checkIndices(const Mesh& mesh, std::string_view caller);

/// Lowers `lowest` to `t` when `t` is smaller; safe to call from many threads.
void keepLowest(std::atomic<std::size_t>& lowest, std::size_t t);

/// Throws the InputError that names why triangle `t` is invalid, prefixed by `caller`.
/// @pre invalidTriangle(mesh, mesh.triangles[t])
/// @throw InputError always: an out-of-range vertex index, else a non-finite coordinate.
[[noreturn]] void throwInvalidTriangle(const Mesh& mesh, std::size_t t, std::string_view caller);

}  // namespace isovdb::mesh::detail
