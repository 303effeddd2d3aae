// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/io/raw_reader.h, and of the pieces every dense reader shares:
// byte_stream.h (ByteStream suite), dense_slice_stream.h and dense_volume.h (DenseVolume suite).
#include "isovdb/io/raw_reader.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <limits>
#include <string>
#include <vector>

#include "io/reader_test_support.h"
#include "isovdb/errors.h"
#include "isovdb/io/byte_stream.h"
#include "isovdb/io/dense_volume.h"

namespace isovdb::io {
namespace {

using namespace test;  // TempDir, writeFile and the reader helpers of reader_test_support.h

// --- RawReader --------------------------------------------------------------------

TEST(RawReader, ReadsEveryTypeInBothByteOrdersExactly) {
  TempDir dir;
  const std::array<std::int64_t, 3> dims{5, 4, 3};
  for (SampleType type : kAllTypes) {
    for (bool big : {false, true}) {
      SCOPED_TRACE(std::string(sampleTypeName(type)) + (big ? " big" : " little"));
      const std::vector<double> values = testValues(type, 60);
      const auto path = dir / "vol.raw";
      writeFile(path, encode(type, big, values));
      auto stream = openRaw(path, {.dims = dims, .type = type, .bigEndian = big});
      EXPECT_EQ(stream->header().dims, dims);
      EXPECT_EQ(stream->header().sampleType, type);
      EXPECT_EQ(stream->header().bigEndian, big);
      EXPECT_EQ(stream->source(), path.string());
      const std::vector<float> read = readAll(*stream);
      for (std::size_t i = 0; i < values.size(); ++i)
        ASSERT_EQ(read[i], static_cast<float>(values[i])) << "sample " << i;
      EXPECT_EQ(stream->nextSlice(), 3);
      float extra[20];
      EXPECT_THROW(stream->readSlice(extra), std::out_of_range);
    }
  }
}

TEST(RawReader, SkipsHeaderBytesAndKeepsSpacing) {
  TempDir dir;
  const std::vector<double> values = testValues(SampleType::UInt16, 2 * 3 * 4);
  writeFile(dir / "vol.bin", std::string(13, 'H') + encode(SampleType::UInt16, true, values));
  auto stream = openRaw(dir / "vol.bin", {.dims = {2, 3, 4},
                                          .type = SampleType::UInt16,
                                          .bigEndian = true,
                                          .spacing = {0.5, 2.0, 3.0},
                                          .headerBytes = 13});
  EXPECT_EQ(stream->header().spacing, (std::array<double, 3>{0.5, 2.0, 3.0}));
  EXPECT_EQ(stream->header().origin, (std::array<double, 3>{0.0, 0.0, 0.0}));
  const std::vector<float> read = readAll(*stream);
  for (std::size_t i = 0; i < values.size(); ++i) EXPECT_EQ(read[i], static_cast<float>(values[i]));
}

TEST(RawReader, StreamsALargeVolumeSliceBySlice) {
  TempDir dir;
  const std::int64_t nx = 256, ny = 256, nz = 64;
  std::string bytes(static_cast<std::size_t>(nx * ny * nz), '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i)
    bytes[i] = static_cast<char>((i / static_cast<std::size_t>(nx * ny)) & 0xff);
  writeFile(dir / "big.raw", bytes);
  auto stream = openRaw(dir / "big.raw", {.dims = {nx, ny, nz}, .type = SampleType::UInt8});
  std::vector<float> slice(static_cast<std::size_t>(nx * ny));
  for (std::int64_t z = 0; z < nz; ++z) {
    stream->readSlice(slice.data());
    ASSERT_EQ(slice.front(), static_cast<float>(z));
    ASSERT_EQ(slice.back(), static_cast<float>(z));
  }
}

TEST(RawReader, SkippedSlicesAreNotReadAndTheNextOnesAreExact) {
  // A distributed run's slab skips the slices before its window (io/slice_window.h).
  TempDir dir;
  const std::vector<double> values = testValues(SampleType::Int16, 5 * 4 * 6);
  writeFile(dir / "vol.raw", encode(SampleType::Int16, false, values));
  auto stream = openRaw(dir / "vol.raw", {.dims = {5, 4, 6}, .type = SampleType::Int16});
  stream->skipSlices(2);
  EXPECT_EQ(stream->nextSlice(), 2);
  std::vector<float> slice(20);
  stream->readSlice(slice.data());
  for (std::size_t i = 0; i < slice.size(); ++i) ASSERT_EQ(slice[i], static_cast<float>(values[40 + i]));
  stream->skipSlices(3);
  EXPECT_EQ(stream->nextSlice(), 6);
  EXPECT_THROW(stream->skipSlices(1), std::out_of_range);
  // A truncated file is named when the skip runs past its end.
  writeFile(dir / "short.raw", encode(SampleType::Int16, false, values).substr(0, 100));
  expectError<InputError>(
      [&] {
        openRaw(dir / "short.raw", {.dims = {5, 4, 6}, .type = SampleType::Int16})->skipSlices(4);
      },
      {"short.raw"});
}

TEST(RawReader, MissingFileIsIoError) {
  TempDir dir;
  const auto path = dir / "absent.raw";
  expectError<IoError>(
      [&] {
        openRaw(path, {.dims = {2, 2, 2}, .type = SampleType::UInt8});
      },
      {path.string(), "no such file"});
}

TEST(RawReader, FileSizeMustMatchDims) {
  TempDir dir;
  const auto path = dir / "short.raw";
  writeFile(path, std::string(100, '\0'));
  // 4 x 4 x 4 uint16 = 128 bytes.
  expectError<InputError>(
      [&] {
        openRaw(path, {.dims = {4, 4, 4}, .type = SampleType::UInt16});
      },
      {path.string(), "100", "128"});
  // Header bytes count too: 28 + 64 = 92.
  expectError<InputError>(
      [&] {
        openRaw(path, {.dims = {4, 4, 4}, .type = SampleType::UInt8, .headerBytes = 28});
      },
      {path.string(), "100", "92"});
}

TEST(RawReader, ZeroDimIsRejected) {
  TempDir dir;
  const auto path = dir / "zero.raw";
  writeFile(path, "");
  expectError<InputError>(
      [&] {
        openRaw(path, {.dims = {4, 0, 4}, .type = SampleType::UInt8});
      },
      {path.string(), "dims", "y", "got 0"});
}

TEST(RawReader, NegativeDimIsRejected) {
  TempDir dir;
  const auto path = dir / "neg.raw";
  writeFile(path, "");
  expectError<InputError>(
      [&] {
        openRaw(path, {.dims = {4, 4, -3}, .type = SampleType::UInt8});
      },
      {path.string(), "dims", "z", "-3"});
}

TEST(RawReader, OverflowingDimsAreRejected) {
  TempDir dir;
  const auto path = dir / "huge.raw";
  writeFile(path, "");
  const std::int64_t big = std::int64_t{1} << 31;
  expectError<InputError>(
      [&] {
        openRaw(path, {.dims = {big, big, big}, .type = SampleType::UInt8});
      },
      {path.string(), "dims", "overflow"});
  // The voxel count fits (2^62) but its byte size as float64 does not.
  const std::int64_t d = std::int64_t{1} << 21;
  expectError<InputError>(
      [&] {
        openRaw(path, {.dims = {d, d, d / 2}, .type = SampleType::Float64});
      },
      {path.string(), "dims", "byte size"});
}

TEST(RawReader, BadSpacingAndHeaderBytesAreRejected) {
  TempDir dir;
  const auto path = dir / "v.raw";
  writeFile(path, std::string(8, '\0'));
  expectError<InputError>(
      [&] {
        openRaw(path, {.dims = {2, 2, 2}, .type = SampleType::UInt8, .spacing = {1, 0, 1}});
      },
      {path.string(), "spacing"});
  expectError<InputError>(
      [&] {
        openRaw(path, {.dims = {2, 2, 2}, .type = SampleType::UInt8, .headerBytes = -1});
      },
      {path.string(), "header bytes"});
}

TEST(RawReader, NaNInFloat32GivesTheVoxel) {
  TempDir dir;
  std::vector<double> values = testValues(SampleType::Float32, 4 * 3 * 2);
  values[1 * 12 + 2 * 4 + 3] = std::numeric_limits<double>::quiet_NaN();  // voxel (3, 2, 1)
  const auto path = dir / "nan.raw";
  writeFile(path, encode(SampleType::Float32, false, values));
  auto stream = openRaw(path, {.dims = {4, 3, 2}, .type = SampleType::Float32});
  std::vector<float> slice(12);
  stream->readSlice(slice.data());  // slice 0 is fine
  expectError<InputError>([&] { stream->readSlice(slice.data()); }, {path.string(), "(3, 2, 1)", "NaN"});
}

TEST(RawReader, InfInFloat32GivesTheVoxel) {
  TempDir dir;
  std::vector<double> values = testValues(SampleType::Float32, 4 * 3 * 2);
  values[0 * 12 + 1 * 4 + 0] = -std::numeric_limits<double>::infinity();  // voxel (0, 1, 0)
  const auto path = dir / "inf.raw";
  writeFile(path, encode(SampleType::Float32, true, values));
  auto stream = openRaw(path, {.dims = {4, 3, 2}, .type = SampleType::Float32, .bigEndian = true});
  std::vector<float> slice(12);
  expectError<InputError>([&] { stream->readSlice(slice.data()); }, {path.string(), "(0, 1, 0)", "Inf"});
}

TEST(RawReader, Float64BeyondFloatRangeGivesTheVoxel) {
  TempDir dir;
  std::vector<double> values(8, 1.0);
  values[5] = 1e300;  // voxel (1, 0, 1)
  const auto path = dir / "big.raw";
  writeFile(path, encode(SampleType::Float64, false, values));
  auto stream = openRaw(path, {.dims = {2, 2, 2}, .type = SampleType::Float64});
  std::vector<float> slice(4);
  stream->readSlice(slice.data());
  expectError<InputError>([&] { stream->readSlice(slice.data()); }, {path.string(), "(1, 0, 1)", "float range"});
}

// --- ByteStream ---------------------------------------------------------------------

TEST(ByteStream, FileRegionReadsThroughASmallBuffer) {
  TempDir dir;
  std::string data;
  for (int i = 0; i < 1000; ++i) data.push_back(static_cast<char>(i * 7));
  writeFile(dir / "f.bin", data);
  FileRegionStream stream(dir / "f.bin", {.offset = 10, .length = 900, .bufferSize = 7});
  EXPECT_EQ(stream.remaining(), 900);
  std::string got(900, '\0');
  auto* out = reinterpret_cast<std::byte*>(got.data());
  stream.readExact(out, 3);
  stream.skip(5);
  stream.readExact(out + 8, 500);  // larger than the buffer: read directly
  stream.readExact(out + 508, 392);
  EXPECT_EQ(stream.remaining(), 0);
  EXPECT_EQ(got.substr(0, 3), data.substr(10, 3));
  EXPECT_EQ(got.substr(8), data.substr(18, 892));
  std::byte extra{};
  EXPECT_EQ(stream.read(&extra, 1), 0u);
}

TEST(ByteStream, FileRegionReportsShortData) {
  TempDir dir;
  const auto path = dir / "short.bin";
  writeFile(path, std::string(50, 'x'));
  FileRegionStream stream(path, {.offset = 20});
  std::vector<std::byte> out(40);
  expectError<InputError>([&] { stream.readExact(out.data(), 40, 40); },
                          {path.string(), "file ends after 30 of 40 bytes"});
  expectError<InputError>([&] { FileRegionStream(path, {.offset = 10, .length = 60}); },
                          {path.string(), "ends after 40 of 60"});
  expectError<IoError>([&] { FileRegionStream(dir / "nope.bin"); }, {"nope.bin", "no such file"});
}

TEST(ByteStream, ReadsLinesAndSkipsLines) {
  TempDir dir;
  writeFile(dir / "t.txt", "one\r\ntwo\nthree\nfour");
  FileRegionStream stream(dir / "t.txt");
  EXPECT_EQ(stream.readLine(), "one");
  stream.skipLines(1);
  EXPECT_EQ(stream.readLine(), "three");
  EXPECT_EQ(stream.readLine(), "four");
  EXPECT_EQ(stream.readLine(), std::nullopt);
}

TEST(ByteStream, InflatesZlibAndConcatenatedGzip) {
  TempDir dir;
  std::string data;
  for (int i = 0; i < 300000; ++i) data.push_back(static_cast<char>((i * 31) ^ (i >> 7)));
  // zlib
  uLongf size = compressBound(data.size());
  std::string zlib(size, '\0');
  ASSERT_EQ(
      compress(reinterpret_cast<Bytef*>(zlib.data()), &size, reinterpret_cast<const Bytef*>(data.data()), data.size()),
      Z_OK);
  zlib.resize(size);
  writeFile(dir / "d.z", zlib);
  // two gzip members
  writeFile(dir / "d.gz", gzipBytes(dir, data.substr(0, 1000)) + gzipBytes(dir, data.substr(1000)));
  for (const char* name : {"d.z", "d.gz"}) {
    SCOPED_TRACE(name);
    InflateStream stream(std::make_unique<FileRegionStream>(dir / name, FileRegionOptions{.bufferSize = 4096}), 333);
    std::string got(data.size(), '\0');
    stream.readExact(reinterpret_cast<std::byte*>(got.data()), got.size());
    EXPECT_EQ(got, data);
    EXPECT_NO_THROW(stream.finish(static_cast<std::int64_t>(data.size())));
  }
}

TEST(ByteStream, InflateDetectsTruncationAndCorruption) {
  TempDir dir;
  const std::string data(100000, 'a');
  const std::string gz = gzipBytes(dir, data);
  writeFile(dir / "cut.gz", gz.substr(0, gz.size() - 6));  // checksum cut off
  {
    InflateStream stream(std::make_unique<FileRegionStream>(dir / "cut.gz"));
    std::string got(data.size(), '\0');
    stream.readExact(reinterpret_cast<std::byte*>(got.data()), got.size());  // the data itself is all there
    expectError<InputError>([&] { stream.finish(100000); }, {"cut.gz", "truncated"});
  }
  std::string corrupt = gz;
  corrupt[10] = static_cast<char>(0xff);  // first deflate block: final, reserved type 3
  writeFile(dir / "bad.gz", corrupt);
  InflateStream stream(std::make_unique<FileRegionStream>(dir / "bad.gz"));
  std::string got(data.size(), '\0');
  expectError<InputError>([&] { stream.readExact(reinterpret_cast<std::byte*>(got.data()), got.size()); },
                          {"bad.gz", "corrupt compressed data"});
}

// --- DenseVolume ---------------------------------------------------------------------

TEST(DenseVolume, DispatchesByExtension) {
  TempDir dir;
  writeFile(dir / "v.raw", std::string(8, '\x02'));
  auto raw = openDenseVolume(dir / "v.raw", RawOptions{.dims = {2, 2, 2}, .type = SampleType::UInt8});
  EXPECT_EQ(readAll(*raw), std::vector<float>(8, 2.f));

  writeFile(dir / "v.NRRD",
            "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n\n" + std::string(8, '\x03'));
  auto nrrd = openDenseVolume(dir / "v.NRRD");
  EXPECT_EQ(readAll(*nrrd), std::vector<float>(8, 3.f));

  writeFile(dir / "v.mha",
            "NDims = 3\nDimSize = 2 2 2\nElementType = MET_UCHAR\nElementDataFile = LOCAL\n" + std::string(8, '\x04'));
  auto mha = openDenseVolume(dir / "v.mha");
  EXPECT_EQ(readAll(*mha), std::vector<float>(8, 4.f));

  EXPECT_TRUE(isDenseVolumePath("a/b.nhdr"));
  EXPECT_TRUE(isDenseVolumePath("b.MHD"));
  EXPECT_TRUE(isDenseVolumePath("b.raw"));
  EXPECT_FALSE(isDenseVolumePath("b.vdb"));
  EXPECT_FALSE(isDenseVolumePath("b.ply"));
}

TEST(DenseVolume, RawNeedsOptions) {
  TempDir dir;
  const auto path = dir / "x.raw";
  writeFile(path, std::string(8, '\0'));
  expectError<InputError>([&] { openDenseVolume(path); }, {path.string(), "raw volumes need --dims and --type"});
}

TEST(DenseVolume, MissingFileIsIoError) {
  TempDir dir;
  for (const char* name : {"gone.nrrd", "gone.mhd", "gone.raw"}) {
    const auto path = dir / name;
    expectError<IoError>([&] { openDenseVolume(path); }, {path.string(), "no such file"});
  }
}

}  // namespace
}  // namespace isovdb::io
