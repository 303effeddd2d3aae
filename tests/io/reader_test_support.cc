// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "io/reader_test_support.h"

#include <bzlib.h>
#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <filesystem>

namespace isovdb::test {

namespace {

using io::SampleType;

/// A value of sample `i` that `type` holds and float represents exactly (covers
/// negative values and the ends of the small integer ranges).
double sampleValue(SampleType type, std::int64_t i) {
  switch (type) {
    case SampleType::Int8:
      return static_cast<double>((i * 37) % 256 - 128);
    case SampleType::UInt8:
      return static_cast<double>((i * 37) % 256);
    case SampleType::Int16:
      return static_cast<double>((i * 4099) % 65536 - 32768);
    case SampleType::UInt16:
      return static_cast<double>((i * 4099) % 65536);
    case SampleType::Int32:
      return static_cast<double>(i * 100003 - 5000000);
    case SampleType::UInt32:
      return static_cast<double>(i * 100003);
    case SampleType::Float32:
      return static_cast<double>(i) * 0.25 - 3.0;
    case SampleType::Float64:
      return static_cast<double>(i) * 0.5 - 7.0;
  }
  return 0;
}

template <typename T>
void appendSample(std::string& bytes, double value, bool bigEndian) {
  const T typed = static_cast<T>(value);
  char raw[sizeof(T)];
  std::memcpy(raw, &typed, sizeof(T));
  if (bigEndian != (std::endian::native == std::endian::big)) std::reverse(raw, raw + sizeof(T));
  bytes.append(raw, sizeof(T));
}

}  // namespace

std::string encode(SampleType type, bool bigEndian, const std::vector<double>& values) {
  std::string bytes;
  for (double v : values) {
    switch (type) {
      case SampleType::Int8:
        appendSample<std::int8_t>(bytes, v, bigEndian);
        break;
      case SampleType::UInt8:
        appendSample<std::uint8_t>(bytes, v, bigEndian);
        break;
      case SampleType::Int16:
        appendSample<std::int16_t>(bytes, v, bigEndian);
        break;
      case SampleType::UInt16:
        appendSample<std::uint16_t>(bytes, v, bigEndian);
        break;
      case SampleType::Int32:
        appendSample<std::int32_t>(bytes, v, bigEndian);
        break;
      case SampleType::UInt32:
        appendSample<std::uint32_t>(bytes, v, bigEndian);
        break;
      case SampleType::Float32:
        appendSample<float>(bytes, v, bigEndian);
        break;
      case SampleType::Float64:
        appendSample<double>(bytes, v, bigEndian);
        break;
    }
  }
  return bytes;
}

std::vector<double> testValues(SampleType type, std::int64_t count) {
  std::vector<double> values(static_cast<std::size_t>(count));
  for (std::int64_t i = 0; i < count; ++i) values[static_cast<std::size_t>(i)] = sampleValue(type, i);
  return values;
}

std::vector<float> readAll(io::SliceStream& stream) {
  const io::VolumeHeader& header = stream.header();
  std::vector<float> values(static_cast<std::size_t>(header.sliceSamples() * header.dims[2]));
  for (std::int64_t z = 0; z < header.dims[2]; ++z) {
    EXPECT_EQ(stream.nextSlice(), z);
    stream.readSlice(values.data() + z * header.sliceSamples());
  }
  return values;
}

std::string gzipBytes(const TempDir& dir, const std::string& data) {
  const auto path = dir / "scratch.gz";
  gzFile gz = gzopen(path.c_str(), "wb");
  EXPECT_NE(gz, nullptr);
  EXPECT_EQ(gzwrite(gz, data.data(), static_cast<unsigned>(data.size())), static_cast<int>(data.size()));
  gzclose(gz);
  std::string bytes = readFile(path);
  std::filesystem::remove(path);
  return bytes;
}

std::string bzip2Bytes(const std::string& data) {
  std::string out(data.size() + data.size() / 100 + 600, '\0');
  auto length = static_cast<unsigned>(out.size());
  std::string input = data;  // libbz2 takes a non-const source
  EXPECT_EQ(BZ2_bzBuffToBuffCompress(out.data(), &length, input.data(), static_cast<unsigned>(input.size()), 1, 0, 0),
            BZ_OK);
  out.resize(length);
  return out;
}

}  // namespace isovdb::test
