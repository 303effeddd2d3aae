// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file ply_stream_writer.h
/// @brief Writes a binary PLY mesh piece by piece, as the meta-cell pipeline
///        produces it, without holding the mesh in memory.
///
/// Vertices go to the output's temporary file as they arrive, after a header
/// of reserved size; triangles go to a second temporary file beside it. On
/// commit() the triangles are appended, the header is rewritten with the final
/// counts (padded with a comment line to the reserved size) and the file is
/// renamed into place (AtomicFile): a failed or interrupted run leaves no
/// output, and the result is byte-for-byte what io::writePly writes for the
/// same mesh, apart from the header's padding comment. Memory: one batch.
#pragma once

#include <array>
#include <filesystem>

#include "isovdb/io/atomic_file.h"
#include "isovdb/mesh/mesh_sink.h"

namespace isovdb::io {

class PlyStreamWriter final : public mesh::MeshSink {
 public:
  /// Opens the temporaries. Positions are written as scale * p + offset (the
  /// index-to-world transform; identity by default).
  /// @throw IoError naming `path` when it cannot be written.
  explicit PlyStreamWriter(const std::filesystem::path& path, std::array<double, 3> scale = {1, 1, 1},
                           std::array<double, 3> offset = {0, 0, 0});

  void addVertices(std::span<const mesh::Vec3f> positions) override;
  /// @throw InputError if a triangle refers to a vertex not added yet (nothing is written).
  void addTriangles(std::span<const mesh::Triangle> triangles) override;
  std::uint64_t vertexCount() const override { return vertices_; }
  std::uint64_t triangleCount() const override { return triangles_; }

  /// Appends the triangles, writes the final header and renames the file into place.
  /// @throw IoError on a failed write; InputError beyond 2^32 - 1 vertices.
  void commit();

 private:
  std::filesystem::path path_;
  std::array<double, 3> scale_, offset_;
  AtomicFile file_;
  AtomicFile faces_;
  std::uint64_t vertices_ = 0;
  std::uint64_t triangles_ = 0;
  std::size_t headerSize_ = 0;
};

}  // namespace isovdb::io
