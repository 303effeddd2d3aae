// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/io/metaimage_reader.h: every sample type and byte order,
// .mhd/.mha, raw and zlib data, the real frog tissue volume, and bad headers.
#include "isovdb/io/metaimage_reader.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "io/reader_test_support.h"
#include "isovdb/errors.h"

namespace isovdb::io {
namespace {

using namespace test;  // TempDir, writeFile and the reader helpers of reader_test_support.h

std::string metTypeName(SampleType type) {
  switch (type) {
    case SampleType::Int8:
      return "MET_CHAR";
    case SampleType::UInt8:
      return "MET_UCHAR";
    case SampleType::Int16:
      return "MET_SHORT";
    case SampleType::UInt16:
      return "MET_USHORT";
    case SampleType::Int32:
      return "MET_INT";
    case SampleType::UInt32:
      return "MET_UINT";
    case SampleType::Float32:
      return "MET_FLOAT";
    case SampleType::Float64:
      return "MET_DOUBLE";
  }
  return "";
}

/// A MetaImage header; `extra` lines go before ElementDataFile, which comes last.
std::string metaHeader(const std::string& type, const std::string& dims, const std::string& dataFile,
                       const std::string& extra = {}) {
  return "ObjectType = Image\nNDims = 3\nBinaryData = True\nDimSize = " + dims + "\nElementType = " + type + "\n" +
         extra + "ElementDataFile = " + dataFile + "\n";
}

std::string zlibBytes(const std::string& data) {
  uLongf size = compressBound(data.size());
  std::string out(size, '\0');
  EXPECT_EQ(
      compress(reinterpret_cast<Bytef*>(out.data()), &size, reinterpret_cast<const Bytef*>(data.data()), data.size()),
      Z_OK);
  out.resize(size);
  return out;
}

// --- MetaImageReader ------------------------------------------------------------------

TEST(MetaImageReader, ReadsEveryTypeInBothByteOrdersExactly) {
  TempDir dir;
  for (SampleType type : kAllTypes) {
    for (bool big : {false, true}) {
      SCOPED_TRACE(std::string(sampleTypeName(type)) + (big ? " big" : " little"));
      const std::vector<double> values = testValues(type, 60);
      const auto path = dir / "vol.mha";
      writeFile(path, metaHeader(metTypeName(type), "5 4 3", "LOCAL",
                                 big ? "BinaryDataByteOrderMSB = True\n" : "ElementByteOrderMSB = False\n") +
                          encode(type, big, values));
      auto stream = openMetaImage(path);
      EXPECT_EQ(stream->header().dims, (std::array<std::int64_t, 3>{5, 4, 3}));
      EXPECT_EQ(stream->header().sampleType, type);
      EXPECT_EQ(stream->header().bigEndian, big);
      const std::vector<float> read = readAll(*stream);
      for (std::size_t i = 0; i < values.size(); ++i)
        ASSERT_EQ(read[i], static_cast<float>(values[i])) << "sample " << i;
    }
  }
}

TEST(MetaImageReader, ReadsDetachedRawWithGeometry) {
  TempDir dir;
  std::filesystem::create_directory(dir / "sub");
  const std::vector<double> values = testValues(SampleType::Int16, 3 * 2 * 2);
  writeFile(dir / "sub" / "vol.raw", encode(SampleType::Int16, false, values));
  writeFile(dir / "vol.mhd", metaHeader("MET_SHORT", "3 2 2", "sub/vol.raw",
                                        "TransformMatrix = 1 0 0 0 1 0 0 0 1\nOffset = 1.5 -2 3\n"
                                        "CenterOfRotation = 0 0 0\nElementSpacing = 0.5 0.25 2\n"
                                        "AnatomicalOrientation = RAI\n"));
  auto stream = openMetaImage(dir / "vol.mhd");
  EXPECT_EQ(stream->header().spacing, (std::array<double, 3>{0.5, 0.25, 2.0}));
  EXPECT_EQ(stream->header().origin, (std::array<double, 3>{1.5, -2.0, 3.0}));
  EXPECT_FALSE(stream->header().bigEndian);
  const std::vector<float> read = readAll(*stream);
  for (std::size_t i = 0; i < values.size(); ++i) EXPECT_EQ(read[i], static_cast<float>(values[i]));
}

TEST(MetaImageReader, ReadsZlibDetachedAndLocal) {
  TempDir dir;
  const std::vector<double> values = testValues(SampleType::UInt16, 8 * 7 * 6);
  const std::string z = zlibBytes(encode(SampleType::UInt16, true, values));
  writeFile(dir / "c.zraw", z);
  writeFile(dir / "c.mhd", metaHeader("MET_USHORT", "8 7 6", "c.zraw",
                                      "BinaryDataByteOrderMSB = True\nCompressedData = True\nCompressedDataSize = " +
                                          std::to_string(z.size()) + "\nElementSize = 2 2 2\n"));
  auto detached = openMetaImage(dir / "c.mhd");
  EXPECT_EQ(detached->header().spacing, (std::array<double, 3>{2.0, 2.0, 2.0}));
  std::vector<float> read = readAll(*detached);
  for (std::size_t i = 0; i < values.size(); ++i) ASSERT_EQ(read[i], static_cast<float>(values[i]));

  writeFile(dir / "c.mha",
            metaHeader("MET_USHORT", "8 7 6", "LOCAL", "ElementByteOrderMSB = True\nCompressedData = True\n") + z);
  auto local = openMetaImage(dir / "c.mha");
  read = readAll(*local);
  for (std::size_t i = 0; i < values.size(); ++i) ASSERT_EQ(read[i], static_cast<float>(values[i]));
}

TEST(MetaImageReader, HonoursHeaderSize) {
  TempDir dir;
  const std::vector<double> values = testValues(SampleType::UInt8, 27);
  writeFile(dir / "d.raw", std::string(11, 'h') + encode(SampleType::UInt8, false, values));
  writeFile(dir / "a.mhd", metaHeader("MET_UCHAR", "3 3 3", "d.raw", "HeaderSize = 11\n"));
  writeFile(dir / "b.mhd", metaHeader("MET_UCHAR", "3 3 3", "d.raw", "HeaderSize = -1\n"));
  for (const char* name : {"a.mhd", "b.mhd"}) {
    SCOPED_TRACE(name);
    auto stream = openMetaImage(dir / name);
    const std::vector<float> read = readAll(*stream);
    for (std::size_t i = 0; i < values.size(); ++i) EXPECT_EQ(read[i], static_cast<float>(values[i]));
  }
}

TEST(MetaImageReader, ReadsTheFrogTissueVolume) {
  const auto path = test::sharedDataDir() / "binary" / "frog_tissue" / "frogtissue.mhd";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is absent";
  auto stream = openMetaImage(path);
  const VolumeHeader& header = stream->header();
  EXPECT_EQ(header.dims, (std::array<std::int64_t, 3>{500, 470, 136}));
  EXPECT_EQ(header.sampleType, SampleType::UInt8);
  EXPECT_EQ(header.spacing, (std::array<double, 3>{1.0, 1.0, 1.5}));
  EXPECT_EQ(header.origin, (std::array<double, 3>{0.0, 0.0, 0.0}));
  std::vector<float> slice(static_cast<std::size_t>(header.sliceSamples()));
  std::int64_t skeleton = 0;
  for (std::int64_t z = 0; z < header.dims[2]; ++z) {
    stream->readSlice(slice.data());
    skeleton += std::count(slice.begin(), slice.end(), 13.f);
  }
  EXPECT_EQ(skeleton, 440722);
  EXPECT_EQ(stream->nextSlice(), 136);
}

TEST(MetaImageReader, MissingFileIsIoError) {
  TempDir dir;
  expectError<IoError>([&] { openMetaImage(dir / "none.mha"); }, {"none.mha", "no such file"});
  writeFile(dir / "v.mhd", metaHeader("MET_UCHAR", "2 2 2", "gone.raw"));
  expectError<IoError>([&] { openMetaImage(dir / "v.mhd"); }, {"v.mhd", "gone.raw", "no such file"});
}

TEST(MetaImageReader, NDimsOtherThanThreeIsRejected) {
  TempDir dir;
  writeFile(dir / "v.mha",
            "NDims = 2\nDimSize = 4 4\nElementType = MET_UCHAR\nElementDataFile = LOCAL\n" + std::string(16, '\0'));
  expectError<InputError>([&] { openMetaImage(dir / "v.mha"); }, {"v.mha", "'NDims'", "3-D"});
}

TEST(MetaImageReader, MissingDimSizeIsRejected) {
  TempDir dir;
  writeFile(dir / "v.mha", "NDims = 3\nElementType = MET_UCHAR\nElementDataFile = LOCAL\n" + std::string(8, '\0'));
  expectError<InputError>([&] { openMetaImage(dir / "v.mha"); }, {"v.mha", "'DimSize'", "missing"});
}

TEST(MetaImageReader, MissingElementTypeIsRejected) {
  TempDir dir;
  writeFile(dir / "v.mha", "NDims = 3\nDimSize = 2 2 2\nElementDataFile = LOCAL\n" + std::string(8, '\0'));
  expectError<InputError>([&] { openMetaImage(dir / "v.mha"); }, {"v.mha", "'ElementType'", "missing"});
}

TEST(MetaImageReader, DimSizeWithTwoValuesIsRejected) {
  TempDir dir;
  writeFile(dir / "v.mha", metaHeader("MET_UCHAR", "4 4", "LOCAL") + std::string(16, '\0'));
  expectError<InputError>([&] { openMetaImage(dir / "v.mha"); }, {"v.mha", "'DimSize'", "2 values"});
}

TEST(MetaImageReader, BadDimSizesAreRejected) {
  TempDir dir;
  writeFile(dir / "z.mha", metaHeader("MET_UCHAR", "0 2 2", "LOCAL"));
  expectError<InputError>([&] { openMetaImage(dir / "z.mha"); }, {"z.mha", "'DimSize'", "got 0"});
  writeFile(dir / "n.mha", metaHeader("MET_UCHAR", "2 -2 2", "LOCAL"));
  expectError<InputError>([&] { openMetaImage(dir / "n.mha"); }, {"n.mha", "'DimSize'", "-2"});
  writeFile(dir / "o.mha", metaHeader("MET_DOUBLE", "3000000 3000000 3000000", "LOCAL"));
  expectError<InputError>([&] { openMetaImage(dir / "o.mha"); }, {"o.mha", "'DimSize'", "overflow"});
}

TEST(MetaImageReader, UnknownElementTypeIsRejected) {
  TempDir dir;
  writeFile(dir / "v.mha", metaHeader("MET_COMPLEX", "2 2 2", "LOCAL") + std::string(64, '\0'));
  expectError<InputError>([&] { openMetaImage(dir / "v.mha"); }, {"v.mha", "'ElementType'", "MET_COMPLEX"});
}

TEST(MetaImageReader, RotatedTransformIsRejected) {
  TempDir dir;
  writeFile(dir / "v.mha",
            metaHeader("MET_UCHAR", "2 2 2", "LOCAL", "TransformMatrix = 0 1 0 1 0 0 0 0 1\n") + std::string(8, '\0'));
  expectError<InputError>([&] { openMetaImage(dir / "v.mha"); }, {"v.mha", "'TransformMatrix'", "identity"});
}

TEST(MetaImageReader, RawDataSizeMustMatchDimSize) {
  TempDir dir;
  writeFile(dir / "v.mha", metaHeader("MET_SHORT", "4 4 4", "LOCAL") + std::string(100, '\0'));
  expectError<InputError>([&] { openMetaImage(dir / "v.mha"); }, {"v.mha", "'DimSize'", "128", "100"});
}

TEST(MetaImageReader, TruncatedZlibIsRejected) {
  TempDir dir;
  const std::vector<double> values = testValues(SampleType::Float32, 32 * 32 * 8);
  const std::string z = zlibBytes(encode(SampleType::Float32, false, values));
  writeFile(dir / "t.zraw", z.substr(0, z.size() / 3));
  writeFile(dir / "t.mhd", metaHeader("MET_FLOAT", "32 32 8", "t.zraw", "CompressedData = True\n"));
  auto stream = openMetaImage(dir / "t.mhd");
  std::vector<float> slice(32 * 32);
  expectError<InputError>(
      [&] {
        for (int z = 0; z < 8; ++z) stream->readSlice(slice.data());
      },
      {"t.zraw", "t.mhd", "truncated"});
}

TEST(MetaImageReader, NaNAndInfGiveTheVoxel) {
  TempDir dir;
  std::vector<double> values = testValues(SampleType::Float32, 4 * 2 * 2);
  values[1 * 8 + 1 * 4 + 3] = std::numeric_limits<double>::quiet_NaN();  // voxel (3, 1, 1)
  writeFile(dir / "nan.mha", metaHeader("MET_FLOAT", "4 2 2", "LOCAL", "CompressedData = True\n") +
                                 zlibBytes(encode(SampleType::Float32, false, values)));
  auto stream = openMetaImage(dir / "nan.mha");
  std::vector<float> slice(8);
  stream->readSlice(slice.data());
  expectError<InputError>([&] { stream->readSlice(slice.data()); }, {"nan.mha", "(3, 1, 1)", "NaN"});

  values[1 * 8 + 1 * 4 + 3] = 0;
  values[0 * 8 + 0 * 4 + 2] = -std::numeric_limits<double>::infinity();  // voxel (2, 0, 0)
  writeFile(dir / "inf.mha", metaHeader("MET_FLOAT", "4 2 2", "LOCAL") + encode(SampleType::Float32, false, values));
  auto raw = openMetaImage(dir / "inf.mha");
  expectError<InputError>([&] { raw->readSlice(slice.data()); }, {"inf.mha", "(2, 0, 0)", "-Inf"});
}

TEST(MetaImageReader, NotAMetaImageHeaderIsRejected) {
  TempDir dir;
  writeFile(dir / "v.mha", std::string("\x89PNG\r\n\x1a\n", 8) + std::string(100, '\0'));
  expectError<InputError>([&] { openMetaImage(dir / "v.mha"); }, {"v.mha", "not a MetaImage header"});
}

TEST(MetaImageReader, AcceptsGzipHeaderedCompressedData) {
  TempDir dir;
  const std::vector<double> values = testValues(SampleType::Int32, 3 * 3 * 3);
  writeFile(dir / "g.mha", metaHeader("MET_INT", "3 3 3", "LOCAL", "CompressedData = True\n") +
                               gzipBytes(dir, encode(SampleType::Int32, false, values)));
  auto stream = openMetaImage(dir / "g.mha");
  const std::vector<float> read = readAll(*stream);
  for (std::size_t i = 0; i < values.size(); ++i) EXPECT_EQ(read[i], static_cast<float>(values[i]));
}

}  // namespace
}  // namespace isovdb::io
