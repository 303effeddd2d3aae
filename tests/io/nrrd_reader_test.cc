// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/io/nrrd_reader.h: every sample type and byte order, attached
// and detached headers, raw and gzip encodings, and bad headers.
#include "isovdb/io/nrrd_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "io/reader_test_support.h"
#include "isovdb/errors.h"

namespace isovdb::io {
namespace {

using namespace test;  // TempDir, writeFile and the reader helpers of reader_test_support.h

/// A NRRD header (without the blank line) for a 3-D volume.
std::string nrrdHeader(const std::string& type, const std::string& sizes, const std::string& encoding,
                       const std::string& extra = {}) {
  return "NRRD0004\n# Complete NRRD file format specification at:\ntype: " + type + "\ndimension: 3\nsizes: " + sizes +
         "\nencoding: " + encoding + "\n" + extra;
}

std::string nrrdTypeName(SampleType type) {
  switch (type) {
    case SampleType::Int8:
      return "signed char";
    case SampleType::UInt8:
      return "uchar";
    case SampleType::Int16:
      return "short";
    case SampleType::UInt16:
      return "unsigned short";
    case SampleType::Int32:
      return "int";
    case SampleType::UInt32:
      return "uint";
    case SampleType::Float32:
      return "float";
    case SampleType::Float64:
      return "double";
  }
  return "";
}

// --- NrrdReader ---------------------------------------------------------------------

TEST(NrrdReader, ReadsEveryTypeInBothByteOrdersExactly) {
  TempDir dir;
  for (SampleType type : kAllTypes) {
    for (bool big : {false, true}) {
      SCOPED_TRACE(std::string(sampleTypeName(type)) + (big ? " big" : " little"));
      const std::vector<double> values = testValues(type, 60);
      const auto path = dir / "vol.nrrd";
      writeFile(path, nrrdHeader(nrrdTypeName(type), "5 4 3", "raw", big ? "endian: big\n" : "endian: little\n") +
                          "\n" + encode(type, big, values));
      auto stream = openNrrd(path);
      EXPECT_EQ(stream->header().dims, (std::array<std::int64_t, 3>{5, 4, 3}));
      EXPECT_EQ(stream->header().sampleType, type);
      const std::vector<float> read = readAll(*stream);
      for (std::size_t i = 0; i < values.size(); ++i)
        ASSERT_EQ(read[i], static_cast<float>(values[i])) << "sample " << i;
    }
  }
}

TEST(NrrdReader, ReadsDetachedRawWithGeometry) {
  TempDir dir;
  std::filesystem::create_directory(dir / "data");
  const std::vector<double> values = testValues(SampleType::Int16, 3 * 2 * 2);
  writeFile(dir / "data" / "vol.raw", encode(SampleType::Int16, true, values));
  writeFile(dir / "vol.nhdr", nrrdHeader("int16", "3 2 2", "raw",
                                         "endian: big\nspace: right-anterior-superior\n"
                                         "space directions: (0.5,0,0) (0, 2, 0) (0,0,1.25)\n"
                                         "space origin: (10,-20,30.5)\nkinds: domain domain domain\n"
                                         "my key:=some value: with colon\n"
                                         "data file: data/vol.raw\n"));
  auto stream = openNrrd(dir / "vol.nhdr");
  EXPECT_EQ(stream->header().spacing, (std::array<double, 3>{0.5, 2.0, 1.25}));
  EXPECT_EQ(stream->header().origin, (std::array<double, 3>{10.0, -20.0, 30.5}));
  EXPECT_TRUE(stream->header().bigEndian);
  EXPECT_EQ(stream->source(), (dir / "vol.nhdr").string());
  const std::vector<float> read = readAll(*stream);
  for (std::size_t i = 0; i < values.size(); ++i) EXPECT_EQ(read[i], static_cast<float>(values[i]));
}

TEST(NrrdReader, ReadsSpacingsLineSkipAndByteSkip) {
  TempDir dir;
  const std::vector<double> values = testValues(SampleType::UInt8, 8);
  writeFile(dir / "d.raw", "junk line\nanother\n" + std::string(5, 'B') + encode(SampleType::UInt8, false, values));
  writeFile(dir / "v.nhdr",
            nrrdHeader("uint8", "2 2 2", "raw", "spacings: 1 2 3\nline skip: 2\nbyte skip: 5\ndata file: d.raw\n"));
  auto stream = openNrrd(dir / "v.nhdr");
  EXPECT_EQ(stream->header().spacing, (std::array<double, 3>{1.0, 2.0, 3.0}));
  const std::vector<float> read = readAll(*stream);
  for (std::size_t i = 0; i < values.size(); ++i) EXPECT_EQ(read[i], static_cast<float>(values[i]));
  // byte skip -1: the data is at the end of the file.
  writeFile(dir / "w.nhdr", nrrdHeader("uint8", "2 2 2", "raw", "byte skip: -1\ndata file: d.raw\n"));
  auto tail = openNrrd(dir / "w.nhdr");
  const std::vector<float> readTail = readAll(*tail);
  for (std::size_t i = 0; i < values.size(); ++i) EXPECT_EQ(readTail[i], static_cast<float>(values[i]));
}

TEST(NrrdReader, ReadsAttachedGzip) {
  TempDir dir;
  const std::vector<double> values = testValues(SampleType::Float32, 6 * 5 * 4);
  writeFile(dir / "g.nrrd", nrrdHeader("float", "6 5 4", "gzip", "endian: little\n") + "\n" +
                                gzipBytes(dir, encode(SampleType::Float32, false, values)));
  auto stream = openNrrd(dir / "g.nrrd");
  const std::vector<float> read = readAll(*stream);
  for (std::size_t i = 0; i < values.size(); ++i) EXPECT_EQ(read[i], static_cast<float>(values[i]));
}

TEST(NrrdReader, ReadsDetachedGzipWithByteSkip) {
  TempDir dir;
  const std::vector<double> values = testValues(SampleType::UInt32, 4 * 4 * 4);
  writeFile(dir / "d.raw.gz", gzipBytes(dir, std::string(7, 'S') + encode(SampleType::UInt32, true, values)));
  writeFile(dir / "d.nhdr", nrrdHeader("uint32", "4 4 4", "gz", "endian: big\nbyte skip: 7\ndata file: d.raw.gz\n"));
  auto stream = openNrrd(dir / "d.nhdr");
  const std::vector<float> read = readAll(*stream);
  for (std::size_t i = 0; i < values.size(); ++i) EXPECT_EQ(read[i], static_cast<float>(values[i]));
}

TEST(NrrdReader, ReadsBzip2AttachedDetachedAndConcatenated) {
  TempDir dir;
  // 40 x 40 x 40 int16: 128 kB, more than one 100 kB bzip2 block.
  const std::vector<double> values = testValues(SampleType::Int16, 40 * 40 * 40);
  const std::string raw = encode(SampleType::Int16, false, values);
  writeFile(dir / "b.nrrd", nrrdHeader("int16", "40 40 40", "bzip2", "endian: little\n") + "\n" + bzip2Bytes(raw));
  auto attached = openNrrd(dir / "b.nrrd");
  const std::vector<float> read = readAll(*attached);
  for (std::size_t i = 0; i < values.size(); ++i) ASSERT_EQ(read[i], static_cast<float>(values[i])) << i;
  // Detached, with a byte skip counted in decompressed bytes, the data split over two
  // concatenated bzip2 streams (as pbzip2 writes them).
  const std::string skipped = std::string(5, 'S') + raw;
  writeFile(dir / "d.raw.bz2", bzip2Bytes(skipped.substr(0, 1000)) + bzip2Bytes(skipped.substr(1000)));
  writeFile(dir / "d.nhdr",
            nrrdHeader("int16", "40 40 40", "bz2", "endian: little\nbyte skip: 5\ndata file: d.raw.bz2\n"));
  auto detached = openNrrd(dir / "d.nhdr");
  const std::vector<float> readDetached = readAll(*detached);
  for (std::size_t i = 0; i < values.size(); ++i) ASSERT_EQ(readDetached[i], static_cast<float>(values[i])) << i;
}

TEST(NrrdReader, PynrrdsBzip2AndGzipBallsHoldTheSameSamples) {
  // Written by another implementation (data/nrrd/PROVENANCE.md): a binary ball, int16 0 outside
  // and 257 inside (both bytes set).
  const std::filesystem::path nrrd = std::filesystem::path(ISOVDB_DATA_DIR) / "nrrd";
  auto bz2 = openNrrd(nrrd / "BallBinary30x30x30_bz2.nrrd");
  auto gz = openNrrd(nrrd / "BallBinary30x30x30_gz.nrrd");
  const std::vector<float> fromBz2 = readAll(*bz2), fromGz = readAll(*gz);
  ASSERT_EQ(fromBz2.size(), 27000u);
  EXPECT_EQ(fromBz2, fromGz);
  EXPECT_EQ(std::count(fromBz2.begin(), fromBz2.end(), 257.0f), 14328);
  EXPECT_EQ(std::count(fromBz2.begin(), fromBz2.end(), 0.0f), 27000 - 14328);
}

TEST(NrrdReader, DamagedBzip2IsRejectedNamingTheFile) {
  TempDir dir;
  const std::vector<double> values = testValues(SampleType::Int16, 32 * 32 * 8);
  const std::string bz = bzip2Bytes(encode(SampleType::Int16, false, values));
  std::vector<float> slice(32 * 32);
  const auto readEverySlice = [&](const std::string& name) {
    auto stream = openNrrd(dir / name);
    for (int z = 0; z < 8; ++z) stream->readSlice(slice.data());
  };
  writeFile(dir / "t.nrrd",
            nrrdHeader("int16", "32 32 8", "bzip2", "endian: little\n") + "\n" + bz.substr(0, bz.size() / 2));
  expectError<InputError>([&] { readEverySlice("t.nrrd"); }, {"t.nrrd", "truncated"});
  std::string flipped = bz;
  flipped[flipped.size() / 2] = static_cast<char>(flipped[flipped.size() / 2] ^ 0x5a);
  writeFile(dir / "c.nrrd", nrrdHeader("int16", "32 32 8", "bzip2", "endian: little\n") + "\n" + flipped);
  expectError<InputError>([&] { readEverySlice("c.nrrd"); }, {"c.nrrd", "corrupt compressed data"});
  writeFile(dir / "n.nrrd", nrrdHeader("int16", "32 32 8", "bzip2", "endian: little\n") + "\nnot bzip2 at all");
  expectError<InputError>([&] { readEverySlice("n.nrrd"); }, {"n.nrrd", "not bzip2 data"});
  writeFile(dir / "l.nrrd", nrrdHeader("uint8", "2 2 2", "bzip2") + "\n" + bzip2Bytes(std::string(9, '\1')));
  expectError<InputError>(
      [&] {
        auto stream = openNrrd(dir / "l.nrrd");
        std::vector<float> small(4);
        stream->readSlice(small.data());
        stream->readSlice(small.data());
      },
      {"l.nrrd", "longer than the 8 bytes"});
}

TEST(NrrdReader, MissingFileIsIoError) {
  TempDir dir;
  expectError<IoError>([&] { openNrrd(dir / "none.nrrd"); }, {"none.nrrd", "no such file"});
  writeFile(dir / "v.nhdr", nrrdHeader("uint8", "2 2 2", "raw", "data file: missing.raw\n"));
  expectError<IoError>([&] { openNrrd(dir / "v.nhdr"); }, {"v.nhdr", "missing.raw", "no such file"});
}

TEST(NrrdReader, RejectsAFileWithoutMagic) {
  TempDir dir;
  writeFile(dir / "v.nrrd", "NRRD0009\ntype: uint8\n");
  expectError<InputError>([&] { openNrrd(dir / "v.nrrd"); }, {"v.nrrd", "not a NRRD file"});
}

TEST(NrrdReader, MissingSizesIsRejected) {
  TempDir dir;
  writeFile(dir / "v.nrrd", "NRRD0004\ntype: uint8\ndimension: 3\nencoding: raw\n\n" + std::string(8, '\0'));
  expectError<InputError>([&] { openNrrd(dir / "v.nrrd"); }, {"v.nrrd", "'sizes'", "missing"});
}

TEST(NrrdReader, MissingTypeIsRejected) {
  TempDir dir;
  writeFile(dir / "v.nrrd", "NRRD0004\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n\n" + std::string(8, '\0'));
  expectError<InputError>([&] { openNrrd(dir / "v.nrrd"); }, {"v.nrrd", "'type'", "missing"});
}

TEST(NrrdReader, MissingEndianForUInt16IsRejected) {
  TempDir dir;
  writeFile(dir / "v.nrrd", nrrdHeader("uint16", "2 2 2", "raw") + "\n" + std::string(16, '\0'));
  expectError<InputError>([&] { openNrrd(dir / "v.nrrd"); }, {"v.nrrd", "'endian'", "missing", "uint16"});
}

TEST(NrrdReader, TwoSizesForThreeDimensionsIsRejected) {
  TempDir dir;
  writeFile(dir / "v.nrrd", nrrdHeader("uint8", "4 4", "raw") + "\n" + std::string(16, '\0'));
  expectError<InputError>([&] { openNrrd(dir / "v.nrrd"); }, {"v.nrrd", "'sizes'", "dimension is 3", "2 values"});
}

TEST(NrrdReader, DimensionOtherThanThreeIsRejected) {
  TempDir dir;
  writeFile(dir / "v.nrrd",
            "NRRD0004\ntype: uint8\ndimension: 2\nsizes: 4 4\nencoding: raw\n\n" + std::string(16, '\0'));
  expectError<InputError>([&] { openNrrd(dir / "v.nrrd"); }, {"v.nrrd", "'dimension'", "3-D"});
}

TEST(NrrdReader, UnknownTypeIsRejected) {
  TempDir dir;
  writeFile(dir / "v.nrrd", nrrdHeader("complex64", "2 2 2", "raw", "endian: little\n") + "\n" + std::string(64, '\0'));
  expectError<InputError>([&] { openNrrd(dir / "v.nrrd"); }, {"v.nrrd", "'type'", "complex64"});
}

TEST(NrrdReader, UnsupportedEncodingIsRejected) {
  TempDir dir;
  writeFile(dir / "v.nrrd", nrrdHeader("uint8", "2 2 2", "ascii") + "\n1 2 3 4 5 6 7 8\n");
  expectError<InputError>([&] { openNrrd(dir / "v.nrrd"); }, {"v.nrrd", "'encoding'", "unsupported encoding 'ascii'"});
}

TEST(NrrdReader, BadDimsAreRejected) {
  TempDir dir;
  writeFile(dir / "v.nrrd", nrrdHeader("uint8", "2 0 2", "raw") + "\n");
  expectError<InputError>([&] { openNrrd(dir / "v.nrrd"); }, {"v.nrrd", "'sizes'", "positive", "got 0"});
  writeFile(dir / "w.nrrd", nrrdHeader("uint8", "2 2 -5", "raw") + "\n");
  expectError<InputError>([&] { openNrrd(dir / "w.nrrd"); }, {"w.nrrd", "'sizes'", "-5"});
  writeFile(dir / "x.nrrd", nrrdHeader("uint8", "4000000000 4000000000 4000000000", "raw") + "\n");
  expectError<InputError>([&] { openNrrd(dir / "x.nrrd"); }, {"x.nrrd", "'sizes'", "overflow"});
}

TEST(NrrdReader, NonDiagonalSpaceDirectionsAreRejected) {
  TempDir dir;
  writeFile(dir / "v.nrrd", nrrdHeader("uint8", "2 2 2", "raw", "space directions: (0,1,0) (1,0,0) (0,0,1)\n") + "\n" +
                                std::string(8, '\0'));
  expectError<InputError>([&] { openNrrd(dir / "v.nrrd"); }, {"v.nrrd", "'space directions'", "axis-aligned"});
}

TEST(NrrdReader, SpaceDirectionCountMismatchIsRejected) {
  TempDir dir;
  writeFile(dir / "v.nrrd",
            nrrdHeader("uint8", "2 2 2", "raw", "space directions: (1,0,0) (0,1,0)\n") + "\n" + std::string(8, '\0'));
  expectError<InputError>([&] { openNrrd(dir / "v.nrrd"); }, {"v.nrrd", "'space directions'", "2 vectors"});
}

TEST(NrrdReader, SpacingsWithSpaceDirectionsAreContradictory) {
  TempDir dir;
  writeFile(dir / "v.nrrd",
            nrrdHeader("uint8", "2 2 2", "raw", "spacings: 1 1 1\nspace directions: (1,0,0) (0,1,0) (0,0,1)\n") + "\n" +
                std::string(8, '\0'));
  expectError<InputError>([&] { openNrrd(dir / "v.nrrd"); }, {"v.nrrd", "'spacings'", "contradicts"});
}

TEST(NrrdReader, RawDataSizeMustMatchSizes) {
  TempDir dir;
  writeFile(dir / "v.nrrd", nrrdHeader("uint16", "4 4 4", "raw", "endian: little\n") + "\n" + std::string(100, '\0'));
  expectError<InputError>([&] { openNrrd(dir / "v.nrrd"); }, {"v.nrrd", "'sizes'", "128", "100"});
  writeFile(dir / "d.raw", std::string(200, '\0'));
  writeFile(dir / "d.nhdr", nrrdHeader("uint16", "4 4 4", "raw", "endian: little\ndata file: d.raw\n"));
  expectError<InputError>([&] { openNrrd(dir / "d.nhdr"); }, {"d.nhdr", "d.raw", "128", "200"});
}

TEST(NrrdReader, TruncatedGzipIsRejected) {
  TempDir dir;
  const std::vector<double> values = testValues(SampleType::Int16, 32 * 32 * 8);
  const std::string gz = gzipBytes(dir, encode(SampleType::Int16, false, values));
  writeFile(dir / "t.nrrd",
            nrrdHeader("int16", "32 32 8", "gzip", "endian: little\n") + "\n" + gz.substr(0, gz.size() / 2));
  auto stream = openNrrd(dir / "t.nrrd");
  std::vector<float> slice(32 * 32);
  expectError<InputError>(
      [&] {
        for (int z = 0; z < 8; ++z) stream->readSlice(slice.data());
      },
      {"t.nrrd", "truncated"});
}

TEST(NrrdReader, GzipWithTooMuchDataIsRejected) {
  TempDir dir;
  writeFile(dir / "t.nrrd", nrrdHeader("uint8", "2 2 2", "gzip") + "\n" + gzipBytes(dir, std::string(9, '\1')));
  auto stream = openNrrd(dir / "t.nrrd");
  std::vector<float> slice(4);
  stream->readSlice(slice.data());
  expectError<InputError>([&] { stream->readSlice(slice.data()); }, {"t.nrrd", "longer than the 8 bytes"});
}

TEST(NrrdReader, NaNAndInfGiveTheVoxel) {
  TempDir dir;
  std::vector<double> values = testValues(SampleType::Float32, 3 * 3 * 3);
  values[2 * 9 + 1 * 3 + 2] = std::numeric_limits<double>::infinity();  // voxel (2, 1, 2)
  writeFile(dir / "inf.nrrd", nrrdHeader("float", "3 3 3", "raw", "endian: little\n") + "\n" +
                                  encode(SampleType::Float32, false, values));
  auto stream = openNrrd(dir / "inf.nrrd");
  std::vector<float> slice(9);
  expectError<InputError>(
      [&] {
        for (int z = 0; z < 3; ++z) stream->readSlice(slice.data());
      },
      {"inf.nrrd", "(2, 1, 2)", "+Inf"});
  values[2 * 9 + 1 * 3 + 2] = 0;
  values[0 * 9 + 2 * 3 + 1] = std::numeric_limits<double>::quiet_NaN();  // voxel (1, 2, 0)
  writeFile(dir / "nan.nrrd", nrrdHeader("float", "3 3 3", "gzip", "endian: big\n") + "\n" +
                                  gzipBytes(dir, encode(SampleType::Float32, true, values)));
  auto gz = openNrrd(dir / "nan.nrrd");
  expectError<InputError>([&] { gz->readSlice(slice.data()); }, {"nan.nrrd", "(1, 2, 0)", "NaN"});
}

}  // namespace
}  // namespace isovdb::io
