// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests for lib/isovdb/volume/digital_topology.h: hand-built voxel objects whose
// Euler characteristic a naive count gets wrong, a brute-force cubical-complex
// count on random volumes, and the BoolGrid path (tiles, negative coordinates).
#include "isovdb/volume/digital_topology.h"

#include <array>
#include <cstdint>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <openvdb/openvdb.h>

#include "isovdb/errors.h"
#include "isovdb/volume/grids.h"
#include "generators/shapes.h"
#include "support/vector_slice_stream.h"

namespace isovdb::volume {
namespace {

/// A small dense uint8 volume built in code.
struct Dense {
  int nx, ny, nz;
  std::vector<std::uint8_t> values;

  Dense(int x, int y, int z) : nx(x), ny(y), nz(z), values(static_cast<std::size_t>(x * y * z), 0) {}
  std::uint8_t& at(int x, int y, int z) { return values[static_cast<std::size_t>((z * ny + y) * nx + x)]; }
  std::uint8_t at(int x, int y, int z) const { return values[static_cast<std::size_t>((z * ny + y) * nx + x)]; }
  void set(int x, int y, int z, std::uint8_t v = 1) { at(x, y, z) = v; }
  void fillBox(std::array<int, 3> lo, std::array<int, 3> hi, std::uint8_t v = 1) {
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int x = lo[0]; x <= hi[0]; ++x) set(x, y, z, v);
  }
};

/// SliceStream over a Dense volume (values converted to float).
class DenseStream final : public io::SliceStream {
 public:
  explicit DenseStream(const Dense& dense) : dense_(dense) { header_.dims = {dense.nx, dense.ny, dense.nz}; }
  const std::string& source() const override { return source_; }
  const io::VolumeHeader& header() const override { return header_; }
  std::int64_t nextSlice() const override { return next_; }
  void readSlice(float* out) override {
    if (next_ >= dense_.nz) throw InputError("dense: past the end");
    for (int y = 0; y < dense_.ny; ++y)
      for (int x = 0; x < dense_.nx; ++x) out[y * dense_.nx + x] = dense_.at(x, y, static_cast<int>(next_));
    ++next_;
  }

 private:
  const Dense& dense_;
  std::string source_ = "dense";
  io::VolumeHeader header_;
  std::int64_t next_ = 0;
};

/// Mask volume with voxel (x, y, z) of `dense` at (x, y, z) + offset.
Volume maskVolume(const Dense& dense, openvdb::Coord offset = openvdb::Coord(0)) {
  auto grid = openvdb::BoolGrid::create(false);
  auto accessor = grid->getAccessor();
  for (int z = 0; z < dense.nz; ++z)
    for (int y = 0; y < dense.ny; ++y)
      for (int x = 0; x < dense.nx; ++x)
        if (dense.at(x, y, z)) accessor.setValueOn(offset + openvdb::Coord(x, y, z), true);
  return Volume(VolumeKind::Mask, grid, Geometry{}, "test mask");
}

/// chi = V - E + F - C of the union of closed cubes, by listing every cell.
/// Cells are keyed by doubled coordinates: a cell's centre is (2i + ex, ...)
/// with ex = 1 along the axes it spans.
std::int64_t bruteForceEuler(const Dense& dense) {
  std::set<std::tuple<int, int, int>> cells;
  for (int z = 0; z < dense.nz; ++z)
    for (int y = 0; y < dense.ny; ++y)
      for (int x = 0; x < dense.nx; ++x) {
        if (!dense.at(x, y, z)) continue;
        for (int cz = 0; cz <= 2; ++cz)
          for (int cy = 0; cy <= 2; ++cy)
            for (int cx = 0; cx <= 2; ++cx) cells.emplace(2 * x + cx, 2 * y + cy, 2 * z + cz);
      }
  std::int64_t chi = 0;
  for (const auto& [x, y, z] : cells) {
    const int dimension = (x & 1) + (y & 1) + (z & 1);
    chi += (dimension % 2 == 0) ? 1 : -1;
  }
  return chi;
}

std::int64_t streamEuler(const Dense& dense, const MaskRule& rule = {}) {
  DenseStream stream(dense);
  return eulerCharacteristic(stream, rule);
}

/// Checks the stream version, the BoolGrid version (at two offsets) and the
/// brute-force count against `expected`.
void expectEuler(const Dense& dense, std::int64_t expected) {
  EXPECT_EQ(bruteForceEuler(dense), expected) << "test case itself is wrong";
  EXPECT_EQ(streamEuler(dense), expected);
  EXPECT_EQ(eulerCharacteristic(maskVolume(dense)), expected);
  EXPECT_EQ(eulerCharacteristic(maskVolume(dense, openvdb::Coord(-37, 5, -1000))), expected);
}

TEST(DigitalTopology, EmptyVolume) { expectEuler(Dense(4, 3, 2), 0); }

TEST(DigitalTopology, OneVoxel) {
  Dense dense(3, 3, 3);
  dense.set(1, 1, 1);
  expectEuler(dense, 1);
}

TEST(DigitalTopology, OneVoxelVolume) {
  // The voxel fills the whole volume: every vertex is on the boundary.
  Dense dense(1, 1, 1);
  dense.set(0, 0, 0);
  expectEuler(dense, 1);
}

TEST(DigitalTopology, FullVolumeTouchesEveryFace) {
  Dense dense(5, 4, 3);
  dense.fillBox({0, 0, 0}, {4, 3, 2});
  expectEuler(dense, 1);
}

TEST(DigitalTopology, TwoVoxelsTouchingAtACornerAreOneComponent) {
  Dense dense(2, 2, 2);
  dense.set(0, 0, 0);
  dense.set(1, 1, 1);
  // V = 15, E = 24, F = 12, C = 2 -> 1 (26-connected), not 2.
  expectEuler(dense, 1);
}

TEST(DigitalTopology, TwoVoxelsTouchingAlongAnEdgeAreOneComponent) {
  Dense dense(2, 2, 1);
  dense.set(0, 0, 0);
  dense.set(1, 1, 0);
  expectEuler(dense, 1);
}

TEST(DigitalTopology, TwoSeparateVoxels) {
  Dense dense(4, 1, 1);
  dense.set(0, 0, 0);
  dense.set(2, 0, 0);
  expectEuler(dense, 2);
}

TEST(DigitalTopology, CubeWithCentreRemovedHasACavity) {
  Dense dense(3, 3, 3);
  dense.fillBox({0, 0, 0}, {2, 2, 2});
  dense.set(1, 1, 1, 0);
  expectEuler(dense, 2);
}

TEST(DigitalTopology, RingOfEightAroundAHole) {
  Dense dense(3, 3, 1);
  dense.fillBox({0, 0, 0}, {2, 2, 0});
  dense.set(1, 1, 0, 0);
  expectEuler(dense, 0);
}

TEST(DigitalTopology, RingClosedOnlyThroughCornersIsStillARing) {
  // Four voxels meeting diagonally enclose one 6-connected background voxel.
  Dense dense(3, 3, 1);
  dense.set(1, 0, 0);
  dense.set(0, 1, 0);
  dense.set(2, 1, 0);
  dense.set(1, 2, 0);
  expectEuler(dense, 0);
}

TEST(DigitalTopology, HollowCubeShell) {
  Dense dense(7, 7, 7);
  dense.fillBox({1, 1, 1}, {5, 5, 5});
  dense.fillBox({2, 2, 2}, {4, 4, 4}, 0);
  expectEuler(dense, 2);  // one component, one cavity
}

TEST(DigitalTopology, HollowCubeShellOpenedOnOneSide) {
  Dense dense(7, 7, 7);
  dense.fillBox({1, 1, 1}, {5, 5, 5});
  dense.fillBox({2, 2, 2}, {4, 4, 4}, 0);
  dense.set(3, 3, 1, 0);  // one-voxel hole: the cavity now opens to the outside
  expectEuler(dense, 1);
}

TEST(DigitalTopology, HollowCubeShellPiercedByATunnel) {
  Dense dense(7, 7, 7);
  dense.fillBox({1, 1, 1}, {5, 5, 5});
  dense.fillBox({2, 2, 2}, {4, 4, 4}, 0);
  dense.set(3, 3, 1, 0);
  dense.set(3, 3, 5, 0);  // through both walls: a thickened annulus
  expectEuler(dense, 0);
}

TEST(DigitalTopology, ThickShellWithATunnelInItsWall) {
  // 7^3 cube, 3^3 cavity, and a one-voxel tunnel along z through the wall at
  // (1, 1): it only meets the cavity along an edge, which the foreground
  // owns, so cavity and tunnel stay apart: 1 - 1 + 1.
  Dense dense(7, 7, 7);
  dense.fillBox({0, 0, 0}, {6, 6, 6});
  dense.fillBox({2, 2, 2}, {4, 4, 4}, 0);
  for (int z = 0; z < 7; ++z) dense.set(1, 1, z, 0);
  expectEuler(dense, 1);
}

TEST(DigitalTopology, SolidTorusOfVoxels) {
  Dense dense(6, 6, 3);
  dense.fillBox({0, 0, 0}, {5, 5, 2});
  dense.fillBox({2, 2, 0}, {3, 3, 2}, 0);
  expectEuler(dense, 0);
}

TEST(DigitalTopology, RandomVolumesMatchBruteForce) {
  std::mt19937 random(12345);
  for (int trial = 0; trial < 40; ++trial) {
    Dense dense(1 + static_cast<int>(random() % 9), 1 + static_cast<int>(random() % 9),
                1 + static_cast<int>(random() % 9));
    const unsigned density = 20 + random() % 60;  // percent
    for (auto& value : dense.values) value = (random() % 100) < density ? 1 : 0;
    const std::int64_t expected = bruteForceEuler(dense);
    SCOPED_TRACE("trial " + std::to_string(trial));
    EXPECT_EQ(streamEuler(dense), expected);
    EXPECT_EQ(eulerCharacteristic(maskVolume(dense, openvdb::Coord(-3, -9, 4))), expected);
  }
}

TEST(DigitalTopology, MaskRuleSelectsLabels) {
  Dense dense(5, 1, 1);
  dense.set(0, 0, 0, 13);
  dense.set(1, 0, 0, 7);
  dense.set(2, 0, 0, 13);
  dense.set(4, 0, 0, 13);
  EXPECT_EQ(streamEuler(dense), 2);  // value > 0: voxels 0-2 joined, voxel 4 apart
  EXPECT_EQ(streamEuler(dense, MaskRule{.threshold = 0.0, .labels = {13}}), 3);
  EXPECT_EQ(streamEuler(dense, MaskRule{.threshold = 10.0, .labels = {}}), 3);
}

TEST(DigitalTopology, StreamStartsAtItsNextSlice) {
  Dense dense(3, 3, 3);
  dense.set(1, 1, 0);
  dense.set(1, 1, 2);
  DenseStream stream(dense);
  std::vector<float> skipped(9);
  stream.readSlice(skipped.data());  // slice 0 is consumed before the count
  EXPECT_EQ(eulerCharacteristic(stream, MaskRule{}), 1);
}

TEST(DigitalTopology, GridWithActiveTilesCountsLikeVoxels) {
  // A 64^3 block filled as tiles (no leaves), with a 3^3 cavity of voxels
  // punched into it and a tunnel straight through it.
  auto grid = openvdb::BoolGrid::create(false);
  grid->tree().fill(openvdb::CoordBBox(openvdb::Coord(-64, 0, 0), openvdb::Coord(-1, 63, 63)), true, true);
  ASSERT_GT(grid->tree().activeTileCount(), 0u);
  const Volume block(VolumeKind::Mask, grid, Geometry{}, "tiles");
  EXPECT_EQ(eulerCharacteristic(block), 1);

  auto accessor = grid->getAccessor();
  for (int z = 20; z < 23; ++z)
    for (int y = 30; y < 33; ++y)
      for (int x = -40; x < -37; ++x) accessor.setValueOff(openvdb::Coord(x, y, z), false);
  EXPECT_EQ(eulerCharacteristic(block), 2);

  for (int z = 0; z < 64; ++z) accessor.setValueOff(openvdb::Coord(-10, 10, z), false);
  EXPECT_EQ(eulerCharacteristic(block), 1);  // 1 component - 1 tunnel + 1 cavity
}

TEST(DigitalTopology, InactiveTrueVoxelsAreOutside) {
  // Inside means active; an inactive voxel holding `true` is background.
  auto grid = openvdb::BoolGrid::create(false);
  auto accessor = grid->getAccessor();
  for (int x = 0; x < 3; ++x) accessor.setValueOn(openvdb::Coord(x, 0, 0), true);
  accessor.setValueOff(openvdb::Coord(1, 0, 0), true);
  EXPECT_EQ(eulerCharacteristic(Volume(VolumeKind::Mask, grid, Geometry{}, "m")), 2);
}

TEST(DigitalTopology, RejectsAScalarVolume) {
  const Volume scalar(VolumeKind::Scalar, openvdb::FloatGrid::create(0.f), Geometry{}, "field");
  EXPECT_THROW(eulerCharacteristic(scalar), InputError);
}

TEST(DigitalTopology, InterrupterCancels) {
  struct Cancel : Interrupter {
    bool wasInterrupted(int) override { return true; }
  } cancel;
  Dense dense(4, 4, 4);
  dense.set(1, 1, 1);
  DenseStream stream(dense);
  EXPECT_THROW(eulerCharacteristic(stream, MaskRule{}, &cancel), Interrupted);
  EXPECT_THROW(eulerCharacteristic(maskVolume(dense), &cancel), Interrupted);
}

}  // namespace
}  // namespace isovdb::volume

namespace isovdb::volume {
namespace {

/// chi with (6, 18) adjacency of a small dense volume given as 0/1 values, x fastest.
std::int64_t chi6(std::array<std::int64_t, 3> dims, const std::vector<int>& inside) {
  std::vector<float> values(inside.begin(), inside.end());
  test::VectorSliceStream stream(dims, values);
  return eulerCharacteristic(stream, MaskRule{.threshold = 0.5, .labels = {}}, nullptr, Adjacency::Foreground6);
}

TEST(EulerCharacteristic6, DiagonalContactsStayApart) {
  EXPECT_EQ(chi6({2, 2, 1}, {1, 0, 0, 1}), 2);                 // sharing only an edge
  EXPECT_EQ(chi6({2, 2, 2}, {1, 0, 0, 0, 0, 0, 0, 1}), 2);     // sharing only a corner
  EXPECT_EQ(chi6({2, 1, 1}, {1, 1}), 1);                       // sharing a face
  EXPECT_EQ(chi6({2, 2, 2}, {1, 1, 1, 1, 1, 1, 1, 1}), 1);     // a full block
  EXPECT_EQ(chi6({3, 3, 1}, {1, 1, 1, 1, 0, 1, 1, 1, 1}), 0);  // a ring around a hole
  EXPECT_EQ(chi6({3, 3, 1}, {0, 1, 0, 1, 0, 1, 0, 1, 0}), 4);  // a diagonal "ring": four pieces
}

TEST(EulerCharacteristic6, BodyDiagonalBackgroundEnclosesNoTunnel) {
  // Six inside voxels around two opposite outside corners: with 26-adjacent
  // background the outside would pass through the block's centre (a ring, chi 0);
  // with 18-adjacent background it does not (chi 1).
  EXPECT_EQ(chi6({2, 2, 2}, {0, 1, 1, 1, 1, 1, 1, 0}), 1);
  // Add a third outside voxel: now the two corners connect through it (18-adjacent
  // to both), and the six become five voxels in a bent row: still one piece.
  EXPECT_EQ(chi6({2, 2, 2}, {0, 0, 1, 1, 1, 1, 1, 0}), 1);
}

TEST(EulerCharacteristic6, AgreesWith26OnShapesWithoutDiagonalContacts) {
  for (samples::ShapeKind kind : samples::shapesOfKnownTopology()) {
    auto stream = samples::makeShapeStream(kind, {.size = 64});
    EXPECT_EQ(eulerCharacteristic(*stream, MaskRule{}, nullptr, Adjacency::Foreground6),
              samples::knownEulerCharacteristic(kind))
        << samples::shapeName(kind);
  }
}

}  // namespace
}  // namespace isovdb::volume
