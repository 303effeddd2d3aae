// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file bit_count.h
/// @brief Set bits of a 64-bit word, inline on every x86-64.
///
/// Debian builds for the x86-64 baseline, which has no POPCNT instruction, so
/// std::popcount compiles to a call of libgcc's __popcountdi2 (a table walk): 2 % of an
/// adaptive or regular run on 512³ blobs (perf), from the rank look-ups of the unit-leaf
/// and unit-edge indexes, the sample phases' sign changes and the voxel reading's split
/// vertices. The SWAR sum below is a dozen register operations with no call; where the
/// build targets POPCNT, the instruction. The engine counts bits with this only.
#pragma once

#include <bit>
#include <cstdint>

namespace isovdb {

constexpr int countBits(std::uint64_t v) noexcept {
#if defined(__POPCNT__)
  return std::popcount(v);
#else
  v = v - ((v >> 1) & 0x5555555555555555ull);
  v = (v & 0x3333333333333333ull) + ((v >> 2) & 0x3333333333333333ull);
  v = (v + (v >> 4)) & 0x0f0f0f0f0f0f0f0full;
  return static_cast<int>((v * 0x0101010101010101ull) >> 56);
#endif
}

static_assert(countBits(0) == 0 && countBits(~std::uint64_t{0}) == 64 && countBits(0x8000000000000001ull) == 2);

}  // namespace isovdb
