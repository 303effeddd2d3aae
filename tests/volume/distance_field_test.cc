// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/volume/distance_field.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>

#include "isovdb/volume/grids.h"
#include "isovdb/volume/ingest.h"
#include "support/vector_slice_stream.h"

namespace isovdb::volume {
namespace {

using test::VectorSliceStream;

constexpr float kRadius = 20.3f;
constexpr float kCentre = 31.6f;

Volume sphereMask() {
  VectorSliceStream stream = VectorSliceStream::fromFunction({64, 64, 64}, [](int x, int y, int z) {
    return std::hypot(x - kCentre, y - kCentre, z - kCentre) < kRadius ? 1.f : 0.f;
  });
  return ingestMask(stream, {});
}

TEST(DistanceField, SignsAreRightEverywhere) {
  const Volume mask = sphereMask();
  const Volume sdf = distanceField(mask, {.halfWidth = 3});
  ASSERT_EQ(sdf.kind(), VolumeKind::DistanceField);
  const FieldGrid& grid = fieldGrid(sdf);
  EXPECT_EQ(grid.getGridClass(), openvdb::GRID_LEVEL_SET);
  auto sdfAcc = grid.getConstAccessor();
  auto maskAcc = maskGrid(mask).getConstAccessor();
  // Every voxel of the box and a margin around it: inside the mask <=> negative,
  // whether the voxel is in the narrow band or not.
  for (int z = -4; z < 68; ++z)
    for (int y = -4; y < 68; ++y)
      for (int x = -4; x < 68; ++x) {
        const openvdb::Coord c(x, y, z);
        const float d = sdfAcc.getValue(c);
        ASSERT_EQ(maskAcc.isValueOn(c), d < 0) << x << "," << y << "," << z << " d=" << d;
      }
}

TEST(DistanceField, WithinOneVoxelOfTheAnalyticDistance) {
  const Volume sdf = distanceField(sphereMask(), {.halfWidth = 3});
  const FieldGrid& grid = fieldGrid(sdf);
  double worst = 0;
  std::int64_t band = 0;
  for (auto it = grid.cbeginValueOn(); it; ++it) {
    const openvdb::Coord c = it.getCoord();
    const float exact = std::hypot(c.x() - kCentre, c.y() - kCentre, c.z() - kCentre) - kRadius;
    if (std::abs(exact) > 2.5f) continue;  // the band's outer rim is clamped by construction
    worst = std::max(worst, static_cast<double>(std::abs(*it - exact)));
    ++band;
  }
  EXPECT_GT(band, 10000);
  EXPECT_LT(worst, 1.0) << "max |sdf - exact| over " << band << " band voxels";
}

TEST(DistanceField, BandFollowsTheSurface) {
  const Volume sdf = distanceField(sphereMask(), {.halfWidth = 3});
  const auto stats = sdf.stats();
  // A thin shell: far fewer active voxels than the 35k voxels inside the sphere.
  EXPECT_LT(stats.activeVoxels, 4 * 3.15 * kRadius * kRadius * 8);
  EXPECT_GT(stats.activeVoxels, 4 * 3.14 * kRadius * kRadius * 4);
}

TEST(DistanceField, RejectsNonMaskAndBadWidth) {
  const Volume sdf = distanceField(sphereMask());
  EXPECT_THROW(distanceField(sdf), InputError);
  EXPECT_THROW(distanceField(sphereMask(), {.halfWidth = 0}), InputError);
}

}  // namespace
}  // namespace isovdb::volume

namespace isovdb::volume {
namespace {

TEST(DistanceField, ChunksMeetWithoutSeams) {
  // A torus-like ring whose surface crosses the corner where eight 32^3 chunks meet.
  VectorSliceStream stream = VectorSliceStream::fromFunction({72, 72, 72}, [](int x, int y, int z) {
    const float rho = std::hypot(x - 32.3f, y - 31.7f) - 14.f;
    return std::hypot(rho, z - 32.2f) < 8.5f ? 1.f : 0.f;
  });
  const Volume mask = ingestMask(stream, {});
  const Volume whole = distanceField(mask, {.chunkSize = 0});
  const Volume chunked = distanceField(mask, {.chunkSize = 32});
  const FieldGrid& a = fieldGrid(whole);
  const FieldGrid& b = fieldGrid(chunked);
  EXPECT_EQ(a.activeVoxelCount(), b.activeVoxelCount());
  auto acc = b.getConstAccessor();
  for (auto it = a.cbeginValueOn(); it; ++it) {
    ASSERT_TRUE(acc.isValueOn(it.getCoord())) << it.getCoord();
    ASSERT_NEAR(acc.getValue(it.getCoord()), *it, 1e-4f) << it.getCoord();
  }
  // Signs outside the band agree too (flood fill between chunks).
  auto accA = a.getConstAccessor();
  for (int z = -4; z < 76; z += 3)
    for (int y = -4; y < 76; y += 3)
      for (int x = -4; x < 76; x += 3)
        ASSERT_EQ(accA.getValue(openvdb::Coord(x, y, z)) < 0, acc.getValue(openvdb::Coord(x, y, z)) < 0);
}

TEST(DistanceField, ChunksInParallelGiveTheSameValuesAsOneAtATime) {
  VectorSliceStream stream = VectorSliceStream::fromFunction({80, 72, 64}, [](int x, int y, int z) {
    const float rho = std::hypot(x - 40.3f, y - 35.7f) - 20.f;
    return std::hypot(rho, z - 31.2f) < 9.5f ? 1.f : 0.f;
  });
  const Volume mask = ingestMask(stream, {});
  Volume fields[2];
  const int threads[2] = {1, 8};
  for (int i = 0; i < 2; ++i) {
    tbb::task_arena arena(threads[i]);
    arena.execute([&] { fields[i] = distanceField(mask, {.chunkSize = 16}); });
  }
  const FieldGrid& a = fieldGrid(fields[0]);
  const FieldGrid& b = fieldGrid(fields[1]);
  ASSERT_GT(a.tree().leafCount(), 100u);
  ASSERT_EQ(a.tree().leafCount(), b.tree().leafCount());
  auto acc = b.getConstAccessor();
  for (auto leaf = a.tree().cbeginLeaf(); leaf; ++leaf) {
    const auto* other = acc.probeConstLeaf(leaf->origin());
    ASSERT_NE(other, nullptr) << leaf->origin();
    ASSERT_EQ(leaf->getValueMask(), other->getValueMask()) << leaf->origin();
    for (int i = 0; i < 512; ++i) ASSERT_EQ(leaf->getValue(i), other->getValue(i)) << leaf->origin();
  }
}

}  // namespace
}  // namespace isovdb::volume
