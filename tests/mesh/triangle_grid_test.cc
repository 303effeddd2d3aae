// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// TriangleGrid: the closest point on a triangle against a dense barycentric search,
// and the binned "within d of the surface" answer against every triangle.
#include "isovdb/mesh/triangle_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mesh/test_meshes.h"

namespace isovdb::mesh {
namespace {

double distance(const Vec3d& a, const Vec3d& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

TEST(TriangleGrid, ClosestPointMatchesADenseSearchInEveryRegion) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(-2.0, 2.0);
  const auto random = [&] { return Vec3d{coord(rng), coord(rng), coord(rng)}; };
  constexpr int kSteps = 400;
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3d a = random(), b = random(), c = random(), p = random();
    const Vec3d q = closestPointOnTriangle(p, a, b, c);
    double best = 1e300;
    for (int i = 0; i <= kSteps; ++i)
      for (int j = 0; i + j <= kSteps; ++j) {
        const double u = static_cast<double>(i) / kSteps, v = static_cast<double>(j) / kSteps;
        const Vec3d s{a[0] + u * (b[0] - a[0]) + v * (c[0] - a[0]), a[1] + u * (b[1] - a[1]) + v * (c[1] - a[1]),
                      a[2] + u * (b[2] - a[2]) + v * (c[2] - a[2])};
        best = std::min(best, distance(p, s));
      }
    // The dense search is at most a grid step (the longest edge / kSteps) worse, never better.
    const double step = std::max({distance(a, b), distance(b, c), distance(c, a)}) / kSteps;
    EXPECT_LE(distance(p, q), best + 1e-9) << "trial " << trial;
    EXPECT_GE(distance(p, q), best - step) << "trial " << trial;
  }
}

TEST(TriangleGrid, AnswersAsASearchOverEveryTriangle) {
  const Mesh mesh = test::torus(24, 12, 3.0f, 1.0f, {0.3f, -0.2f, 0.1f});
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> coord(-5.5f, 5.5f);
  for (const double binSize : {0.25, 1.0, 4.0}) {
    const TriangleGrid grid(mesh, binSize);
    int near = 0, far = 0;
    for (int trial = 0; trial < 2000; ++trial) {
      const Vec3f p{coord(rng), coord(rng), coord(rng)};
      const Vec3d q{p[0], p[1], p[2]};
      double best = 1e300;
      for (const Triangle& t : mesh.triangles) {
        const auto at = [&](std::uint32_t v) {
          return Vec3d{mesh.positions[v][0], mesh.positions[v][1], mesh.positions[v][2]};
        };
        best = std::min(best, distance(q, closestPointOnTriangle(q, at(t[0]), at(t[1]), at(t[2]))));
      }
      for (const double d : {0.1, 0.5, 1.5}) {
        if (std::abs(best - d) < 1e-6) continue;  // too close to call in float
        EXPECT_EQ(grid.within(p, d), best <= d) << "bin " << binSize << ", d " << d << ", distance " << best;
        (best <= d ? near : far) += 1;
      }
    }
    EXPECT_GT(near, 100);  // both answers were asked for
    EXPECT_GT(far, 100);
  }
  EXPECT_FALSE(TriangleGrid(Mesh{}, 1.0).within({0.0f, 0.0f, 0.0f}, 10.0));
}

}  // namespace
}  // namespace isovdb::mesh
