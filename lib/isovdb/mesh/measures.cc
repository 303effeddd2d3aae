// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/mesh/measures.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <vector>

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

std::vector<Vec3f> areaWeightedNormals(const Mesh& mesh) {
  std::vector<Eigen::Vector3d> sums(mesh.positions.size(), Eigen::Vector3d::Zero());
  for (const Triangle& tri : mesh.triangles) {
    const Eigen::Vector3d a = corner(mesh, tri, 0);
    const Eigen::Vector3d n = (corner(mesh, tri, 1) - a).cross(corner(mesh, tri, 2) - a);  // twice the area
    for (const std::uint32_t v : tri) sums[v] += n;
  }
  std::vector<Vec3f> normals(sums.size(), Vec3f{0.0f, 0.0f, 0.0f});
  for (std::size_t v = 0; v < sums.size(); ++v) {
    const double length = sums[v].norm();
    if (length > 0 && std::isfinite(length))
      for (int a = 0; a < 3; ++a) normals[v][static_cast<std::size_t>(a)] = static_cast<float>(sums[v][a] / length);
  }
  return normals;
}

}  // namespace isovdb::mesh
