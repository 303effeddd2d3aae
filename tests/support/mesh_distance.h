// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file mesh_distance.h
/// @brief Distance from a point to a triangle mesh, for tests that measure how
///        close a mesh follows a known surface or feature line (brute force).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "isovdb/mesh/mesh.h"
#include "isovdb/mesh/triangle_grid.h"

namespace isovdb::test {

using Point3 = std::array<double, 3>;

/// Closest point to `p` on triangle (a, b, c): the engine's own (mesh/triangle_grid.h),
/// checked against a dense search in tests/mesh/triangle_grid_test.cc.
inline Point3 closestOnTriangle(const Point3& p, const Point3& a, const Point3& b, const Point3& c) {
  return mesh::closestPointOnTriangle(p, a, b, c);
}

/// Distance from `p` to the nearest triangle of `m` (max double for an empty mesh).
inline double distanceToMesh(const mesh::Mesh& m, const Point3& p) {
  double best = std::numeric_limits<double>::max();
  for (const auto& t : m.triangles) {
    std::array<Point3, 3> v;
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t a = 0; a < 3; ++a) v[i][a] = m.positions[t[i]][a];
    // Cheap reject on the bounding box.
    bool far = false;
    for (std::size_t a = 0; a < 3 && !far; ++a)
      far = p[a] < std::min({v[0][a], v[1][a], v[2][a]}) - best || p[a] > std::max({v[0][a], v[1][a], v[2][a]}) + best;
    if (far) continue;
    const Point3 q = closestOnTriangle(p, v[0], v[1], v[2]);
    best = std::min(best, std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]));
  }
  return best;
}

}  // namespace isovdb::test
