// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/store/vdb_file.h"

#include <gtest/gtest.h>

#include <openvdb/io/File.h>
#include <openvdb/tools/LevelSetSphere.h>

#include <cmath>

#include "isovdb/errors.h"
#include "isovdb/volume/grids.h"
#include "support/test_support.h"

namespace isovdb::store {
namespace {

using volume::FieldGrid;
using volume::Volume;
using volume::VolumeKind;

Volume sphereSdf(volume::Geometry geometry) {
  openvdb::initialize();
  // Radius 10 voxels, values in voxels, index-space transform, as the engine keeps them.
  FieldGrid::Ptr grid = openvdb::tools::createLevelSetSphere<FieldGrid>(10.f, openvdb::Vec3f(0.3f), 1.f, 3.f);
  return Volume(VolumeKind::DistanceField, grid, geometry, "sphere");
}

TEST(VdbFile, DistanceFieldRoundTripInWorldUnits) {
  test::TempDir dir;
  const Volume sdf = sphereSdf({.spacing = {0.5, 0.5, 0.5}, .origin = {1, 2, 3}});
  writeVdb(dir / "s.vdb", sdf, {.gridName = "ls"});

  // As a VFX tool sees it: a level set in world units with the right transform.
  openvdb::io::File file((dir / "s.vdb").string());
  file.open();
  auto raw = openvdb::gridPtrCast<FieldGrid>(file.readGrid("ls"));
  file.close();
  ASSERT_TRUE(raw);
  EXPECT_EQ(raw->getGridClass(), openvdb::GRID_LEVEL_SET);
  EXPECT_DOUBLE_EQ(raw->voxelSize()[0], 0.5);
  EXPECT_NEAR(raw->background(), 1.5f, 1e-6);
  EXPECT_NEAR(raw->indexToWorld(openvdb::Vec3d(0, 0, 0))[2], 3.0, 1e-12);

  const Volume back = readVdb(dir / "s.vdb", "ls");
  ASSERT_EQ(back.kind(), VolumeKind::DistanceField);
  EXPECT_EQ(back.geometry().spacing[1], 0.5);
  EXPECT_EQ(back.geometry().origin[2], 3.0);
  const FieldGrid& original = volume::fieldGrid(sdf);
  const FieldGrid& reread = volume::fieldGrid(back);
  EXPECT_EQ(original.activeVoxelCount(), reread.activeVoxelCount());
  auto acc = reread.getConstAccessor();
  for (auto it = original.cbeginValueOn(); it; ++it) ASSERT_NEAR(acc.getValue(it.getCoord()), *it, 1e-5f);
}

TEST(VdbFile, ReadsLegacyHalfFloatLevelSet) {
  const auto path = test::sharedDataDir() / "vdb" / "sphere.vdb";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not present";
  const auto grids = listVdbGrids(path);
  ASSERT_EQ(grids.size(), 1u);
  EXPECT_EQ(grids[0].name, "ls_sphere");
  EXPECT_EQ(grids[0].gridClass, "level set");
  const Volume volume = readVdb(path);
  EXPECT_EQ(volume.kind(), VolumeKind::DistanceField);
  EXPECT_NEAR(volume.geometry().spacing[0], 0.05, 1e-9);
  const auto stats = volume.stats();
  EXPECT_EQ(stats.activeVoxels, 270638);
  // Values are now in voxels: background 0.15 world = 3 voxels.
  EXPECT_NEAR(volume::fieldGrid(volume).background(), 3.f, 1e-3f);
}

TEST(VdbFile, MissingGridNamesTheGridsThatExist) {
  test::TempDir dir;
  writeVdb(dir / "s.vdb", sphereSdf({}), {.gridName = "density"});
  try {
    readVdb(dir / "s.vdb", "nope");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("s.vdb"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("no grid named 'nope'"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("density"), std::string::npos);
  }
}

TEST(VdbFile, WrongGridTypeIsRejected) {
  test::TempDir dir;
  auto vectors = openvdb::Vec3SGrid::create();
  vectors->setName("velocity");
  vectors->tree().setValueOn(openvdb::Coord(1, 2, 3), openvdb::Vec3s(1, 0, 0));
  openvdb::io::File((dir / "v.vdb").string()).write({vectors});
  try {
    readVdb(dir / "v.vdb", "velocity");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("v.vdb"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("vec3s"), std::string::npos);
  }
  EXPECT_THROW(readVdb(dir / "v.vdb"), InputError);  // no usable grid at all
}

TEST(VdbFile, MissingAndCorruptFiles) {
  test::TempDir dir;
  EXPECT_THROW(readVdb(dir / "missing.vdb"), IoError);
  test::writeFile(dir / "junk.vdb", "this is not a vdb file");
  EXPECT_THROW(readVdb(dir / "junk.vdb"), InputError);
}

TEST(VdbFile, UnwritablePathLeavesNothing) {
  test::TempDir dir;
  EXPECT_THROW(writeVdb(dir / "no" / "such" / "dir.vdb", sphereSdf({})), IoError);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace isovdb::store
