// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file gltf_reader.h
/// @brief Reads the triangles of a glTF 2.0 scene, binary (.glb) or text (.gltf),
///        into one indexed mesh, placed as the scene places them.
///
/// The default scene (`scene`, else the first of `scenes`; a file without scenes: its
/// root nodes; a file without nodes: every mesh as stored) is walked from its root
/// nodes, each node's transform (`matrix`, or `translation` x `rotation` x `scale`)
/// applied to its children and to its mesh's primitives, so a mesh two nodes use
/// appears twice. Positions are transformed in double precision, normals by the
/// inverse transpose (then normalised), and a transform that mirrors (negative
/// determinant) reverses the triangles' winding, as glTF's renderers do, so an
/// outward-facing surface stays outward-facing.
///
/// Buffers: a .glb file's BIN chunk; a .gltf file's `data:` URIs (base64) or files
/// relative to it. Reads float32 POSITION, float32 NORMAL when every primitive has it,
/// and indices of any unsigned type (or none: consecutive corners); other primitive
/// modes (points, lines, strips, fans) are refused.
#pragma once

#include <filesystem>

#include "isovdb/mesh/mesh.h"

namespace isovdb::io {

/// @throw IoError when the file or an external buffer cannot be opened or read
/// @throw InputError naming the file and the problem: not glTF 2.0, a chunk, buffer or
///        accessor outside its data, an unsupported accessor type, an index beyond the
///        vertices, a non-finite coordinate, a node graph that is not a forest, a
///        singular or non-affine transform, or a scene that instances its meshes into
///        more than 16 times the file's vertices
mesh::Mesh readGltf(const std::filesystem::path& path);

}  // namespace isovdb::io
