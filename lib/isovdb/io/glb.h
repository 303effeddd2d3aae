// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file glb.h
/// @brief Triangle meshes as binary glTF 2.0 (.glb), the format web viewers,
///        Blender and game engines open directly.
///
/// A .glb file is a 12-byte header ("glTF", version 2, total length), a JSON
/// chunk describing the scene and a BIN chunk holding the arrays. isovdb writes
/// one mesh with one triangle primitive: float32 POSITION (with the min/max the
/// format requires), float32 NORMAL when the mesh has normals, and uint32
/// indices. Positions are written as stored (isovdb's world units, z up; glTF
/// viewers assume metres and y up, which only changes how a viewer first frames
/// the object).
#pragma once

#include <filesystem>

#include "isovdb/mesh/mesh.h"

namespace isovdb::io {

/// @brief Writes `mesh` as a binary glTF 2.0 file through a temporary beside
///        `path` (AtomicFile): a failure leaves no file.
/// @throw InputError when a triangle references a missing vertex, the normals'
///        count differs from the positions', or the arrays exceed the 4 GiB a GLB
///        chunk can hold (nothing is written)
/// @throw IoError when the file cannot be created or written
void writeGlb(const std::filesystem::path& path, const mesh::Mesh& mesh);

/// Reading: io/gltf_reader.h (.glb and .gltf, node transforms applied).

}  // namespace isovdb::io
