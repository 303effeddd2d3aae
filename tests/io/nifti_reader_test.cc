// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/io/nifti_reader.h: NIfTI-1 files written here field by field, both
// byte orders, raw and gzip, the transforms (pixdim, sform, qform), scaling, and bad
// headers; and pynrrd's ball written by ITK (data/nifti).
#include "isovdb/io/nifti_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "io/reader_test_support.h"
#include "isovdb/errors.h"
#include "isovdb/io/dense_volume.h"

namespace isovdb::io {
namespace {

using test::encode;
using test::expectError;
using test::readAll;
using test::TempDir;
using test::writeFile;

/// The fields of a NIfTI-1 header this test sets; the rest stay 0.
struct NiftiFields {
  std::array<std::int16_t, 8> dim{3, 4, 3, 2, 1, 1, 1, 1};
  std::int16_t datatype = 2;  // uint8
  std::int16_t bitpix = 8;
  std::array<float, 8> pixdim{1, 1, 1, 1, 0, 0, 0, 0};
  float voxOffset = 352;
  float slope = 0, intercept = 0;
  std::int16_t qformCode = 0, sformCode = 0;
  std::array<float, 3> quatern{0, 0, 0};
  std::array<float, 3> qoffset{0, 0, 0};
  std::array<std::array<float, 4>, 3> srow{};
  std::int32_t sizeofHdr = 348;
  std::string magic = std::string("n+1\0", 4);
  bool bigEndian = false;
};

template <typename T>
void put(std::string& bytes, std::size_t offset, T value, bool bigEndian) {
  std::array<char, sizeof(T)> raw;
  std::memcpy(raw.data(), &value, sizeof(T));
  if (bigEndian) std::reverse(raw.begin(), raw.end());
  std::memcpy(bytes.data() + offset, raw.data(), sizeof(T));
}

/// Header, 4 bytes of extension flag (zero) and `data`.
std::string niftiBytes(const NiftiFields& f, const std::string& data) {
  std::string bytes(352, '\0');
  const bool be = f.bigEndian;
  put(bytes, 0, f.sizeofHdr, be);
  for (std::size_t i = 0; i < 8; ++i) put(bytes, 40 + 2 * i, f.dim[i], be);
  put(bytes, 70, f.datatype, be);
  put(bytes, 72, f.bitpix, be);
  for (std::size_t i = 0; i < 8; ++i) put(bytes, 76 + 4 * i, f.pixdim[i], be);
  put(bytes, 108, f.voxOffset, be);
  put(bytes, 112, f.slope, be);
  put(bytes, 116, f.intercept, be);
  put(bytes, 252, f.qformCode, be);
  put(bytes, 254, f.sformCode, be);
  for (std::size_t i = 0; i < 3; ++i) put(bytes, 256 + 4 * i, f.quatern[i], be);
  for (std::size_t i = 0; i < 3; ++i) put(bytes, 268 + 4 * i, f.qoffset[i], be);
  for (std::size_t r = 0; r < 3; ++r)
    for (std::size_t c = 0; c < 4; ++c) put(bytes, 280 + 16 * r + 4 * c, f.srow[r][c], be);
  std::memcpy(bytes.data() + 344, f.magic.data(), 4);
  return bytes + data;
}

/// Values 0..n-1 of a 4 x 3 x 2 volume: sample (x, y, z) holds x + 4 y + 12 z.
std::vector<double> ramp() {
  std::vector<double> v(24);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<double>(i);
  return v;
}

TEST(NiftiReader, ReadsLittleEndianRawWithPixdimSpacing) {
  TempDir dir;
  NiftiFields f;
  f.pixdim = {1, 2, 3, 4, 0, 0, 0, 0};
  writeFile(dir / "a.nii", niftiBytes(f, encode(SampleType::UInt8, false, ramp())));
  auto stream = openDenseVolume(dir / "a.nii", std::nullopt);  // dispatched by its name
  EXPECT_EQ(stream->header().dims, (std::array<std::int64_t, 3>{4, 3, 2}));
  EXPECT_EQ(stream->header().spacing, (std::array<double, 3>{2, 3, 4}));
  EXPECT_EQ(stream->header().origin, (std::array<double, 3>{0, 0, 0}));
  const std::vector<float> read = readAll(*stream);
  for (std::size_t i = 0; i < read.size(); ++i) EXPECT_EQ(read[i], static_cast<float>(i));
}

TEST(NiftiReader, SformWithXAndYFlippedIsReadReversedWithPositiveSteps) {
  // ITK's LPS images in NIfTI's RAS space: srow diag(-1, -1, 2), here big-endian int16, gzip.
  TempDir dir;
  NiftiFields f;
  f.bigEndian = true;
  f.datatype = 4;
  f.bitpix = 16;
  f.sformCode = 1;
  f.srow = {{{-1, 0, 0, 10}, {0, -1, 0, 20}, {0, 0, 2, 30}}};
  writeFile(dir / "b.nii.gz", test::gzipBytes(dir, niftiBytes(f, encode(SampleType::Int16, true, ramp()))));
  auto stream = openNifti(dir / "b.nii.gz");
  EXPECT_EQ(stream->header().spacing, (std::array<double, 3>{1, 1, 2}));
  EXPECT_EQ(stream->header().origin, (std::array<double, 3>{10 - 3, 20 - 2, 30}));
  const std::vector<float> read = readAll(*stream);
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 4; ++x)
        EXPECT_EQ(read[static_cast<std::size_t>(x + 4 * y + 12 * z)],
                  static_cast<float>((3 - x) + 4 * (2 - y) + 12 * z))
            << x << ' ' << y << ' ' << z;
}

TEST(NiftiReader, QformQuaternionAndScaling) {
  // Quaternion (b, c, d) = (0, 0, 1): 180 degrees about z, x and y reversed; pixdim 1.5 1.5 3.
  TempDir dir;
  NiftiFields f;
  f.qformCode = 1;
  f.quatern = {0, 0, 1};
  f.qoffset = {5, 6, 7};
  f.pixdim = {1, 1.5f, 1.5f, 3, 0, 0, 0, 0};
  f.slope = 2;
  f.intercept = -1;
  writeFile(dir / "q.nii", niftiBytes(f, encode(SampleType::UInt8, false, ramp())));
  auto stream = openNifti(dir / "q.nii");
  EXPECT_EQ(stream->header().spacing, (std::array<double, 3>{1.5, 1.5, 3}));
  EXPECT_EQ(stream->header().origin, (std::array<double, 3>{5 - 4.5, 6 - 3, 7}));
  const std::vector<float> read = readAll(*stream);
  EXPECT_EQ(read[0], 2.0f * static_cast<float>(3 + 4 * 2) - 1.0f);  // sample (3, 2, 0) of the file
  EXPECT_EQ(read[23], 2.0f * 12.0f - 1.0f);                         // sample (0, 0, 1)
}

TEST(NiftiReader, BadHeadersNameTheFileAndTheField) {
  TempDir dir;
  const std::string data = encode(SampleType::UInt8, false, ramp());
  const auto refused = [&](NiftiFields f, const std::vector<std::string>& parts, const std::string& body) {
    writeFile(dir / "bad.nii", niftiBytes(f, body));
    expectError<InputError>([&] { readAll(*openNifti(dir / "bad.nii")); }, parts);
  };
  NiftiFields f;
  f.sizeofHdr = 540;
  refused(f, {"bad.nii", "NIfTI-2"}, data);
  f = {};
  f.sizeofHdr = 1234;
  refused(f, {"bad.nii", "sizeof_hdr", "1234"}, data);
  f = {};
  f.magic = std::string("ni1\0", 4);
  refused(f, {"bad.nii", "magic", ".hdr/.img"}, data);
  f = {};
  f.magic = std::string(4, '\0');
  refused(f, {"bad.nii", "magic", "ANALYZE"}, data);
  f = {};
  f.dim = {4, 4, 3, 2, 5, 1, 1, 1};
  refused(f, {"bad.nii", "dim[4] is 5", "3-D"}, data);
  f = {};
  f.datatype = 128;
  f.bitpix = 24;
  refused(f, {"bad.nii", "datatype", "rgb24"}, data);
  f = {};
  f.bitpix = 16;
  refused(f, {"bad.nii", "bitpix", "16"}, data);
  f = {};
  f.sformCode = 1;
  f.srow = {{{0, 1, 0, 0}, {1, 0, 0, 0}, {0, 0, 1, 0}}};
  refused(f, {"bad.nii", "sform", "rotates or swaps"}, data);
  f = {};
  f.sformCode = 1;
  f.srow = {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, -1, 0}}};
  refused(f, {"bad.nii", "negative step"}, data);
  f = {};
  f.voxOffset = 100;
  refused(f, {"bad.nii", "vox_offset"}, data);
  refused({}, {"bad.nii", "24 data bytes", "holds 20"}, data.substr(0, 20));
  // gzip: too much data is found at the end.
  writeFile(dir / "long.nii.gz", test::gzipBytes(dir, niftiBytes({}, data + "xx")));
  expectError<InputError>([&] { readAll(*openNifti(dir / "long.nii.gz")); }, {"long.nii.gz", "longer than"});
  writeFile(dir / "short.nii", "n+1");
  expectError<InputError>([&] { openNifti(dir / "short.nii"); }, {"short.nii"});
}

TEST(NiftiReader, PynrrdsBallWrittenByItkMatchesItsNrrdTwinMirrored) {
  // data/nifti/PROVENANCE.md: ITK wrote the same int16 ball as NRRD (LPS, identity
  // directions) and as NIfTI (RAS: srow diag(-1, -1, 1)). Read in world space, the NIfTI
  // samples are the NRRD's with x and y reversed, from origin (-29, -29, 0).
  const std::filesystem::path data(ISOVDB_DATA_DIR);
  auto nifti = openNifti(data / "nifti" / "BallBinary30x30x30.nii.gz");
  auto nrrd = openDenseVolume(data / "nrrd" / "BallBinary30x30x30_gz.nrrd", std::nullopt);
  EXPECT_EQ(nifti->header().origin, (std::array<double, 3>{-29, -29, 0}));
  EXPECT_EQ(nifti->header().spacing, (std::array<double, 3>{1, 1, 1}));
  const std::vector<float> a = readAll(*nifti), b = readAll(*nrrd);
  ASSERT_EQ(a.size(), 27000u);
  ASSERT_EQ(b.size(), 27000u);
  std::size_t differing = 0;
  for (int z = 0; z < 30; ++z)
    for (int y = 0; y < 30; ++y)
      for (int x = 0; x < 30; ++x)
        differing += a[static_cast<std::size_t>(x + 30 * y + 900 * z)] !=
                     b[static_cast<std::size_t>((29 - x) + 30 * (29 - y) + 900 * z)];
  EXPECT_EQ(differing, 0u);
  EXPECT_EQ(std::count(a.begin(), a.end(), 257.0f), 14328);
}

}  // namespace
}  // namespace isovdb::io
