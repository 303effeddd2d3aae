// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// The interface distance field (volume/interface_band.h, the default method):
// signs are the mask's on inputs that break smoothing (single voxels, one-voxel
// sheets, random voxels), the band is the same bit for bit for every chunk size
// and thread count and has topologyToLevelSet's topology, planes come out exact,
// and analytic solids come out closer to their true distance than with
// topologyToLevelSet + sdfToSdf.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>

#include <openvdb/tools/Morphology.h>

#include "isovdb/volume/distance_field.h"
#include "isovdb/volume/grids.h"
#include "isovdb/volume/ingest.h"
#include "support/vector_slice_stream.h"

namespace isovdb::volume {
namespace {

using test::VectorSliceStream;

Volume maskOf(std::array<std::int64_t, 3> dims, const std::function<bool(int, int, int)>& inside) {
  VectorSliceStream stream =
      VectorSliceStream::fromFunction(dims, [&](int x, int y, int z) { return inside(x, y, z) ? 1.f : 0.f; });
  return ingestMask(stream, {});
}

Volume interfaceField(const Volume& mask, int chunk = 64) {
  return distanceField(mask, {.method = DistanceMethod::Interface, .halfWidth = 3, .chunkSize = chunk});
}

/// Every voxel of the box [lo, hi]^3: inside the mask <=> negative, and never 0.
void expectSignsOfTheMask(const Volume& mask, const Volume& sdf, int lo, int hi, const std::string& what) {
  SCOPED_TRACE(what);
  auto sdfAcc = fieldGrid(sdf).getConstAccessor();
  auto maskAcc = maskGrid(mask).getConstAccessor();
  for (int z = lo; z <= hi; ++z)
    for (int y = lo; y <= hi; ++y)
      for (int x = lo; x <= hi; ++x) {
        const openvdb::Coord c(x, y, z);
        const float d = sdfAcc.getValue(c);
        ASSERT_EQ(maskAcc.isValueOn(c), d < 0) << c << " d=" << d;
        ASSERT_NE(d, 0.f) << c;
      }
}

void expectSameTree(const FieldGrid& a, const FieldGrid& b, const std::string& what) {
  SCOPED_TRACE(what);
  ASSERT_GT(a.tree().leafCount(), 0u);
  ASSERT_EQ(a.tree().leafCount(), b.tree().leafCount());
  ASSERT_EQ(a.activeVoxelCount(), b.activeVoxelCount());
  auto acc = b.getConstAccessor();
  for (auto leaf = a.tree().cbeginLeaf(); leaf; ++leaf) {
    const auto* other = acc.probeConstLeaf(leaf->origin());
    ASSERT_NE(other, nullptr) << leaf->origin();
    ASSERT_EQ(leaf->getValueMask(), other->getValueMask()) << leaf->origin();
    for (openvdb::Index i = 0; i < FieldLeaf::SIZE; ++i)
      ASSERT_EQ(leaf->getValue(i), other->getValue(i)) << leaf->origin() << " voxel " << i;
  }
}

TEST(InterfaceBand, SignsAreTheMasksWhereABlurWouldLoseThem) {
  // Single voxels, a one-voxel sheet, a one-voxel line and a one-voxel hole in a
  // block: a blurred mask changes sign on each of them; the field must not.
  const Volume thin = maskOf({40, 40, 40}, [](int x, int y, int z) {
    if (x == 5 && y == 5 && z == 5) return true;                                     // a lone voxel
    if ((x == 3 && y == 9 && z == 3) || (x == 4 && y == 10 && z == 4)) return true;  // two touching at a corner
    if (z == 20 && x >= 4 && x < 36 && y >= 4 && y < 36) return true;                // a sheet
    if (y == 30 && z == 30 && x >= 3 && x < 37) return true;                         // a line
    const bool block = x >= 10 && x < 30 && y >= 8 && y < 16 && z >= 8 && z < 16;
    return block && !(x == 20 && y == 12 && z == 12);  // a block with a hole
  });
  const Volume thinField = interfaceField(thin);
  expectSignsOfTheMask(thin, thinField, -4, 44, "thin features");
  // A feature one voxel thick keeps its thickness: its surfaces half a voxel away,
  // not wherever a blur of it would put them.
  auto acc = fieldGrid(thinField).getConstAccessor();
  EXPECT_LE(acc.getValue({20, 20, 20}), -0.5f);  // the sheet
  EXPECT_LE(acc.getValue({20, 30, 30}), -0.5f);  // the line
  EXPECT_GE(acc.getValue({20, 12, 12}), 0.5f);   // the hole in the block
  // Random voxels at four densities: ambiguous faces, diagonal contacts, specks.
  for (const double density : {0.05, 0.3, 0.5, 0.8}) {
    std::mt19937 random(static_cast<unsigned>(density * 1000));
    std::bernoulli_distribution inside(density);
    std::vector<char> voxels(24 * 24 * 24);
    for (char& v : voxels) v = inside(random);
    const Volume mask = maskOf({24, 24, 24}, [&](int x, int y, int z) { return voxels[(z * 24 + y) * 24 + x] != 0; });
    expectSignsOfTheMask(mask, interfaceField(mask, 16), -4, 28, "random voxels, density " + std::to_string(density));
  }
}

TEST(InterfaceBand, SameBitsForEveryChunkSizeAndThreadCount) {
  // A ring whose surface crosses the corners where chunks of every size meet.
  const Volume mask = maskOf({88, 80, 72}, [](int x, int y, int z) {
    const double rho = std::hypot(x - 40.3, y - 39.7) - 22.0;
    return std::hypot(rho, z - 35.2) < 9.5;
  });
  const Volume reference = interfaceField(mask, 64);
  for (const int chunk : {8, 16, 24, 32, 128})
    expectSameTree(fieldGrid(reference), fieldGrid(interfaceField(mask, chunk)), "chunk " + std::to_string(chunk));
  for (const int threads : {1, 2, 8}) {
    tbb::task_arena arena(threads);
    Volume field;
    arena.execute([&] { field = interfaceField(mask, 16); });
    expectSameTree(fieldGrid(reference), fieldGrid(field), std::to_string(threads) + " threads");
  }
}

TEST(InterfaceBand, NarrowBandsAreTheWideBandsValues) {
  // Pass 1 scans a row's sites as one 64-bit word up to half-width 23 and byte by byte
  // beyond: a voxel of a narrow band has its nearest interface voxel closer than the
  // narrow reach, so a wide band finds the same one and gives the same value. Random
  // blobs with thin parts and sites at every offset along z.
  std::mt19937 random(5);
  std::uniform_real_distribution<double> at(4.0, 52.0), radius(1.2, 7.0);
  std::vector<std::array<double, 4>> balls(40);
  for (auto& b : balls) b = {at(random), at(random), at(random), radius(random)};
  const Volume mask = maskOf({56, 56, 56}, [&](int x, int y, int z) {
    for (const auto& b : balls)
      if (std::hypot(x - b[0], y - b[1], z - b[2]) < b[3]) return true;
    return z == 30 && x > 8 && x < 20;  // and a one-voxel sheet
  });
  const Volume wide = distanceField(mask, {.method = DistanceMethod::Interface, .halfWidth = 30});
  auto wideValues = fieldGrid(wide).getConstAccessor();
  for (const int halfWidth : {1, 3, 9, 23}) {
    SCOPED_TRACE("half-width " + std::to_string(halfWidth));
    const Volume narrow = distanceField(mask, {.method = DistanceMethod::Interface, .halfWidth = halfWidth});
    std::size_t compared = 0;
    for (auto v = fieldGrid(narrow).cbeginValueOn(); v; ++v) {
      ASSERT_TRUE(wideValues.isValueOn(v.getCoord())) << v.getCoord();
      ASSERT_EQ(wideValues.getValue(v.getCoord()), *v) << v.getCoord();
      ++compared;
    }
    EXPECT_GT(compared, 1000u);
  }
}

TEST(InterfaceBand, AxisAlignedFacesAreExactAndTheBandIsWhole) {
  // A box made of tiles (fill) and the same box voxel by voxel (leaves): the same band.
  // Away from its edges a face is a plane between voxel centres: the voxel k steps
  // inside reads -(k + 1/2), the one k steps outside +(k + 1/2), exactly.
  openvdb::initialize();
  const openvdb::CoordBBox box({-13, 2, 5}, {150, 140, 147});
  MaskGrid::Ptr tiles = MaskGrid::create(false);
  tiles->tree().fill(box, true, true);
  MaskGrid::Ptr voxels = MaskGrid::create(false);
  for (auto c = box.begin(); c; ++c)
    if (!box.expandBy(-4).isInside(*c)) voxels->tree().setValueOn(*c);  // a shell: no tiles, same surface
  voxels->tree().fill(box.expandBy(-4), true, true);
  const Volume a = interfaceField(Volume(VolumeKind::Mask, tiles, {}, "tiles"));
  const Volume b = interfaceField(Volume(VolumeKind::Mask, voxels, {}, "voxels"));
  expectSameTree(fieldGrid(a), fieldGrid(b), "tiles against voxels");
  auto acc = fieldGrid(a).getConstAccessor();
  for (int k = 0; k < 3; ++k) {
    const int y = 70, z = 76;  // the middle of the x faces
    EXPECT_FLOAT_EQ(acc.getValue({box.min().x() + k, y, z}), -(k + 0.5f)) << k;
    EXPECT_FLOAT_EQ(acc.getValue({box.min().x() - 1 - k, y, z}), k + 0.5f) << k;
    EXPECT_FLOAT_EQ(acc.getValue({box.max().x() - k, y, z}), -(k + 0.5f)) << k;
    EXPECT_FLOAT_EQ(acc.getValue({box.max().x() + 1 + k, y, z}), k + 0.5f) << k;
  }
  // The band: |value| < 3 exactly on the active voxels, which include every voxel
  // within 2.5 of a face (the far interior is a tile, not band).
  for (auto it = fieldGrid(a).cbeginValueOn(); it; ++it) ASSERT_LT(std::abs(*it), 3.f) << it.getCoord();
  for (int x = box.min().x() - 3; x <= box.min().x() + 2; ++x) EXPECT_TRUE(acc.isValueOn({x, 70, 76})) << x;
  EXPECT_FALSE(acc.isValueOn({70, 70, 76}));
  EXPECT_LT(acc.getValue({70, 70, 76}), 0.f);
}

/// Mean and largest |field - exact| over the band's (active) voxels with |exact| < 2.5.
std::pair<double, double> distanceError(const Volume& sdf, const std::function<double(double, double, double)>& exact) {
  double sum = 0, worst = 0;
  std::int64_t count = 0;
  auto acc = fieldGrid(sdf).getConstAccessor();
  for (int z = -2; z < 70; ++z)
    for (int y = -2; y < 70; ++y)
      for (int x = -2; x < 70; ++x) {
        const double e = exact(x, y, z);
        if (std::abs(e) >= 2.5 || !acc.isValueOn({x, y, z})) continue;
        const double error = std::abs(acc.getValue({x, y, z}) - e);
        sum += error, worst = std::max(worst, error), ++count;
      }
  return {sum / static_cast<double>(count), worst};
}

TEST(InterfaceBand, CloserToAnalyticSolidsThanTheTracker) {
  const auto sphere = [](double x, double y, double z) { return std::hypot(x - 33.6, y - 31.2, z - 32.7) - 21.3; };
  const auto torus = [](double x, double y, double z) {
    return std::hypot(std::hypot(x - 32.4, y - 33.1) - 20.0, z - 31.8) - 8.3;
  };
  for (const auto& [name, solid] :
       {std::pair<const char*, std::function<double(double, double, double)>>{"sphere", sphere}, {"torus", torus}}) {
    SCOPED_TRACE(name);
    const auto& exact = solid;  // a lambda cannot capture a structured binding before C++20 in clang 14
    const Volume mask = maskOf({68, 68, 68}, [&](int x, int y, int z) { return exact(x, y, z) < 0; });
    const auto [mean, worst] = distanceError(interfaceField(mask), exact);
    const auto [trackerMean, trackerWorst] =
        distanceError(distanceField(mask, {.method = DistanceMethod::Tracker, .halfWidth = 3}), exact);
    std::printf("%s: interface mean %.3f max %.3f | tracker mean %.3f max %.3f\n", name, mean, worst, trackerMean,
                trackerWorst);
    // The worst voxels are where the solid is flat along an axis (a pole): the mask
    // cannot place that plane closer than half a voxel, with either method.
    EXPECT_LT(mean, 0.1);
    EXPECT_LT(worst, 0.6);
    EXPECT_LT(mean, 0.85 * trackerMean);
  }
}

TEST(InterfaceBand, TheBandIsTopologyToLevelSetsBand) {
  // The active voxels: within halfWidth face steps of the other side, the topology
  // topologyToLevelSet gives (the mask dilated minus the mask eroded, NN_FACE), less
  // the few whose distance reaches halfWidth.
  const Volume mask = maskOf({68, 68, 68}, [](int x, int y, int z) {
    return std::hypot(std::hypot(x - 32.4, y - 33.1) - 20.0, z - 31.8) < 8.3 || std::hypot(x - 30, y - 30, z - 12) < 9;
  });
  MaskGrid::Ptr band = maskGrid(mask).deepCopy();
  MaskGrid::Ptr eroded = maskGrid(mask).deepCopy();
  openvdb::tools::dilateActiveValues(band->tree(), 3, openvdb::tools::NN_FACE, openvdb::tools::IGNORE_TILES);
  openvdb::tools::erodeActiveValues(eroded->tree(), 3, openvdb::tools::NN_FACE, openvdb::tools::IGNORE_TILES);
  band->tree().topologyDifference(eroded->tree());
  const Volume field = interfaceField(mask);
  const FieldGrid& ours = fieldGrid(field);
  auto acc = band->getConstAccessor();
  for (auto it = ours.cbeginValueOn(); it; ++it) ASSERT_TRUE(acc.isValueOn(it.getCoord())) << it.getCoord();
  EXPECT_GT(static_cast<double>(ours.activeVoxelCount()), 0.95 * static_cast<double>(band->activeVoxelCount()));
}

TEST(InterfaceBand, ClosingFillsAGapBeforeTheTransform) {
  // Two blocks one voxel apart: closed by one step, kept apart without closing.
  const Volume mask = maskOf({40, 24, 24}, [](int x, int y, int z) {
    return y >= 6 && y < 18 && z >= 6 && z < 18 && ((x >= 4 && x < 19) || (x >= 20 && x < 36));
  });
  const openvdb::Coord gap(19, 12, 12);
  EXPECT_GT(fieldGrid(interfaceField(mask)).getConstAccessor().getValue(gap), 0.f);
  const Volume closed = distanceField(mask, {.method = DistanceMethod::Interface, .closingSteps = 1});
  EXPECT_LT(fieldGrid(closed).getConstAccessor().getValue(gap), 0.f);
}

TEST(InterfaceBand, MethodNamesRoundTrip) {
  for (const DistanceMethod method : {DistanceMethod::Interface, DistanceMethod::Tracker})
    EXPECT_EQ(parseDistanceMethod(distanceMethodName(method)), method);
  EXPECT_EQ(parseDistanceMethod("sweep"), std::nullopt);
}

}  // namespace
}  // namespace isovdb::volume
