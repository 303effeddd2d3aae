// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/pipeline/data_boundary.h"

#include <algorithm>
#include <limits>
#include <vector>

#include "isovdb/mesh/pinched_vertices.h"

namespace isovdb::pipeline {

namespace {

constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();

/// True when the three vertices lie on or beyond one face of the box.
bool onOneFace(const mesh::Mesh& mesh, const mesh::Triangle& tri, const volume::IndexBox& box) {
  const auto all = [&](auto&& onFace) { return onFace(tri[0]) && onFace(tri[1]) && onFace(tri[2]); };
  for (int a = 0; a < 3; ++a) {
    const auto lo = static_cast<float>(box.min[a]), hi = static_cast<float>(box.max[a]);
    if (all([&](std::uint32_t v) { return mesh.positions[v][a] <= lo; })) return true;
    if (all([&](std::uint32_t v) { return mesh.positions[v][a] >= hi; })) return true;
  }
  return false;
}

/// Removes vertices no triangle uses (with their normals) and renumbers the triangles.
void removeUnusedVertices(mesh::Mesh& mesh) {
  std::vector<std::uint32_t> newIndex(mesh.positions.size(), kUnused);
  for (const mesh::Triangle& tri : mesh.triangles)
    for (const std::uint32_t v : tri) newIndex[v] = 0;
  std::uint32_t next = 0;
  for (std::size_t v = 0; v < newIndex.size(); ++v) {
    if (newIndex[v] == kUnused) continue;
    newIndex[v] = next;
    mesh.positions[next] = mesh.positions[v];
    if (!mesh.normals.empty()) mesh.normals[next] = mesh.normals[v];
    ++next;
  }
  mesh.positions.resize(next);
  if (!mesh.normals.empty()) mesh.normals.resize(next);
  for (mesh::Triangle& tri : mesh.triangles)
    for (std::uint32_t& v : tri) v = newIndex[v];
}

}  // namespace

std::int64_t applyDataBoundary(mesh::Mesh& mesh, const volume::IndexBox& box, BoundaryMode mode, bool flatten) {
  if (flatten)
    for (mesh::Vec3f& p : mesh.positions)
      for (int a = 0; a < 3; ++a)
        p[a] = std::clamp(p[a], static_cast<float>(box.min[a]), static_cast<float>(box.max[a]));
  if (mode == BoundaryMode::Cap) return 0;
  const auto before = static_cast<std::int64_t>(mesh.triangles.size());
  std::erase_if(mesh.triangles, [&](const mesh::Triangle& tri) { return onOneFace(mesh, tri, box); });
  removeUnusedVertices(mesh);
  // Two sheets that met the box at one cap vertex touch there once their caps are gone.
  mesh::splitPinchedVertices(mesh);
  return before - static_cast<std::int64_t>(mesh.triangles.size());
}

void CappingSink::addVertices(std::span<const mesh::Vec3f> positions) {
  if (!box_) {
    target_.addVertices(positions);
    return;
  }
  std::vector<mesh::Vec3f> clamped(positions.begin(), positions.end());
  for (mesh::Vec3f& p : clamped)
    for (int a = 0; a < 3; ++a)
      p[a] = std::clamp(p[a], static_cast<float>(box_->min[a]), static_cast<float>(box_->max[a]));
  target_.addVertices(clamped);
}

}  // namespace isovdb::pipeline
