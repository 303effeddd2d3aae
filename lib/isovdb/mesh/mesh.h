// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file mesh.h
/// @brief The indexed triangle mesh that every contouring method produces.
///
/// Positions are in whatever space the producer states: the engine works in
/// voxel index space, and pipeline/ applies the grid's index-to-world
/// transform once, just before writing.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "isovdb/vec3.h"

namespace isovdb::mesh {

using isovdb::Vec3f;
using Triangle = std::array<std::uint32_t, 3>;

/// Indexed triangle mesh: float positions, 32-bit indices, optional per-vertex normals.
struct Mesh {
  std::vector<Vec3f> positions;
  std::vector<Triangle> triangles;
  std::vector<Vec3f> normals;  ///< empty, or one per position
  /// Lines the mesh file's header carries (PLY `comment`, OBJ `#`, glTF asset.extras;
  /// STL has no room): what a reader needs to place the mesh, e.g. a reservoir's MAPAXES.
  std::vector<std::string> comments;

  std::size_t vertexCount() const { return positions.size(); }
  std::size_t triangleCount() const { return triangles.size(); }
  bool empty() const { return triangles.empty(); }
};

}  // namespace isovdb::mesh
