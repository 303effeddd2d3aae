// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file mesh_sink.h
/// @brief Where a contourer puts its mesh piece by piece: collected in memory
///        (MeshCollector) or streamed to a file (io::MeshStreamWriter), so the
///        meta-cell pipeline never has to hold the whole mesh.
///
/// Vertex ids are global: the first vertex ever added is 0, and triangles may
/// refer to any vertex added before them.
#pragma once

#include <cstdint>
#include <span>

#include "isovdb/mesh/mesh.h"

namespace isovdb::mesh {

class MeshSink {
 public:
  virtual ~MeshSink() = default;
  /// Appends vertices; their ids continue after the vertices already added.
  virtual void addVertices(std::span<const Vec3f> positions) = 0;
  /// Appends triangles over vertices already added.
  virtual void addTriangles(std::span<const Triangle> triangles) = 0;
  /// Vertices added so far.
  virtual std::uint64_t vertexCount() const = 0;
  /// Triangles added so far.
  virtual std::uint64_t triangleCount() const = 0;
};

/// A sink that keeps the mesh in memory.
class MeshCollector final : public MeshSink {
 public:
  void addVertices(std::span<const Vec3f> positions) override {
    mesh.positions.insert(mesh.positions.end(), positions.begin(), positions.end());
  }
  void addTriangles(std::span<const Triangle> triangles) override {
    mesh.triangles.insert(mesh.triangles.end(), triangles.begin(), triangles.end());
  }
  std::uint64_t vertexCount() const override { return mesh.positions.size(); }
  std::uint64_t triangleCount() const override { return mesh.triangles.size(); }

  Mesh mesh;
};

}  // namespace isovdb::mesh
