// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/mesh/measures.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace isovdb::mesh {
namespace {

Eigen::Vector3d corner(const Mesh& mesh, const Triangle& tri, int k) {
  return Eigen::Map<const Eigen::Vector3f>(mesh.positions[tri[static_cast<std::size_t>(k)]].data()).cast<double>();
}

}  // namespace

double signedVolumeTerm(const Mesh& mesh, const Triangle& tri) {
  return corner(mesh, tri, 0).dot(corner(mesh, tri, 1).cross(corner(mesh, tri, 2))) / 6.0;
}

double triangleArea(const Mesh& mesh, const Triangle& tri) {
  const Eigen::Vector3d a = corner(mesh, tri, 0);
  return 0.5 * (corner(mesh, tri, 1) - a).cross(corner(mesh, tri, 2) - a).norm();
}

MeshMeasures measure(const Mesh& mesh) {
  MeshMeasures result;
  for (const Triangle& tri : mesh.triangles) {
    result.area += triangleArea(mesh, tri);
    result.signedVolume += signedVolumeTerm(mesh, tri);
  }
  return result;
}

}  // namespace isovdb::mesh
