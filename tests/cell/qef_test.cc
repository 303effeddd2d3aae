// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/contour/qef.h.
#include "isovdb/cell/qef.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace isovdb::cell {
namespace {

TEST(Qef, CornerOfThreePlanesIsExact) {
  const std::vector<Vec3f> points{{1.5f, 0.2f, 0.9f}, {1.5f, 0.7f, 0.1f}, {0.3f, 2.5f, 0.6f},
                                  {0.8f, 2.5f, 0.2f}, {0.4f, 0.6f, 3.5f}, {0.9f, 0.1f, 3.5f}};
  const std::vector<Vec3f> normals{{1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 1}};
  const QefSolution s = solveQef(points, normals);
  EXPECT_EQ(s.rank, 3);
  EXPECT_NEAR(s.point[0], 1.5f, 1e-5f);
  EXPECT_NEAR(s.point[1], 2.5f, 1e-5f);
  EXPECT_NEAR(s.point[2], 3.5f, 1e-5f);
  EXPECT_NEAR(s.error, 0.0f, 1e-8f);
}

TEST(Qef, DegenerateSystemStaysAtTheMassPointOnThePlane) {
  // All normals equal: rank 1; the solution moves only along the normal.
  const Vec3f n{0.0f, 0.6f, 0.8f};
  std::vector<Vec3f> points, normals;
  for (int i = 0; i < 5; ++i) {
    const float u = static_cast<float>(i);
    // points on the plane n . x = 2
    points.push_back({u * 0.7f, 2.0f / 0.6f - u * 0.8f / 0.6f * 0.5f, u * 0.5f});
    normals.push_back(n);
  }
  const QefSolution s = solveQef(points, normals);
  EXPECT_EQ(s.rank, 1);
  EXPECT_NEAR(n[0] * s.point[0] + n[1] * s.point[1] + n[2] * s.point[2], 2.0f, 1e-4f);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(s.point[a], s.massPoint[a], 1e-4f);
}

TEST(Qef, TruncationIgnoresNearlyParallelNormals) {
  // Two almost parallel planes: truncating the tiny singular value keeps the
  // vertex near the mass point instead of shooting along the crease.
  const std::vector<Vec3f> points{{0, 0, 0}, {1, 0, 0}};
  const float e = 1e-3f;
  const std::vector<Vec3f> normals{{0, 0, 1}, {e, 0, std::sqrt(1 - e * e)}};
  const QefSolution s = solveQef(points, normals, {.singularValueThreshold = 0.1f});
  EXPECT_EQ(s.rank, 1);
  EXPECT_NEAR(s.point[0], 0.5f, 1e-3f);
  const QefSolution sharp = solveQef(points, normals, {.singularValueThreshold = 0.0f});
  EXPECT_EQ(sharp.rank, 2);
}

TEST(Qef, EmptyInput) {
  const QefSolution s = solveQef({}, {});
  EXPECT_EQ(s.rank, 0);
}

/// Unit normals scattered `spread` around (0, 0.6, 0.8), points within a unit cell: from
/// one plane (spread 0) to a corner of three (spread large).
void randomPlanes(std::mt19937& rng, float spread, int count, std::vector<Vec3f>& points, std::vector<Vec3f>& normals) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f), tilt(-1.0f, 1.0f);
  points.clear();
  normals.clear();
  for (int i = 0; i < count; ++i) {
    points.push_back({unit(rng), unit(rng), unit(rng)});
    Vec3f n{spread * tilt(rng), 0.6f + spread * tilt(rng), 0.8f + spread * tilt(rng)};
    const float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (float& c : n) c /= length;
    normals.push_back(n);
  }
}

TEST(Qef, MinimiserLiesWithinItsReachOfTheMassPoint) {
  std::mt19937 rng(17);
  std::vector<Vec3f> points, normals;
  int useful = 0;  // bounds below a voxel: what lets the error bound's check skip the solve
  for (const float threshold : {0.1f, 0.5f, 0.01f})
    for (const float spread : {0.0f, 0.02f, 0.1f, 0.5f, 3.0f})
      for (int trial = 0; trial < 200; ++trial) {
        randomPlanes(rng, spread, 3 + trial % 6, points, normals);
        const QefSolution s = solveQef(points, normals, {.singularValueThreshold = threshold});
        const QefReach r = qefReach(points, normals, {.singularValueThreshold = threshold});
        EXPECT_EQ(r.massPoint, s.massPoint);
        const float dx = s.point[0] - s.massPoint[0], dy = s.point[1] - s.massPoint[1],
                    dz = s.point[2] - s.massPoint[2];
        const double moved = std::sqrt(static_cast<double>(dx * dx + dy * dy + dz * dz));
        EXPECT_LE(moved, r.reach + 1e-5) << "threshold " << threshold << ", spread " << spread << ", trial " << trial;
        useful += r.reach < 1.0 ? 1 : 0;
      }
  EXPECT_GT(useful, 500);
  // Points on one plane with its normal: the minimiser is the mass point, and the bound says so.
  const std::vector<Vec3f> flat{{0.2f, 0.5f, 0.0f}, {0.9f, 0.1f, 0.0f}, {0.4f, 0.8f, 0.0f}};
  const std::vector<Vec3f> up(3, Vec3f{0.0f, 0.0f, 1.0f});
  EXPECT_EQ(qefReach(flat, up).reach, 0.0);
}

/// The truncated pseudo-inverse's minimiser by Eigen's iterative eigensolver, the
/// reference the fast paths of solveQef must agree with.
Vec3f referenceMinimiser(const std::vector<Vec3f>& points, const std::vector<Vec3f>& normals, double threshold,
                         int& rank) {
  Eigen::Vector3d mass = Eigen::Vector3d::Zero();
  for (const Vec3f& p : points) mass += Eigen::Vector3d(p[0], p[1], p[2]);
  mass /= static_cast<double>(points.size());
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atr = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d n(normals[i][0], normals[i][1], normals[i][2]);
    ata += n * n.transpose();
    atr += n * n.dot(Eigen::Vector3d(points[i][0], points[i][1], points[i][2]) - mass);
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(ata);
  const double largest = eigen.eigenvalues()(2);
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  rank = 0;
  for (int i = 0; i < 3; ++i) {
    const double s = eigen.eigenvalues()(i);
    if (s > 0.0 && s >= threshold * largest) {
      const Eigen::Vector3d v = eigen.eigenvectors().col(i);
      c += v * (v.dot(atr) / s);
      ++rank;
    }
  }
  const Eigen::Vector3d x = mass + c;
  return {static_cast<float>(x(0)), static_cast<float>(x(1)), static_cast<float>(x(2))};
}

TEST(Qef, AgreesWithTheIterativeEigensolverAtEveryRank) {
  // From nearly parallel normals (rank 1, solveQef's power-iteration path) to corners
  // (rank 3), including spreads whose second singular value lies near the cutoff.
  std::mt19937 rng(5);
  std::vector<Vec3f> points, normals;
  std::array<int, 4> ranks{};
  for (const float threshold : {0.1f, 0.5f, 0.01f})
    for (const float spread : {0.0f, 0.01f, 0.05f, 0.15f, 0.25f, 0.4f, 3.0f})
      for (int trial = 0; trial < 300; ++trial) {
        randomPlanes(rng, spread, 2 + trial % 7, points, normals);
        int rank = 0;
        const Vec3f expected = referenceMinimiser(points, normals, threshold, rank);
        const QefSolution s = solveQef(points, normals, {.singularValueThreshold = threshold});
        // Ranks may differ only where a value sits at the cutoff to rounding; none here.
        ASSERT_EQ(s.rank, rank) << "threshold " << threshold << ", spread " << spread << ", trial " << trial;
        ++ranks[static_cast<std::size_t>(rank)];
        for (int a = 0; a < 3; ++a) EXPECT_NEAR(s.point[a], expected[a], 2e-5f) << "trial " << trial;
        // The free directions are unit vectors normal to every kept direction's plane fit.
        for (int f = 0; f < 3 - s.rank; ++f) {
          const Vec3f& d = s.freeDirections[static_cast<std::size_t>(f)];
          EXPECT_NEAR(d[0] * d[0] + d[1] * d[1] + d[2] * d[2], 1.0f, 1e-5f);
        }
      }
  EXPECT_GT(ranks[1], 1000);
  EXPECT_GT(ranks[2], 100);
  EXPECT_GT(ranks[3], 100);
}

}  // namespace
}  // namespace isovdb::cell
