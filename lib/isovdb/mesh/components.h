// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file components.h
/// @brief Connected components of a triangle mesh (triangles connected through shared
///        vertices): the validator's per-component figures and Python's Mesh.components().
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "isovdb/mesh/mesh.h"

namespace isovdb::mesh {

/// @brief The component of each vertex, as its smallest vertex index, through the triangles
///        `joins(t)` accepts (every triangle when empty).
///
/// A concurrent union-find in parallel (TBB) whose roots are always the smallest index of
/// their set, so the result does not depend on the schedule. A vertex no accepted triangle
/// uses is its own root.
/// @pre every triangle references a vertex of `mesh`
std::vector<std::uint32_t> vertexComponentRoots(const Mesh& mesh, const std::function<bool(std::size_t)>& joins = {});

/// @brief The connected components as meshes, in the order of each one's first triangle.
///
/// Each keeps its triangles in their order and its vertices (and normals, if any) in
/// theirs, renumbered from 0; vertices no triangle uses are dropped.
/// @pre every triangle references a vertex of `mesh`
std::vector<Mesh> splitComponents(const Mesh& mesh);

}  // namespace isovdb::mesh
