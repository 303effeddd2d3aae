// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/store/vdb_file.h"

#include <gtest/gtest.h>

#include <openvdb/io/Compression.h>
#include <openvdb/io/File.h>
#include <openvdb/io/Stream.h>
#include <openvdb/tools/LevelSetSphere.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <random>

#include "isovdb/errors.h"
#include "isovdb/store/vdb_layout.h"
#include "isovdb/volume/grids.h"
#include "support/test_support.h"

namespace isovdb::store {
namespace {

using volume::FieldGrid;
using volume::Volume;
using volume::VolumeKind;

/// readVdb's error on `bytes` with the low `size` bytes of `value` written at `offset`
/// (little-endian, as OpenVDB writes on this machine), or "no error".
std::string patchedReadError(const std::filesystem::path& dir, std::string bytes, std::size_t offset,
                             std::int64_t value, std::size_t size) {
  std::memcpy(bytes.data() + offset, &value, size);
  test::writeFile(dir / "bad.vdb", bytes);
  try {
    readVdb(dir / "bad.vdb");
  } catch (const InputError& e) {
    return std::string(e.what());
  }
  return "no error";
}

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

/// readVdb and listVdbGrids on `bytes`: either a volume or an InputError, nothing else.
void expectReadOrInputError(const std::filesystem::path& path, const std::string& bytes, const std::string& what) {
  test::writeFile(path, bytes);
  for (const bool list : {false, true}) {
    try {
      if (list)
        listVdbGrids(path);
      else
        readVdb(path);
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path.filename().string()), std::string::npos) << what << ": " << e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << what << ": not an InputError: " << e.what();
    }
  }
}

TEST(VdbFile, LayoutOfAWrittenFile) {
  test::TempDir dir;
  writeVdb(dir / "s.vdb", sphereSdf({}), {.gridName = "ls"});
  const VdbLayout layout = checkVdbLayout(dir / "s.vdb");
  EXPECT_TRUE(layout.hasGridOffsets);
  ASSERT_EQ(layout.grids.size(), 1u);
  EXPECT_EQ(layout.grids[0].name, "ls");
  EXPECT_EQ(layout.grids[0].type, "Tree_float_5_4_3");
  EXPECT_LT(layout.grids[0].gridPosition, layout.grids[0].blockPosition);
  EXPECT_EQ(layout.grids[0].endPosition, static_cast<std::int64_t>(std::filesystem::file_size(dir / "s.vdb")));
}

TEST(VdbFile, StreamWrittenFileWithoutOffsetsIsCheckedAndRead) {
  // io::Stream writes no grid offsets; its first grid's head is checked where it lies, after
  // the descriptor's unused offsets, and the file reads as one written with offsets.
  test::TempDir dir;
  openvdb::initialize();
  FieldGrid::Ptr grid = openvdb::tools::createLevelSetSphere<FieldGrid>(6.f, openvdb::Vec3f(0.f), 1.f, 3.f);
  grid->setName("ls");
  {
    std::ofstream out(dir / "stream.vdb", std::ios::binary);
    openvdb::io::Stream(out).write(openvdb::GridCPtrVec{grid});
  }
  const VdbLayout layout = checkVdbLayout(dir / "stream.vdb");
  EXPECT_FALSE(layout.hasGridOffsets);
  ASSERT_EQ(layout.grids.size(), 1u);
  EXPECT_EQ(layout.grids[0].name, "ls");
  const Volume read = readVdb(dir / "stream.vdb");
  EXPECT_EQ(read.kind(), VolumeKind::DistanceField);
  EXPECT_EQ(read.stats().activeVoxels, static_cast<std::int64_t>(grid->activeVoxelCount()));
  // A 4 GB delayed-load size in that head is refused as in a file with offsets.
  std::string bytes = test::readFile(dir / "stream.vdb");
  const std::size_t delayed = bytes.find("__delayedload");
  ASSERT_NE(delayed, std::string::npos);
  const std::uint32_t huge = 0xffff0000u;
  std::memcpy(bytes.data() + delayed + 13 + 4 + 4, &huge, 4);  // the mask table's compressed size
  test::writeFile(dir / "bad.vdb", bytes);
  try {
    readVdb(dir / "bad.vdb");
    ADD_FAILURE() << "read a 4 GB delayed-load size";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("compressed into 4294901760"), std::string::npos) << e.what();
  }
}

TEST(VdbFile, TruncatedFilesAreRefusedBeforeOpenVdbReadsThem) {
  test::TempDir dir;
  writeVdb(dir / "s.vdb", sphereSdf({}));
  const std::string bytes = test::readFile(dir / "s.vdb");
  // The first 64 bytes made OpenVDB spin for > 25 s at 3-4 GB; every cut must fail at once.
  for (const std::size_t cut : {std::size_t{0}, std::size_t{7}, std::size_t{12}, std::size_t{40}, std::size_t{64},
                                std::size_t{100}, bytes.size() / 2, bytes.size() - 1}) {
    test::writeFile(dir / "cut.vdb", bytes.substr(0, cut));
    EXPECT_THROW(checkVdbLayout(dir / "cut.vdb"), InputError) << "cut at " << cut;
    EXPECT_THROW(readVdb(dir / "cut.vdb"), InputError) << "cut at " << cut;
  }
}

TEST(VdbFile, LengthsAndOffsetsBeyondTheFileAreNamed) {
  test::TempDir dir;
  writeVdb(dir / "s.vdb", sphereSdf({}), {.gridName = "ls"});
  const std::string bytes = test::readFile(dir / "s.vdb");
  const VdbLayout layout = checkVdbLayout(dir / "s.vdb");
  const auto patched = [&](std::size_t offset, std::int64_t value, std::size_t size) {
    return patchedReadError(dir.path(), bytes, offset, value, size);
  };
  // The grid name's length sits 4 bytes before the name, whose descriptor ends 24 bytes before gridPosition.
  const std::size_t offsets = static_cast<std::size_t>(layout.grids[0].gridPosition) - 24;
  const std::size_t nameLength = offsets - 4 - 16 - 4 - 2 - 4;  // parent "", type, "ls"
  ASSERT_EQ(bytes.substr(nameLength + 4, 2), "ls");
  EXPECT_NE(patched(nameLength, 0x7fffffff, 4).find("runs past the end of the file"), std::string::npos);
  EXPECT_NE(patched(offsets + 16, layout.grids[0].endPosition + 1000, 8).find("beyond the file's"), std::string::npos);
  EXPECT_NE(patched(offsets + 8, layout.grids[0].gridPosition - 1, 8).find("out of order"), std::string::npos);
  EXPECT_NE(patched(0, 0x12345678, 8).find("magic"), std::string::npos);
  EXPECT_NE(patched(8, 999, 4).find("version 999"), std::string::npos);
  // The transform's map type name follows the grid's metadata; OpenVDB allocated its
  // declared length before reading (fuzz_vdb: a 2 GB string, 10.8 s, in a 39 KB file).
  const std::size_t mapName = bytes.find("UniformScaleMap", static_cast<std::size_t>(layout.grids[0].gridPosition));
  ASSERT_NE(mapName, std::string::npos);
  ASSERT_LT(mapName, static_cast<std::size_t>(layout.grids[0].blockPosition));
  const std::string transform = patched(mapName - 4, 0x7fffffff, 4);
  EXPECT_NE(transform.find("grid transform: a string of 2147483647 bytes"), std::string::npos) << transform;
  // A length that stays within the file but runs into the voxel buffers.
  const auto intoBuffers =
      static_cast<std::int64_t>(layout.grids[0].blockPosition) - static_cast<std::int64_t>(mapName) + 1;
  EXPECT_NE(patched(mapName - 4, intoBuffers, 4).find("run into its voxel data"), std::string::npos);
  // OpenVDB sizes the delayed-load tables from their leaf count before reading them
  // (fuzz_vdb: 2^31 leaves, 15 GB); the count follows the type name and the value's size.
  const std::size_t delayed = bytes.find("__delayedload");
  ASSERT_NE(delayed, std::string::npos);
  EXPECT_NE(patched(delayed + 13 + 4, 0x59000004, 4).find("a delayed-load table of 1493172228 leaves"),
            std::string::npos);
}

TEST(VdbFile, ChunkLengthsAreCheckedBeforeOpenVdbReadsThem) {
  // OpenVDB 10 reads -length raw bytes into the buffer before comparing the sizes (a heap
  // overflow), and allocates a positive length before decompressing; the linker routes
  // both functions through lib/vdb_chunk_guard, which refuses such a length first. The
  // buffer is large enough that OpenVDB's own function would not crash: the message says
  // which ran.
  const auto chunk = [](std::int64_t length) {
    std::string bytes(sizeof(length), '\0');
    std::memcpy(bytes.data(), &length, sizeof(length));
    return bytes + std::string(64, 'x');
  };
  std::vector<char> buffer(256);
  for (const bool zip : {false, true}) {
    const auto read = [&](std::int64_t length, std::size_t numBytes) {
      std::istringstream in(chunk(length));
      try {
        if (zip)
          openvdb::io::unzipFromStream(in, buffer.data(), numBytes);
        else
          openvdb::io::bloscFromStream(in, buffer.data(), numBytes);
      } catch (const openvdb::RuntimeError& e) {
        return std::string(e.what());
      }
      return std::string("read");
    };
    EXPECT_NE(read(-64, 16).find("damaged compressed data: a raw chunk of 64 bytes for a 16-byte buffer"),
              std::string::npos);
    EXPECT_NE(read(std::int64_t{1} << 44, 16).find("chunk of 17592186044416 bytes"), std::string::npos);
    EXPECT_NE(read(std::numeric_limits<std::int64_t>::min(), 16).find("raw chunk of 9223372036854775808"),
              std::string::npos);
    EXPECT_EQ(read(-64, 64), "read");  // a raw chunk of the buffer's size is read as before
  }
}

TEST(VdbFile, RootCountsAndFlagsAreCheckedBeforeOpenVdbLoopsOverThem) {
  // OpenVDB loops over the root's declared tile and child counts whatever the file holds
  // (fuzz_vdb: 7 x 10^8 of each spun for 10 s over a 39 KB file) and loads each tile's
  // active flag into a bool (a byte other than 0 or 1: undefined behaviour).
  test::TempDir dir;
  openvdb::initialize();
  FieldGrid::Ptr grid = FieldGrid::create(3.f);
  grid->setName("tiles");
  grid->setGridClass(openvdb::GRID_LEVEL_SET);
  grid->tree().addTile(/*level=*/3, openvdb::Coord(0), -3.f, /*active=*/true);  // a root tile
  grid->tree().setValueOn(openvdb::Coord(5000, 0, 0), 1.f);
  writeVdb(dir / "t.vdb", Volume(VolumeKind::DistanceField, grid, {}, "tiles"), {.gridName = "tiles"});
  const std::string bytes = test::readFile(dir / "t.vdb");
  ASSERT_EQ(patchedReadError(dir.path(), bytes, 0, 0x56444220, 8), "no error");  // the magic, as written
  const auto message = [&](std::size_t at, std::int64_t value, std::size_t size) {
    return patchedReadError(dir.path(), bytes, at, value, size);
  };
  // After the map's name and its 120 bytes: buffer count, background, tile and child counts.
  const std::size_t map = bytes.find("UniformScaleMap");
  ASSERT_NE(map, std::string::npos);
  const std::size_t tiles = map + 15 + 120 + 4 + 4;
  std::uint32_t declared = 0;
  std::memcpy(&declared, bytes.data() + tiles, 4);
  ASSERT_EQ(declared, 1u);
  EXPECT_NE(message(tiles, 0x7fffffff, 4).find("its root declares 2147483647 tiles"), std::string::npos);
  EXPECT_NE(message(tiles + 4, 0x7fffffff, 4).find("and 2147483647 children"), std::string::npos);
  // The first tile: counts, origin (12 bytes), value (4), then its active flag.
  EXPECT_NE(message(tiles + 8 + 12 + 4, 7, 1).find("root tile 0 has the active flag 7"), std::string::npos);
}

TEST(VdbFile, FlippedHeaderBytesGiveAVolumeOrAnInputError) {
  test::TempDir dir;
  writeVdb(dir / "s.vdb", sphereSdf({}));
  const std::string bytes = test::readFile(dir / "s.vdb");
  const VdbLayout layout = checkVdbLayout(dir / "s.vdb");
  // Every byte before the grid's data but its three offsets, which OpenVDB follows blindly
  // when they stay plausible (LengthsAndOffsetsBeyondTheFileAreNamed covers the implausible).
  const auto gridStart = static_cast<std::size_t>(layout.grids[0].gridPosition);
  std::mt19937 random(7);
  for (int trial = 0; trial < 150; ++trial) {
    std::size_t at = std::uniform_int_distribution<std::size_t>(0, gridStart - 25)(random);
    std::string copy = bytes;
    copy[at] = static_cast<char>(copy[at] ^ (1 << (trial % 8)));
    expectReadOrInputError(dir / "flip.vdb", copy, "byte " + std::to_string(at));
  }
}

TEST(VdbFile, UnwritablePathLeavesNothing) {
  test::TempDir dir;
  EXPECT_THROW(writeVdb(dir / "no" / "such" / "dir.vdb", sphereSdf({})), IoError);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace isovdb::store
