// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file data_boundary.h
/// @brief What a mesh does where its surface reaches the boundary of the sampled data
///        (the survey boundary of a seismic cube, the faces of a dense volume).
///
/// Outside the sampled box counts as outside the object (the quiet side of an
/// amplitude, the background of a mask), so every contouring method closes a
/// surface that leaves the data with a cap just beyond the last samples. The
/// box is the sampled box's sample positions, [min, max] in index space: the
/// outermost traces and samples, not half a voxel beyond.
/// - Cap: the mesh stays closed and its caps lie on the box faces. The octree modes
///   make them flat on the faces while contouring (cell::ContourSettings::dataBox and
///   capBox: every vertex within 2 * 10^-3 voxel beyond them, contour/box_caps.h), so
///   nothing moves afterwards and Ju–Udeshi's guarantee holds on the caps too. The vdb
///   method's caps lie up to a voxel beyond and are flattened here: vertices beyond the
///   box are moved onto it (clamped per axis), which can fold their triangles.
/// - Open: the same, then the cap triangles (all three vertices on or beyond one
///   box face) are dropped and unused vertices removed. The mesh's boundary edges
///   lie on the box faces (octree modes: within 2 * 10^-3 voxel), and only there.
///   Two sheets whose caps shared a vertex would touch there: each gets its own copy
///   (mesh/pinched_vertices.h), so the open mesh is manifold.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "isovdb/mesh/mesh.h"
#include "isovdb/named_values.h"
#include "isovdb/mesh/mesh_sink.h"
#include "isovdb/volume/sampled_box.h"

namespace isovdb::pipeline {

enum class BoundaryMode {
  Cap,   ///< closed mesh, caps flattened onto the data boundary
  Open,  ///< caps dropped: the mesh ends on the data boundary
};

inline constexpr NameTable<BoundaryMode, 2> kBoundaryModeNames{
    {{BoundaryMode::Cap, "cap"}, {BoundaryMode::Open, "open"}}};
constexpr std::string_view boundaryModeName(BoundaryMode mode) { return nameOf(kBoundaryModeNames, mode); }
/// The mode named `name`; std::nullopt for another name.
constexpr std::optional<BoundaryMode> parseBoundaryMode(std::string_view name) {
  return valueNamed(kBoundaryModeNames, name);
}

/// Applies `mode` to a mesh in index space (before indexToWorld): `flatten` moves the
/// vertices beyond the box onto it first (false when the contouring made the caps).
/// Normals of moved vertices are kept. Returns the number of triangles dropped (0 for
/// Cap). O(triangles + vertices).
std::int64_t applyDataBoundary(mesh::Mesh& mesh, const volume::IndexBox& box, BoundaryMode mode, bool flatten = true);

/// Cap mode piece by piece: clamps the positions of every batch into the box
/// (when there is one) and forwards everything to `target`, so a streamed mesh
/// gets the same caps as applyDataBoundary(..., Cap) would give it.
class CappingSink final : public mesh::MeshSink {
 public:
  CappingSink(mesh::MeshSink& target, std::optional<volume::IndexBox> box) : target_(target), box_(box) {}
  void addVertices(std::span<const mesh::Vec3f> positions) override;
  void addTriangles(std::span<const mesh::Triangle> triangles) override { target_.addTriangles(triangles); }
  std::uint64_t vertexCount() const override { return target_.vertexCount(); }
  std::uint64_t triangleCount() const override { return target_.triangleCount(); }

 private:
  mesh::MeshSink& target_;
  std::optional<volume::IndexBox> box_;
};

}  // namespace isovdb::pipeline
