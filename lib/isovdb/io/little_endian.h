// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file little_endian.h
/// @brief Appends numbers to a byte buffer in little-endian order, the byte
///        order of every binary file isovdb writes (PLY, raw float32).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <vector>

namespace isovdb::io {

/// Appends the bytes of `value` (an arithmetic type) to `out`, least significant first.
template <class T>
void appendLittleEndian(std::vector<char>& out, T value) {
  auto bytes = std::bit_cast<std::array<char, sizeof(T)>>(value);
  if constexpr (std::endian::native == std::endian::big) std::reverse(bytes.begin(), bytes.end());
  out.insert(out.end(), bytes.begin(), bytes.end());
}

}  // namespace isovdb::io
