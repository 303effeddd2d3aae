// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "mesh/test_meshes.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

namespace isovdb::test {

using mesh::Mesh;
using mesh::Triangle;
using mesh::Vec3f;

Mesh octahedron(Vec3f centre, float radius) {
  Mesh mesh;
  const Vec3f dirs[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const Vec3f& d : dirs)
    mesh.positions.push_back({centre[0] + radius * d[0], centre[1] + radius * d[1], centre[2] + radius * d[2]});
  mesh.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return mesh;
}

Mesh sphere(int levels) {
  Mesh mesh = octahedron();
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      auto [it, inserted] = midpoints.emplace(key, static_cast<std::uint32_t>(mesh.positions.size()));
      if (inserted) {
        Vec3f m;
        for (int k = 0; k < 3; ++k) m[k] = (mesh.positions[a][k] + mesh.positions[b][k]) / 2;
        const float len = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
        mesh.positions.push_back({m[0] / len, m[1] / len, m[2] / len});
      }
      return it->second;
    };
    std::vector<Triangle> refined;
    for (const Triangle& t : mesh.triangles) {
      const std::uint32_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      refined.push_back({t[0], ab, ca});
      refined.push_back({ab, t[1], bc});
      refined.push_back({ca, bc, t[2]});
      refined.push_back({ab, bc, ca});
    }
    mesh.triangles = std::move(refined);
  }
  return mesh;
}

Mesh torus(std::uint32_t n, std::uint32_t m, float major, float minor, Vec3f offset) {
  Mesh mesh;
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = 0; j < m; ++j) {
      const double u = 2 * std::numbers::pi * i / n, v = 2 * std::numbers::pi * j / m;
      const double r = major + minor * std::cos(v);
      mesh.positions.push_back({offset[0] + float(r * std::cos(u)), offset[1] + float(r * std::sin(u)),
                                offset[2] + float(minor * std::sin(v))});
    }
  auto id = [&](std::uint32_t i, std::uint32_t j) { return (i % n) * m + (j % m); };
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = 0; j < m; ++j) {
      mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return mesh;
}

}  // namespace isovdb::test
