// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/octree/build.h: regular vs adaptive constructions,
// thin features, balance, determinism across thread counts.
#include "isovdb/octree/build.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "isovdb/cell/dual_vertex.h"
#include "isovdb/cell/trilinear.h"
#include "isovdb/errors.h"
#include "isovdb/octree/inspect.h"
#include "isovdb/octree/sample_phases.h"
#include "isovdb/octree/surface_deviation.h"

namespace isovdb::octree {
namespace {

cell::MetaCellSamples sphere(int size, double cx, double cy, double cz, double r,
                             std::array<int, 3> origin = {0, 0, 0}) {
  return cell::makeMetaCellSamples(size, origin, [=](int x, int y, int z) {
    return std::sqrt((x - cx) * (x - cx) + (y - cy) * (y - cy) + (z - cz) * (z - cz)) - r;
  });
}

constexpr cell::ContourSettings kRegular{.method = cell::ContourMethod::Regular};
constexpr cell::ContourSettings kAdaptive{.method = cell::ContourMethod::Adaptive};

/// The octree options these tests were written for: uniform down to depth 2, no
/// QEF criterion (OctreeOptions{} are isovdb extract's: 16-voxel cells, 0.15).
constexpr OctreeOptions kOptions{.minDepth = 2, .qefTolerance = -1.0f};

/// True if the samples of the leaf's closed box are not all one phase.
bool crossedBySurface(const cell::MetaCellSamples& s, const OctreeLeaf& l, float iso = 0.0f) {
  const bool first = cell::isInside(s.value(l.origin), iso);
  for (int k = 0; k <= l.size; ++k)
    for (int j = 0; j <= l.size; ++j)
      for (int i = 0; i <= l.size; ++i)
        if (cell::isInside(s.value(l.origin[0] + i, l.origin[1] + j, l.origin[2] + k), iso) != first) return true;
  return false;
}

TEST(BuildOctree, ResolveDepthsFromDepthsOrCellSizes) {
  // The former defaults: uniform down to depth 2, 1-voxel cells at the deepest.
  EXPECT_EQ(resolveDepths({.minDepth = 2, .maxCellSize = 0, .finestCellSize = 0}, 128).maxDepth, 7);
  EXPECT_EQ(resolveDepths({.minDepth = 2, .maxCellSize = 0, .finestCellSize = 0}, 128).minDepth, 2);
  const OctreeDepths d = resolveDepths({.maxCellSize = 32, .finestCellSize = 2}, 128);
  EXPECT_EQ(d.minDepth, 2);
  EXPECT_EQ(d.maxDepth, 6);
  // The defaults (extract's): leaves from 16 voxels (clamped to the meta-cell) down
  // to 1 voxel. A depth >= 0 wins over the matching cell size.
  EXPECT_EQ(resolveDepths({}, 128).minDepth, 3);
  EXPECT_EQ(resolveDepths({}, 128).maxDepth, 7);
  EXPECT_EQ(resolveDepths({}, 8).minDepth, 0);
  const OctreeDepths given = resolveDepths({.minDepth = 1, .maxDepth = 5, .maxCellSize = 32, .finestCellSize = 2}, 128);
  EXPECT_EQ(given.minDepth, 1);
  EXPECT_EQ(given.maxDepth, 5);
  EXPECT_THROW(resolveDepths({.finestCellSize = 3}, 128), InputError);
  EXPECT_THROW(resolveDepths({.minDepth = 5, .maxDepth = 4}, 128), InputError);
  EXPECT_THROW(resolveDepths({.maxDepth = 8}, 128), InputError);
}

class SphereR40 : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { samples_ = new cell::MetaCellSamples(sphere(128, 64.3, 63.7, 64.2, 40.0)); }
  static void TearDownTestSuite() {
    delete samples_;
    samples_ = nullptr;
  }
  static cell::MetaCellSamples* samples_;
};
cell::MetaCellSamples* SphereR40::samples_ = nullptr;

TEST_F(SphereR40, RegularPutsEverySurfaceLeafAtTheMaximumDepth) {
  OctreeBuildStats stats;
  const LinearOctree tree = buildOctree(*samples_, kRegular, kOptions, &stats);
  std::size_t surface = 0;
  for (const OctreeLeaf& l : tree.leaves()) {
    const bool crossed = crossedBySurface(*samples_, l);
    ASSERT_EQ(l.surface, crossed) << l.key;
    if (crossed) {
      ASSERT_EQ(l.depth, 7) << l.key;
      ++surface;
    }
    ASSERT_FALSE(l.complex);
  }
  EXPECT_GT(surface, 10000u);
  EXPECT_EQ(summarizeOctree(tree).surfaceLeaves, surface);
}

TEST_F(SphereR40, AdaptiveIsBalancedAndThreeTimesSmaller) {
  OctreeBuildStats regularStats, adaptiveStats;
  const LinearOctree regular = buildOctree(*samples_, kRegular, kOptions, &regularStats);
  const LinearOctree adaptive = buildOctree(*samples_, kAdaptive, kOptions, &adaptiveStats);
  EXPECT_TRUE(isBalanced(adaptive));
  const OctreeSummary r = summarizeOctree(regular), a = summarizeOctree(adaptive);
  for (const OctreeLeaf& l : adaptive.leaves()) {
    ASSERT_EQ(l.surface, crossedBySurface(*samples_, l));
    ASSERT_FALSE(l.complex);
  }
  std::printf(
      "[ sphere r=40, S=128, max depth 7 ] surface leaves: regular %zu, adaptive %zu (%.1fx); "
      "leaves: regular %zu, adaptive %zu; adaptive balance splits %zu, complex cells %zu\n",
      r.surfaceLeaves, a.surfaceLeaves, double(r.surfaceLeaves) / double(a.surfaceLeaves), r.leaves, a.leaves,
      adaptiveStats.balanceSplits, adaptiveStats.complexCells);
  EXPECT_GE(r.surfaceLeaves, 3 * a.surfaceLeaves);
  for (int minDepth : {3, 4}) {
    const OctreeSummary m =
        summarizeOctree(buildOctree(*samples_, kAdaptive, {.minDepth = minDepth, .qefTolerance = -1.0f}));
    std::printf("[ sphere r=40 ] adaptive, min depth %d: %zu surface leaves (%.1fx fewer than regular)\n", minDepth,
                m.surfaceLeaves, double(r.surfaceLeaves) / double(m.surfaceLeaves));
    EXPECT_GE(r.surfaceLeaves, 3 * m.surfaceLeaves);
  }
  // The regular tree is generally not balanced; the adaptive one is by construction.
  OctreeOptions geometric{.minDepth = 2, .qefTolerance = 0.05f};
  OctreeBuildStats gStats;
  const LinearOctree refined = buildOctree(*samples_, kAdaptive, geometric, &gStats);
  EXPECT_TRUE(isBalanced(refined));
  EXPECT_GE(summarizeOctree(refined).surfaceLeaves, a.surfaceLeaves);
  std::printf("[ sphere r=40 ] adaptive + QEF tolerance 0.05: %zu surface leaves, %zu geometric splits\n",
              summarizeOctree(refined).surfaceLeaves, gStats.geometricSplits);
}

// With an error bound E, a kept leaf's full-resolution surface lies within a share of E of
// its vertex plane: kInteriorPlaneShare inside the meta-cell from four voxels up (the bound's
// check covers those), kPlaneShare in two-voxel leaves. The looser share is used: some
// leaves of four voxels or more stray beyond kPlaneShare * E.
TEST(BuildOctree, ErrorBoundHoldsEachLeafToItsPlaneShare) {
  constexpr float kMaxError = 1.0f;
  // Two-voxel leaves inside the meta-cell take what the check allows, coarser ones all of E.
  constexpr float kTwoVoxelShare = std::max(kPlaneShare * kMaxError, kMaxError - kTwoVoxelReserve);
  // A sphere, its upper half rippled by 0.7 voxel: smooth parts for coarse leaves, the
  // ripples' folds for two-voxel ones.
  const cell::MetaCellSamples samples = cell::makeMetaCellSamples(128, {0, 0, 0}, [](int x, int y, int z) {
    const double r = std::sqrt((x - 64.3) * (x - 64.3) + (y - 63.7) * (y - 63.7) + (z - 64.2) * (z - 64.2));
    return r - 40.0 - 0.7 * std::sin(0.25 * x) * std::sin(0.25 * y) * (z > 64 ? 1.0 : 0.0);
  });
  const LinearOctree tree = buildOctree(samples, kAdaptive, {.maxError = kMaxError});
  const SamplePhases phases(samples, 0.0f);
  int looser = 0, measured = 0, twoVoxel = 0, looserTwoVoxel = 0;
  for (const OctreeLeaf& l : tree.leaves()) {
    if (!l.surface || l.vertexTruncation < 0.0f || l.size == 1) continue;
    ASSERT_FALSE(touchesMetaCellBoundary(l.origin, l.size, samples.size));
    const Vec3f vertex{l.vertex[0], l.vertex[1], l.vertex[2]};
    const float deviation = surfaceDeviation(samples, phases, l.origin, l.size, vertex, 0.0f);
    ++measured;
    // The vertex itself lies where the check after contouring finds it within the bound.
    EXPECT_TRUE(cell::levelWithin(samples, vertex, cell::DualVertexOptions{}, kMaxError - kErrorBoundMargin))
        << "leaf of " << l.size << " at " << l.origin[0] << "," << l.origin[1] << "," << l.origin[2];
    if (l.size == 2) {
      ++twoVoxel;
      EXPECT_LE(deviation, kTwoVoxelShare)
          << "two-voxel leaf at " << l.origin[0] << "," << l.origin[1] << "," << l.origin[2];
      looserTwoVoxel += deviation > kPlaneShare * kMaxError;
    } else {
      EXPECT_LE(deviation, kInteriorPlaneShare * kMaxError) << "leaf of " << l.size;
      looser += deviation > kPlaneShare * kMaxError;
    }
  }
  std::printf("[ rippled sphere, E = 1 ] %d of %d leaves beyond the boundary's plane share, %d of %d two-voxel ones\n",
              looser + looserTwoVoxel, measured, looserTwoVoxel, twoVoxel);
  EXPECT_GT(looser, 0);
  EXPECT_GT(twoVoxel, 0);
}

// The error bound's passes build a block's tree again with more forced splits, recalling
// the other cells' evaluations from a BuildMemo: the same tree as a build without it, the
// forced cells split although the memo holds them as leaves.
TEST_F(SphereR40, MemoRecallsTheSameTreeWithMoreForcedSplits) {
  OctreeOptions options{.maxError = 1.0f};
  BuildMemo memo;
  const LinearOctree first = buildOctree(*samples_, kAdaptive, options, nullptr, nullptr, nullptr, nullptr, &memo);
  for (const OctreeLeaf& l : first.leaves())
    if (l.surface && l.size > 1 && options.forcedSplits.size() < 40) options.forcedSplits.push_back(l.key);
  ASSERT_EQ(options.forcedSplits.size(), 40u);
  std::sort(options.forcedSplits.begin(), options.forcedSplits.end());
  const LinearOctree recalled = buildOctree(*samples_, kAdaptive, options, nullptr, nullptr, nullptr, nullptr, &memo);
  const LinearOctree fresh = buildOctree(*samples_, kAdaptive, options);
  ASSERT_EQ(recalled.leafCount(), fresh.leafCount());
  EXPECT_GT(recalled.leafCount(), first.leafCount());
  for (std::size_t i = 0; i < fresh.leafCount(); ++i) {
    ASSERT_EQ(recalled.leaf(i).key, fresh.leaf(i).key) << "leaf " << i;
    EXPECT_EQ(recalled.leaf(i).vertex, fresh.leaf(i).vertex) << "leaf " << i;
    EXPECT_EQ(recalled.leaf(i).cornerSigns, fresh.leaf(i).cornerSigns) << "leaf " << i;
  }
  for (const MortonKey key : options.forcedSplits) EXPECT_EQ(recalled.findLeaf(key), LinearOctree::kNone);
}

TEST(BuildOctree, ThinSheetForcesTheMaximumDepth) {
  // A sheet one voxel thick at z = 9 (odd, so no cell boundary above size 1 lies on it).
  const cell::MetaCellSamples s =
      cell::makeMetaCellSamples(32, {0, 0, 0}, [](int, int, int z) { return std::abs(z - 9.0) - 0.5; });
  for (const cell::ContourSettings& settings : {kAdaptive, kRegular}) {
    OctreeBuildStats stats;
    const LinearOctree tree = buildOctree(s, settings, kOptions, &stats);
    std::size_t touching = 0;
    for (const OctreeLeaf& l : tree.leaves()) {
      if (l.origin[2] <= 9 && 9 <= l.origin[2] + l.size) {
        ++touching;
        EXPECT_EQ(l.size, 1) << "leaf " << l.key << " touches the sheet at size " << l.size;
      }
    }
    EXPECT_EQ(touching, 2u * 32 * 32);
    // The adaptive construction reaches the sheet through its complex edges; the
    // regular one refines every crossed cell and reads no criterion above the finest depth.
    if (settings.method == cell::ContourMethod::Adaptive) {
      EXPECT_GT(stats.complexEdges, 0u);
    }
  }
  // With the maximum depth capped at 4-voxel cells, the leaves holding the
  // sheet stay complex and are reported.
  OctreeBuildStats stats;
  const LinearOctree capped =
      buildOctree(s, kAdaptive, {.minDepth = 2, .finestCellSize = 4, .qefTolerance = -1.0f}, &stats);
  EXPECT_EQ(stats.unresolvedComplexLeaves, 8u * 8u);
  EXPECT_EQ(summarizeOctree(capped).complexLeaves, 8u * 8u);
}

TEST(BuildOctree, SmallTunnelForcesTheMaximumDepth) {
  // Solid everywhere except a tunnel one sample wide along z through (9, 9).
  const cell::MetaCellSamples s = cell::makeMetaCellSamples(
      32, {0, 0, 0}, [](int x, int y, int) { return 0.8 - std::sqrt((x - 9.0) * (x - 9.0) + (y - 9.0) * (y - 9.0)); });
  for (const cell::ContourSettings& settings : {kAdaptive, kRegular}) {
    OctreeBuildStats stats;
    const LinearOctree tree = buildOctree(s, settings, kOptions, &stats);
    std::size_t touching = 0;
    for (const OctreeLeaf& l : tree.leaves()) {
      if (l.origin[0] <= 9 && 9 <= l.origin[0] + l.size && l.origin[1] <= 9 && 9 <= l.origin[1] + l.size) {
        ++touching;
        EXPECT_EQ(l.size, 1) << "leaf " << l.key << " touches the tunnel at size " << l.size;
      }
    }
    EXPECT_EQ(touching, 4u * 32);
    if (settings.method == cell::ContourMethod::Adaptive) {
      EXPECT_GT(stats.complexFaces, 0u);
    }
  }
}

TEST(BuildOctree, AdaptiveKeepsUnsubdividedFarFromTheSurface) {
  const cell::MetaCellSamples s = sphere(64, 8.5, 8.5, 8.5, 4.0);
  const LinearOctree tree = buildOctree(s, kAdaptive, {.minDepth = 1, .qefTolerance = -1.0f});
  const OctreeSummary sum = summarizeOctree(tree);
  EXPECT_TRUE(isBalanced(tree));
  EXPECT_EQ(sum.leavesPerDepth[1], 7u);  // the far octants stay whole
  EXPECT_GT(sum.surfaceLeaves, 0u);
}

TEST(BuildOctree, DeterministicFor1And2And8Threads) {
  // A bumpy field with many complex cells.
  const cell::MetaCellSamples s = cell::makeMetaCellSamples(64, {64, 0, -64}, [](int x, int y, int z) {
    return 3.0 * std::sin(0.45 * x) * std::cos(0.31 * y) + 2.0 * std::sin(0.27 * z + 0.2 * x) + 0.3;
  });
  std::vector<std::vector<OctreeLeaf>> results;
  for (int threads : {1, 2, 8}) {
    tbb::task_arena arena(threads);
    arena.execute([&] {
      for (const cell::ContourSettings& settings : {kRegular, kAdaptive}) {
        const LinearOctree tree = buildOctree(s, settings, {.minDepth = 2, .qefTolerance = 0.2f});
        results.push_back(tree.leaves());
      }
    });
  }
  ASSERT_EQ(results.size(), 6u);
  for (std::size_t i = 2; i < results.size(); ++i) {
    const auto& a = results[i % 2];
    const auto& b = results[i];
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t j = 0; j < a.size(); ++j) {
      ASSERT_EQ(a[j].key, b[j].key);
      ASSERT_EQ(a[j].cornerSigns, b[j].cornerSigns);
      ASSERT_EQ(a[j].surface, b[j].surface);
      ASSERT_EQ(a[j].complex, b[j].complex);
    }
  }
}

TEST(BuildOctree, IsoValueAndExactIsoSamples) {
  // A constant field equal to iso is all inside: no surface anywhere.
  const cell::MetaCellSamples flat = cell::makeMetaCellSamples(16, {0, 0, 0}, [](int, int, int) { return 0.0; });
  const LinearOctree tree = buildOctree(flat, kAdaptive, {.minDepth = 0, .qefTolerance = -1.0f});
  EXPECT_EQ(tree.leafCount(), 1u);
  EXPECT_EQ(tree.leaf(0).cornerSigns, 0xff);
  EXPECT_FALSE(tree.leaf(0).surface);
  // Same field, iso just below: all outside.
  const cell::ContourSettings below{.method = cell::ContourMethod::Adaptive, .iso = -0.5f};
  EXPECT_EQ(buildOctree(flat, below, {.minDepth = 0, .qefTolerance = -1.0f}).leaf(0).cornerSigns, 0);
}

}  // namespace
}  // namespace isovdb::octree
