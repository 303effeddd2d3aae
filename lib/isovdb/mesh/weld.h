// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file weld.h
/// @brief Merges vertices whose positions are bit-identical.
///
/// Contouring produces one vertex per polygon corner where meta-cells or
/// stitched seams meet; welding turns that soup back into an indexed mesh
/// whose topology validate.h can check. Positions are compared by their bit
/// patterns, never with a tolerance: two vertices merge exactly when all three
/// floats are identical (so 0.0f and -0.0f stay apart, and no geometry moves).
#pragma once

#include <cstddef>

#include "isovdb/mesh/mesh.h"

namespace isovdb::mesh {

/// @brief Merges vertices with bit-identical positions and remaps the triangles.
///
/// The surviving vertices keep the order of their first occurrence, so the
/// result does not depend on anything but the input. A merged vertex keeps the
/// normal of its first occurrence. Unreferenced vertices are kept (merged like
/// the others), and triangles are neither removed nor reordered: a triangle
/// whose corners merge keeps its repeated index (validateMesh() counts it as
/// degenerate).
///
/// O(V) expected time, one hash table of V 32-bit slots.
///
/// @param[in,out] mesh  positions, normals (empty or one per position) and triangles
/// @return the number of vertices removed
/// @pre `mesh.normals` is empty or has one entry per position, and every
///      triangle index is below `mesh.positions.size()`.
/// @throw InputError when the normals' count does not match the positions' or a
///        triangle references a missing vertex (the mesh is left unchanged).
std::size_t weldVertices(Mesh& mesh);

}  // namespace isovdb::mesh
