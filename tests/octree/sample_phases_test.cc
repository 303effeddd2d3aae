// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/octree/sample_phases.h against the float samples they summarise.
#include "isovdb/octree/sample_phases.h"

#include <gtest/gtest.h>

#include <random>

#include "isovdb/octree/criteria.h"

namespace isovdb::octree {
namespace {

/// A random block: stride 131 samples, so rows span three words and runs cross word boundaries.
cell::MetaCellSamples randomBlock(unsigned seed, double insideFraction) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  cell::MetaCellSamples s;
  s.allocate(128, {-64, 3, 1000});
  for (float& v : s.values) v = u(rng) < insideFraction ? -0.5f : 0.5f;
  return s;
}

TEST(SamplePhases, EveryBitIsItsSamplesPhaseApronIncluded) {
  cell::MetaCellSamples s = randomBlock(1, 0.5);
  s.value(5, 5, 5) = 0.0f;  // exactly iso is inside
  const SamplePhases phases(s, 0.0f);
  EXPECT_EQ(phases.size(), 128);
  for (int k = -1; k <= 129; k += 13)
    for (int j = -1; j <= 129; ++j)
      for (int i = -1; i <= 129; ++i) ASSERT_EQ(phases.inside(i, j, k), s.value(i, j, k) <= 0.0f) << i << j << k;
  EXPECT_TRUE(phases.inside(5, 5, 5));
}

TEST(SamplePhases, RunsAgreeWithTheSamplesAcrossWordBoundaries) {
  for (const double fraction : {0.0, 0.02, 0.5, 0.98, 1.0}) {
    const cell::MetaCellSamples s = randomBlock(7, fraction);
    const SamplePhases phases(s, 0.0f);
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> start(-1, 129);
    for (int trial = 0; trial < 4000; ++trial) {
      const int i = start(rng), j = start(rng), k = start(rng);
      const int length = std::uniform_int_distribution<int>(1, 130 - i)(rng);
      int changes = 0;
      bool anyIn = false, anyOut = false;
      for (int t = 0; t < length; ++t) {
        const bool in = s.value(i + t, j, k) <= 0.0f;
        (in ? anyIn : anyOut) = true;
        if (t > 0) changes += in != (s.value(i + t - 1, j, k) <= 0.0f);
      }
      const int phase = anyIn && anyOut ? -1 : anyIn ? 1 : 0;
      ASSERT_EQ(phases.runPhase(i, j, k, length), phase) << i << ' ' << j << ' ' << k << ' ' << length;
      ASSERT_EQ(phases.changesAlong(i, j, k, 0, length), changes) << i << ' ' << j << ' ' << k << ' ' << length;
      if (length <= 64) {
        const std::uint64_t bits = phases.row(i, j, k, length);
        for (int t = 0; t < length; ++t) ASSERT_EQ(((bits >> t) & 1u) != 0, s.value(i + t, j, k) <= 0.0f);
        if (length < 64) {
          ASSERT_EQ(bits >> length, 0u) << "bits beyond the run are cleared";
        }
      }
    }
  }
}

TEST(SamplePhases, SignChangesAlongEveryAxisMatchTheSamples) {
  const cell::MetaCellSamples s = randomBlock(3, 0.3);
  const SamplePhases phases(s, 0.0f);
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> start(0, 64);
  for (int trial = 0; trial < 2000; ++trial) {
    const std::array<int, 3> p{start(rng), start(rng), start(rng)};
    const int axis = trial % 3, length = 1 + trial % 64;
    int expected = 0;
    std::array<int, 3> q = p;
    for (int t = 1; t <= length; ++t) {
      const bool before = s.value(q) <= 0.0f;
      ++q[static_cast<std::size_t>(axis)];
      expected += (s.value(q) <= 0.0f) != before;
    }
    ASSERT_EQ(countSignChanges(phases, p, axis, length), expected) << trial;
  }
}

// The seam's leaves: a face on the meta-cell's boundary whose samples are not all of one
// phase, against every sample of every such face, for cells of 1 to 32 voxels in every
// position along the boundary (a face x = 0 or x = S reads sample by sample, the others in runs
// along x, 33 samples long at 32).
TEST(SamplePhases, SeamCrossingsAgreeWithTheBoundaryFacesSamples) {
  for (const double fraction : {0.0005, 0.01, 0.5}) {
    const cell::MetaCellSamples s = randomBlock(9, fraction);
    const SamplePhases phases(s, 0.0f);
    int crossed = 0, uniform = 0;
    for (const int size : {1, 2, 4, 8, 16, 32})
      for (int trial = 0; trial < 400; ++trial) {
        std::array<int, 3> origin{};
        for (int a = 0; a < 3; ++a) origin[a] = size * ((trial * (7 + 5 * a) + a) % (128 / size));
        origin[trial % 3] = trial % 2 == 0 ? 0 : 128 - size;  // on the boundary
        bool expected = false;
        for (int a = 0; a < 3; ++a)
          for (const int plane : {0, 128}) {
            if (origin[a] + (plane == 0 ? 0 : size) != plane) continue;
            std::array<int, 3> q = origin;
            q[a] = plane;
            const bool first = s.value(q) <= 0.0f;
            const int u = a == 0 ? 1 : 0, v = a == 2 ? 1 : 2;
            for (int j = 0; j <= size; ++j)
              for (int i = 0; i <= size; ++i) {
                std::array<int, 3> r = q;
                r[u] += i;
                r[v] += j;
                expected = expected || (s.value(r) <= 0.0f) != first;
              }
          }
        ASSERT_EQ(crossesMetaCellBoundary(phases, origin, size), expected)
            << origin[0] << ' ' << origin[1] << ' ' << origin[2] << " size " << size << " fraction " << fraction;
        (expected ? crossed : uniform) += 1;
      }
    if (fraction < 0.5) {
      EXPECT_GT(uniform, 0) << fraction;
    }
    EXPECT_GT(crossed, 0) << fraction;
  }
}

}  // namespace
}  // namespace isovdb::octree
