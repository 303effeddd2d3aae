// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/mesh/mesh_distance.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "isovdb/errors.h"

namespace isovdb::mesh {

namespace {

// Distances only, no predicates: plain double arithmetic is enough.
using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Triangle3 = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle3>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Point toPoint(const Vec3f& p) { return {p[0], p[1], p[2]}; }

std::vector<Triangle3> trianglesOf(const Mesh& mesh, const char* name) {
  if (mesh.triangles.empty()) throw InputError(std::string("compare: mesh ") + name + " has no triangles");
  std::vector<Triangle3> result;
  result.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles) {
    for (const std::uint32_t v : t)
      if (v >= mesh.positions.size())
        throw InputError(std::string("compare: mesh ") + name + " has a triangle with vertex " + std::to_string(v) +
                         " of " + std::to_string(mesh.positions.size()));
    result.emplace_back(toPoint(mesh.positions[t[0]]), toPoint(mesh.positions[t[1]]), toPoint(mesh.positions[t[2]]));
  }
  return result;
}

/// Samples of a mesh: the vertices its triangles use, then each triangle's barycentric
/// grid of n + 1 points a side (corners left out), n = ceil(longest edge / spacing).
std::vector<Point> samplesOf(const Mesh& mesh, const std::vector<Triangle3>& triangles, double spacing) {
  std::vector<char> used(mesh.positions.size(), 0);
  for (const Triangle& t : mesh.triangles)
    for (const std::uint32_t v : t) used[v] = 1;
  std::vector<Point> samples;
  for (std::size_t v = 0; v < used.size(); ++v)
    if (used[v]) samples.push_back(toPoint(mesh.positions[v]));
  for (const Triangle3& t : triangles) {
    double longest = 0.0;
    for (int e = 0; e < 3; ++e) longest = std::max(longest, std::sqrt(CGAL::squared_distance(t[e], t[(e + 1) % 3])));
    const int n = static_cast<int>(std::min(1024.0, std::ceil(longest / spacing)));
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const int k = n - i - j;
        if (i == n || j == n || k == n) continue;  // a corner: a vertex, sampled above
        const double a = static_cast<double>(i) / n, b = static_cast<double>(j) / n, c = static_cast<double>(k) / n;
        samples.emplace_back(a * t[0].x() + b * t[1].x() + c * t[2].x(), a * t[0].y() + b * t[1].y() + c * t[2].y(),
                             a * t[0].z() + b * t[1].z() + c * t[2].z());
      }
  }
  return samples;
}

OneSidedDistance distancesTo(const std::vector<Point>& samples, const Tree& tree) {
  std::vector<double> distances(samples.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples.size(), 1024),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i)
                        distances[i] = std::sqrt(tree.squared_distance(samples[i]));
                    });
  OneSidedDistance result;
  result.samples = distances.size();
  double sum = 0.0;  // in sample order: the same total whatever the threads
  for (const double d : distances) sum += d;
  result.mean = sum / static_cast<double>(distances.size());
  const auto farthest = std::max_element(distances.begin(), distances.end());
  result.max = *farthest;
  const Point& at = samples[static_cast<std::size_t>(farthest - distances.begin())];
  result.farthest = {at.x(), at.y(), at.z()};
  const auto rank = static_cast<std::size_t>(std::floor(0.99 * static_cast<double>(distances.size() - 1)));
  std::nth_element(distances.begin(), distances.begin() + static_cast<std::ptrdiff_t>(rank), distances.end());
  result.p99 = distances[rank];
  return result;
}

}  // namespace

double MeshDistance::upperBound() const noexcept { return hausdorff() + spacing / std::sqrt(3.0); }

MeshDistance compareMeshes(const Mesh& a, const Mesh& b, const MeshDistanceOptions& options) {
  if (!(options.spacing > 0.0)) throw InputError("compare: the sample spacing must be positive");
  const std::vector<Triangle3> trianglesA = trianglesOf(a, "A");
  const std::vector<Triangle3> trianglesB = trianglesOf(b, "B");
  MeshDistance result;
  result.spacing = options.spacing;
  const auto oneSide = [&](const Mesh& from, const std::vector<Triangle3>& fromTriangles,
                           const std::vector<Triangle3>& toTriangles) {
    Tree tree(toTriangles.begin(), toTriangles.end());
    tree.accelerate_distance_queries();
    return distancesTo(samplesOf(from, fromTriangles, options.spacing), tree);
  };
  result.aToB = oneSide(a, trianglesA, trianglesB);
  result.bToA = oneSide(b, trianglesB, trianglesA);
  return result;
}

}  // namespace isovdb::mesh
