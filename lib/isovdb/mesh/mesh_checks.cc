// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/mesh/mesh_checks.h"

#include <cmath>
#include <string>

#include "isovdb/errors.h"

namespace isovdb::mesh::detail {

bool invalidTriangle(const Mesh& mesh, const Triangle& tri) {
  const std::size_t vertexCount = mesh.positions.size();
  for (const std::uint32_t v : tri) {
    if (v >= vertexCount) return true;
    const Vec3f& p = mesh.positions[v];
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) return true;
  }
  return false;
}

void checkIndices(const Mesh& mesh, std::string_view caller) {
  const std::size_t n = mesh.positions.size();
  if (!mesh.normals.empty() && mesh.normals.size() != n)
    throw InputError(std::string(caller) + ": the mesh has " + std::to_string(mesh.normals.size()) + " normals for " +
                     std::to_string(n) + " vertices (expected none or one per vertex)");
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (const std::uint32_t v : mesh.triangles[t])
      if (v >= n)
        throw InputError(std::string(caller) + ": triangle " + std::to_string(t) + " references vertex " +
                         std::to_string(v) + " but the mesh has " + std::to_string(n) + " vertices");
}

void keepLowest(std::atomic<std::size_t>& lowest, std::size_t t) {
  std::size_t seen = lowest.load();
  while (t < seen && !lowest.compare_exchange_weak(seen, t)) {
  }
}

void throwInvalidTriangle(const Mesh& mesh, std::size_t t, std::string_view caller) {
  const std::size_t vertexCount = mesh.positions.size();
  for (const std::uint32_t v : mesh.triangles[t]) {
    if (v >= vertexCount)
      throw InputError(std::string(caller) + ": triangle " + std::to_string(t) + " references vertex " +
                       std::to_string(v) + " but the mesh has " + std::to_string(vertexCount) + " vertices");
  }
  throw InputError(std::string(caller) + ": a vertex of triangle " + std::to_string(t) +
                   " has a non-finite coordinate");
}

}  // namespace isovdb::mesh::detail
