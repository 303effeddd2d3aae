// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file little_endian.h
/// @brief Numbers to and from bytes in little-endian order, the byte order of
///        every binary file isovdb writes (PLY, STL, GLB, raw float32).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <vector>

namespace isovdb::io {

/// The bytes of `value` (an arithmetic type), least significant first.
template <class T>
std::array<char, sizeof(T)> littleEndianBytes(T value) {
  auto bytes = std::bit_cast<std::array<char, sizeof(T)>>(value);
  if constexpr (std::endian::native == std::endian::big) std::reverse(bytes.begin(), bytes.end());
  return bytes;
}

/// Appends the bytes of `value` (an arithmetic type) to `out`, least significant first.
template <class T>
void appendLittleEndian(std::vector<char>& out, T value) {
  const auto bytes = littleEndianBytes(value);
  out.insert(out.end(), bytes.begin(), bytes.end());
}

/// The arithmetic value of type T whose bytes start at `p`, least significant first
/// (any alignment).
template <class T>
T readLittleEndian(const char* p) {
  std::array<char, sizeof(T)> bytes;
  std::memcpy(bytes.data(), p, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) std::reverse(bytes.begin(), bytes.end());
  return std::bit_cast<T>(bytes);
}

}  // namespace isovdb::io
