// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file sample_type.h
/// @brief Element types of dense volume files and their conversion to float.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace isovdb::io {

/// The sample types a dense volume file may hold. Every one converts to float
/// exactly except 32-bit integers above 2^24 and float64 (rounded).
enum class SampleType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

/// Bytes per sample.
std::size_t sampleSize(SampleType type);
/// Canonical lower-case name ("uint8", "float32", ...).
std::string_view sampleTypeName(SampleType type);
/// True for Float32 and Float64 (values may be NaN/Inf and are checked).
bool isFloatingPoint(SampleType type);
/// Parses a canonical name or a common alias ("u8", "uchar", "float", "f32", ...);
/// std::nullopt when unknown.
std::optional<SampleType> parseSampleType(std::string_view name);

/// Converts `count` samples stored in `bytes` (file byte order given by
/// `bigEndian`) to float. Returns the index of the first non-finite value,
/// or -1 when all are finite.
std::int64_t convertSamples(const std::byte* bytes, SampleType type, bool bigEndian, std::size_t count, float* out);

}  // namespace isovdb::io
