// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file morton.h
/// @brief Morton keys of a linear octree: encode/decode, parent/child, and
///        neighbour lookup by dilated-integer arithmetic on the key itself.
///
/// Paper 000, section 3.4.2 and 4.2.1: the root key is 1; a child's key is its
/// parent's key followed by the 3 bits of its octant (`key << 3 | octant`);
/// the parent is `key >> 3`. A key of depth d therefore has 3d + 1 significant
/// bits, and the leading 1 marks the depth.
///
/// Conventions (used by the whole octree stage and by contour/):
/// - octant (and cell corner) bits: bit 0 = +x, bit 1 = +y, bit 2 = +z;
/// - in a key, the x bit of each 3-bit group is the lowest;
/// - cell coordinates at depth d are integers in [0, 2^d) on each axis; a
///   cell of depth d in a meta-cell of S voxels spans S >> d voxels.
/// Everything here is constexpr and header-only.
#pragma once

#include <array>
#include <bit>
#include <cstdint>

#include "isovdb/bit_interleave.h"
#include "isovdb/cell/cell_geometry.h"

namespace isovdb::octree {

/// A Morton key (root = 1). 0 is never a valid key and means "none".
using MortonKey = std::uint64_t;

inline constexpr MortonKey kRootKey = 1;
inline constexpr MortonKey kInvalidKey = 0;
/// Deepest depth a key can hold (3 * 20 + 1 = 61 bits). Meta-cells of up to
/// 2^19 voxels plus the extra stitching level fit comfortably.
inline constexpr int kMaxKeyDepth = 20;

/// Integer cell coordinates of a key: depth and position in [0, 2^depth)^3.
struct KeyCoord {
  int depth = 0;
  std::array<int, 3> xyz{0, 0, 0};
  friend constexpr bool operator==(const KeyCoord&, const KeyCoord&) = default;
};

namespace detail {

using isovdb::compactBits3;
using isovdb::spreadBits3;

/// Mask of the bits of `axis` in the 3*depth low bits of a key.
constexpr std::uint64_t axisMask(int axis, int depth) noexcept {
  const std::uint64_t all = depth >= 21 ? ~0ull : ((1ull << (3 * depth)) - 1);
  return (0x1249249249249249ull << axis) & all;
}

}  // namespace detail

/// @brief Depth of a key (root = 0).
/// @pre key != kInvalidKey.
constexpr int keyDepth(MortonKey key) noexcept { return (std::bit_width(key) - 1) / 3; }

/// @brief Key of child `octant` (0..7, bit 0 = +x, bit 1 = +y, bit 2 = +z).
constexpr MortonKey childKey(MortonKey key, int octant) noexcept {
  return (key << 3) | static_cast<MortonKey>(octant & 7);
}

/// @brief Key of the parent (the root's parent is kInvalidKey).
constexpr MortonKey parentKey(MortonKey key) noexcept { return key >> 3; }

/// @brief Octant of a key inside its parent.
constexpr int octantOf(MortonKey key) noexcept { return static_cast<int>(key & 7); }

/// @brief Ancestor of `key` at depth `depth` (<= keyDepth(key)).
constexpr MortonKey ancestorKey(MortonKey key, int depth) noexcept { return key >> (3 * (keyDepth(key) - depth)); }

/// @brief True if `ancestor` is `key` or one of its ancestors.
constexpr bool isAncestorOrSelf(MortonKey ancestor, MortonKey key) noexcept {
  const int da = keyDepth(ancestor), dk = keyDepth(key);
  return da <= dk && (key >> (3 * (dk - da))) == ancestor;
}

/// @brief Key of the cell at integer coordinates `xyz` (each in [0, 2^depth)) of depth `depth`.
/// @pre 0 <= depth <= kMaxKeyDepth.
constexpr MortonKey encodeKey(int depth, std::array<int, 3> xyz) noexcept {
  const std::uint64_t bits = detail::spreadBits3(static_cast<std::uint64_t>(xyz[0])) |
                             detail::spreadBits3(static_cast<std::uint64_t>(xyz[1])) << 1 |
                             detail::spreadBits3(static_cast<std::uint64_t>(xyz[2])) << 2;
  return (MortonKey{1} << (3 * depth)) | bits;
}

/// @brief Depth and integer cell coordinates of a key.
constexpr KeyCoord decodeKey(MortonKey key) noexcept {
  KeyCoord c;
  c.depth = keyDepth(key);
  const std::uint64_t bits = key ^ (MortonKey{1} << (3 * c.depth));
  for (int a = 0; a < 3; ++a) c.xyz[a] = static_cast<int>(detail::compactBits3(bits >> a));
  return c;
}

/// @brief Key of the same-depth cell offset by (dx, dy, dz), each in {-1, 0, 1}
///        (6 face, 12 edge and 8 vertex neighbours), computed by dilated-integer
///        arithmetic on the key, without decoding it.
/// @return kInvalidKey when the neighbour lies outside the root cube.
constexpr MortonKey neighbourKey(MortonKey key, int dx, int dy, int dz) noexcept {
  const int depth = keyDepth(key);
  const MortonKey lead = MortonKey{1} << (3 * depth);
  MortonKey bits = key ^ lead;
  const int d[3] = {dx, dy, dz};
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0) continue;
    const std::uint64_t m = detail::axisMask(a, depth);
    const std::uint64_t v = bits & m;
    std::uint64_t nv;
    if (d[a] > 0) {
      if (v == m) return kInvalidKey;  // already at the last cell on this axis
      nv = ((v | ~m) + (std::uint64_t{1} << a)) & m;
    } else {
      if (v == 0) return kInvalidKey;
      nv = (v - (std::uint64_t{1} << a)) & m;
    }
    bits = (bits & ~m) | nv;
  }
  return lead | bits;
}

/// @brief Face neighbour: face f = 2 * axis + (0: -side, 1: +side).
constexpr MortonKey faceNeighbourKey(MortonKey key, int face) noexcept {
  const int axis = face >> 1, s = (face & 1) ? 1 : -1;
  return neighbourKey(key, axis == 0 ? s : 0, axis == 1 ? s : 0, axis == 2 ? s : 0);
}

/// @brief Sort code that orders cells of mixed depths in octree pre-order
///        (Z order); cells that do not overlap get distinct codes.
/// @param finestDepth a depth >= keyDepth(key), the same for all compared keys.
constexpr std::uint64_t zOrderCode(MortonKey key, int finestDepth) noexcept {
  const int depth = keyDepth(key);
  return (key ^ (MortonKey{1} << (3 * depth))) << (3 * (finestDepth - depth));
}

}  // namespace isovdb::octree

namespace isovdb::octree {

/// The cell numbering the keys follow (octants = corners), from cell/.
using cell::bipolarEdgeMask;
using cell::cellEdgeAxis;
using cell::cellEdgeCorner;
using cell::cellEdgeIndex;
using cell::cellFaceEdgeMask;
using cell::cellFaceEdgesAtCorner;
using cell::otherAxes;

}  // namespace isovdb::octree
