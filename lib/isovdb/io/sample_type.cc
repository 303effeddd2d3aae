// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/sample_type.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

namespace isovdb::io {

std::size_t sampleSize(SampleType type) {
  switch (type) {
    case SampleType::Int8:
    case SampleType::UInt8:
      return 1;
    case SampleType::Int16:
    case SampleType::UInt16:
      return 2;
    case SampleType::Int32:
    case SampleType::UInt32:
    case SampleType::Float32:
      return 4;
    case SampleType::Float64:
      return 8;
  }
  return 0;
}

std::string_view sampleTypeName(SampleType type) {
  switch (type) {
    case SampleType::Int8:
      return "int8";
    case SampleType::UInt8:
      return "uint8";
    case SampleType::Int16:
      return "int16";
    case SampleType::UInt16:
      return "uint16";
    case SampleType::Int32:
      return "int32";
    case SampleType::UInt32:
      return "uint32";
    case SampleType::Float32:
      return "float32";
    case SampleType::Float64:
      return "float64";
  }
  return "unknown";
}

bool isFloatingPoint(SampleType type) { return type == SampleType::Float32 || type == SampleType::Float64; }

std::optional<SampleType> parseSampleType(std::string_view name) {
  std::string s(name);
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  struct Alias {
    const char* name;
    SampleType type;
  };
  static constexpr Alias kAliases[] = {
      {"int8", SampleType::Int8},
      {"i8", SampleType::Int8},
      {"char", SampleType::Int8},
      {"signed char", SampleType::Int8},
      {"int8_t", SampleType::Int8},
      {"uint8", SampleType::UInt8},
      {"u8", SampleType::UInt8},
      {"uchar", SampleType::UInt8},
      {"unsigned char", SampleType::UInt8},
      {"uint8_t", SampleType::UInt8},
      {"int16", SampleType::Int16},
      {"i16", SampleType::Int16},
      {"short", SampleType::Int16},
      {"short int", SampleType::Int16},
      {"signed short", SampleType::Int16},
      {"int16_t", SampleType::Int16},
      {"uint16", SampleType::UInt16},
      {"u16", SampleType::UInt16},
      {"ushort", SampleType::UInt16},
      {"unsigned short", SampleType::UInt16},
      {"unsigned short int", SampleType::UInt16},
      {"uint16_t", SampleType::UInt16},
      {"int32", SampleType::Int32},
      {"i32", SampleType::Int32},
      {"int", SampleType::Int32},
      {"signed int", SampleType::Int32},
      {"int32_t", SampleType::Int32},
      {"uint32", SampleType::UInt32},
      {"u32", SampleType::UInt32},
      {"uint", SampleType::UInt32},
      {"unsigned int", SampleType::UInt32},
      {"uint32_t", SampleType::UInt32},
      {"float32", SampleType::Float32},
      {"f32", SampleType::Float32},
      {"float", SampleType::Float32},
      {"float64", SampleType::Float64},
      {"f64", SampleType::Float64},
      {"double", SampleType::Float64},
  };
  for (const Alias& alias : kAliases)
    if (s == alias.name) return alias.type;
  return std::nullopt;
}

namespace {

template <typename T>
T loadSample(const std::byte* p, bool swap) {
  std::array<std::byte, sizeof(T)> raw;
  std::memcpy(raw.data(), p, sizeof(T));
  if (swap) std::reverse(raw.begin(), raw.end());
  T value;
  std::memcpy(&value, raw.data(), sizeof(T));
  return value;
}

/// Native byte order: blocks copied into a local array of T (any alignment, no aliasing
/// of the bytes) and converted by plain loops the compiler vectorises, with a branch-free
/// test for non-finite values; the per-sample loop below was a tenth of a Python extract
/// on a float field.
template <typename T>
std::int64_t convertNative(const std::byte* bytes, std::size_t count, float* out) {
  constexpr std::size_t kBlock = 1024;
  std::array<T, kBlock> block;
  for (std::size_t start = 0; start < count; start += kBlock) {
    const std::size_t n = std::min(kBlock, count - start);
    std::memcpy(block.data(), bytes + start * sizeof(T), n * sizeof(T));
    for (std::size_t i = 0; i < n; ++i) out[start + i] = static_cast<float>(block[i]);
    if constexpr (std::is_floating_point_v<T>) {
      bool bad = false;  // NaN fails the comparison
      for (std::size_t i = 0; i < n; ++i) bad |= !(std::abs(block[i]) <= std::numeric_limits<T>::max());
      if (!bad) continue;
      for (std::size_t i = 0; i < n; ++i)
        if (!std::isfinite(block[i])) return static_cast<std::int64_t>(start + i);
    }
  }
  return -1;
}

template <typename T>
std::int64_t convertTyped(const std::byte* bytes, bool swap, std::size_t count, float* out) {
  if (!swap) return convertNative<T>(bytes, count, out);
  std::int64_t firstBad = -1;
  for (std::size_t i = 0; i < count; ++i) {
    const T value = loadSample<T>(bytes + i * sizeof(T), swap);
    out[i] = static_cast<float>(value);
    if constexpr (std::is_floating_point_v<T>) {
      if (firstBad < 0 && !std::isfinite(value)) firstBad = static_cast<std::int64_t>(i);
    }
  }
  return firstBad;
}

}  // namespace

std::int64_t convertSamples(const std::byte* bytes, SampleType type, bool bigEndian, std::size_t count, float* out) {
  const bool swap = bigEndian != (std::endian::native == std::endian::big);
  switch (type) {
    case SampleType::Int8:
      return convertTyped<std::int8_t>(bytes, swap, count, out);
    case SampleType::UInt8:
      return convertTyped<std::uint8_t>(bytes, swap, count, out);
    case SampleType::Int16:
      return convertTyped<std::int16_t>(bytes, swap, count, out);
    case SampleType::UInt16:
      return convertTyped<std::uint16_t>(bytes, swap, count, out);
    case SampleType::Int32:
      return convertTyped<std::int32_t>(bytes, swap, count, out);
    case SampleType::UInt32:
      return convertTyped<std::uint32_t>(bytes, swap, count, out);
    case SampleType::Float32:
      return convertTyped<float>(bytes, swap, count, out);
    case SampleType::Float64:
      return convertTyped<double>(bytes, swap, count, out);
  }
  return -1;
}

}  // namespace isovdb::io
