// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/sample_type.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace isovdb::io {
namespace {

TEST(SampleType, ParsesAliases) {
  EXPECT_EQ(parseSampleType("uint8"), SampleType::UInt8);
  EXPECT_EQ(parseSampleType("UCHAR"), SampleType::UInt8);
  EXPECT_EQ(parseSampleType("unsigned short"), SampleType::UInt16);
  EXPECT_EQ(parseSampleType("float"), SampleType::Float32);
  EXPECT_FALSE(parseSampleType("complex64").has_value());
}

TEST(SampleType, ConvertsBothByteOrders) {
  const unsigned char big[] = {0x01, 0x02};
  float out = 0;
  convertSamples(reinterpret_cast<const std::byte*>(big), SampleType::UInt16, true, 1, &out);
  EXPECT_EQ(out, 258.f);
  convertSamples(reinterpret_cast<const std::byte*>(big), SampleType::UInt16, false, 1, &out);
  EXPECT_EQ(out, 513.f);
}

TEST(SampleType, ReportsFirstNonFiniteValue) {
  const float values[] = {1.f, 2.f, std::numeric_limits<float>::quiet_NaN(), INFINITY};
  float out[4];
  EXPECT_EQ(convertSamples(reinterpret_cast<const std::byte*>(values), SampleType::Float32, false, 4, out), 2);
  EXPECT_EQ(convertSamples(reinterpret_cast<const std::byte*>(values), SampleType::Float32, false, 2, out), -1);
}

TEST(SampleType, NativeBlocksFindTheFirstNonFiniteAnywhereAtAnyAlignment) {
  // Native-order samples convert block by block (1024 at a time): a value late in a later
  // block, a start off the type's alignment, and doubles beyond the float range (finite, so
  // not reported here; they read as +-inf and the stream reports them) must all come out
  // as the per-sample loop gives them.
  std::vector<double> doubles(3000);
  for (std::size_t i = 0; i < doubles.size(); ++i) doubles[i] = 0.25 * static_cast<double>(i) - 100.0;
  doubles[1500] = 1e300;
  std::vector<std::byte> bytes(doubles.size() * sizeof(double) + 1);
  std::memcpy(bytes.data() + 1, doubles.data(), doubles.size() * sizeof(double));  // misaligned by one byte
  std::vector<float> out(doubles.size());
  EXPECT_EQ(convertSamples(bytes.data() + 1, SampleType::Float64, false, doubles.size(), out.data()), -1);
  EXPECT_EQ(out[7], static_cast<float>(doubles[7]));
  EXPECT_TRUE(std::isinf(out[1500]));
  doubles[2500] = -std::numeric_limits<double>::infinity();
  doubles[2900] = std::numeric_limits<double>::quiet_NaN();
  std::memcpy(bytes.data() + 1, doubles.data(), doubles.size() * sizeof(double));
  EXPECT_EQ(convertSamples(bytes.data() + 1, SampleType::Float64, false, doubles.size(), out.data()), 2500);
  EXPECT_EQ(out[2500], -INFINITY) << "the reported sample is converted";

  std::vector<std::int16_t> shorts(2100);
  for (std::size_t i = 0; i < shorts.size(); ++i) shorts[i] = static_cast<std::int16_t>(37 * i - 30000);
  std::memcpy(bytes.data() + 1, shorts.data(), shorts.size() * sizeof(std::int16_t));
  EXPECT_EQ(convertSamples(bytes.data() + 1, SampleType::Int16, false, shorts.size(), out.data()), -1);
  for (std::size_t i = 0; i < shorts.size(); ++i) ASSERT_EQ(out[i], static_cast<float>(shorts[i])) << i;
}

}  // namespace
}  // namespace isovdb::io
