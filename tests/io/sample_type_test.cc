// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/sample_type.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

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

}  // namespace
}  // namespace isovdb::io
