// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file reader_test_support.h
/// @brief Helpers shared by the tests of the dense volume readers
///        (raw_reader_test.cc, nrrd_reader_test.cc, metaimage_reader_test.cc):
///        sample data in every type and byte order, reading a whole stream, and
///        checking the type and message of an error.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "isovdb/io/sample_type.h"
#include "isovdb/io/slice_stream.h"
#include "support/test_support.h"

namespace isovdb::test {

/// Every sample type a dense volume file may hold.
inline constexpr io::SampleType kAllTypes[] = {io::SampleType::Int8,    io::SampleType::UInt8,  io::SampleType::Int16,
                                               io::SampleType::UInt16,  io::SampleType::Int32,  io::SampleType::UInt32,
                                               io::SampleType::Float32, io::SampleType::Float64};

/// The bytes of `values` stored as `type` in the given byte order.
std::string encode(io::SampleType type, bool bigEndian, const std::vector<double>& values);

/// `count` values that `type` holds and float represents exactly (covers negative
/// values and the ends of the small integer ranges).
std::vector<double> testValues(io::SampleType type, std::int64_t count);

/// Reads every slice of `stream`, expecting them in order.
std::vector<float> readAll(io::SliceStream& stream);

/// The gzip file bytes of `data` (written through a scratch file in `dir`).
std::string gzipBytes(const TempDir& dir, const std::string& data);

/// The bzip2 stream of `data` (libbz2, block size 100 kB: data longer than that spans blocks).
std::string bzip2Bytes(const std::string& data);

/// Runs `f`, expects it to throw `E` whose message contains each of `parts`.
template <typename E, typename F>
void expectError(F&& f, const std::vector<std::string>& parts) {
  try {
    f();
    ADD_FAILURE() << "no exception thrown";
  } catch (const E& e) {
    const std::string message = e.what();
    for (const std::string& part : parts)
      EXPECT_NE(message.find(part), std::string::npos) << "message '" << message << "' lacks '" << part << "'";
  }
}

}  // namespace isovdb::test
