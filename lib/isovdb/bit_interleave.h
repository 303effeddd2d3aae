// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file bit_interleave.h
/// @brief Three-way bit interleaving (Morton / Z-order codes), shared by the
///        octree keys and the self-intersection BVH's sort order.
#pragma once

#include <cstdint>

namespace isovdb {

/// Bits 0,1,2,... of v moved to bits 0,3,6,... (the low 21 bits are used).
constexpr std::uint64_t spreadBits3(std::uint64_t v) noexcept {
  v &= 0x1fffffull;
  v = (v | v << 32) & 0x1f00000000ffffull;
  v = (v | v << 16) & 0x1f0000ff0000ffull;
  v = (v | v << 8) & 0x100f00f00f00f00full;
  v = (v | v << 4) & 0x10c30c30c30c30c3ull;
  v = (v | v << 2) & 0x1249249249249249ull;
  return v;
}

/// Inverse of spreadBits3.
constexpr std::uint64_t compactBits3(std::uint64_t v) noexcept {
  v &= 0x1249249249249249ull;
  v = (v ^ (v >> 2)) & 0x10c30c30c30c30c3ull;
  v = (v ^ (v >> 4)) & 0x100f00f00f00f00full;
  v = (v ^ (v >> 8)) & 0x1f0000ff0000ffull;
  v = (v ^ (v >> 16)) & 0x1f00000000ffffull;
  v = (v ^ (v >> 32)) & 0x1fffffull;
  return v;
}

}  // namespace isovdb
