// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file pinched_vertices.h
/// @brief Splits the vertices where a mesh's surface pinches to a point.
///
/// A vertex is pinched when its triangles form several fans, no two of which share an
/// edge through it: two sheets touch there, and the mesh is not manifold. Closed meshes
/// from the octree modes have none; they appear where triangles are removed, as when
/// `--boundary open` drops the caps and two sheets met the data's box at one cap vertex
/// (two voxels of the last slice that share only an edge). Giving each fan its own copy
/// of the vertex makes the mesh manifold with a boundary there. Copies at the same point
/// would still make the fans' triangles touch (a self-intersection for mesh_checks.h),
/// so each copy steps 10^-3 (mesh units: voxels in index space) towards its own fan.
#pragma once

#include <cstddef>

#include "isovdb/mesh/mesh.h"

namespace isovdb::mesh {

/// @brief Gives every fan of triangles around a pinched vertex but the first its own copy
/// of the vertex (normal kept), appended after the existing vertices; the vertex and its
/// copies each move 10^-3 towards the mean of their fan's other corners.
///
/// Fans are taken in the order of their first triangle, and copies are numbered in the
/// order of the vertices they split, so the result depends on the input alone. Triangles
/// keep their order. O(T) time and memory.
///
/// @return the number of vertices added
/// @pre every triangle index is below `mesh.positions.size()`; `mesh.normals` is empty or
///      has one entry per position.
std::size_t splitPinchedVertices(Mesh& mesh);

}  // namespace isovdb::mesh
