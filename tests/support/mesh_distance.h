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

namespace isovdb::test {

using Point3 = std::array<double, 3>;

/// Closest point to `p` on triangle (a, b, c) (Ericson, Real-Time Collision Detection, 5.1.5).
inline Point3 closestOnTriangle(const Point3& p, const Point3& a, const Point3& b, const Point3& c) {
  auto sub = [](const Point3& u, const Point3& v) { return Point3{u[0] - v[0], u[1] - v[1], u[2] - v[2]}; };
  auto dot = [](const Point3& u, const Point3& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
  auto along = [](const Point3& o, const Point3& d, double t) {
    return Point3{o[0] + d[0] * t, o[1] + d[1] * t, o[2] + d[2] * t};
  };
  const Point3 ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Point3 bp = sub(p, b);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return along(a, ab, d1 / (d1 - d3));
  const Point3 cp = sub(p, c);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return along(a, ac, d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return along(b, sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denom = 1.0 / (va + vb + vc);
  return along(along(a, ab, vb * denom), ac, vc * denom);
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
