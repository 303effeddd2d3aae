// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/mesh_write_check.h"

#include <string>

#include "isovdb/errors.h"

namespace isovdb::io::detail {

void checkNormalCount(const std::filesystem::path& path, const mesh::Mesh& mesh) {
  if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size())
    throw InputError("cannot write '" + path.string() + "': the mesh has " + std::to_string(mesh.normals.size()) +
                     " normals for " + std::to_string(mesh.positions.size()) + " vertices");
}

void checkTriangleIndices(const std::filesystem::path& path, const mesh::Mesh& mesh) {
  const std::size_t n = mesh.positions.size();
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (const std::uint32_t v : mesh.triangles[t])
      if (v >= n)
        throw InputError("cannot write '" + path.string() + "': triangle " + std::to_string(t) + " references vertex " +
                         std::to_string(v) + " but the mesh has " + std::to_string(n) + " vertices");
}

}  // namespace isovdb::io::detail
