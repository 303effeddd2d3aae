// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/cell/dmc_table.h"

#include <algorithm>
#include <bit>
#include <cassert>

#include "isovdb/bit_count.h"
#include "isovdb/cell/cell_geometry.h"
#include "isovdb/union_find.h"

namespace isovdb::cell {

namespace {

using cell::bipolarEdgeMask;
using cell::cellEdgeCorner;
using cell::cellFaceEdgeMask;

bool inside(std::uint8_t config, int corner) noexcept { return ((config >> corner) & 1) != 0; }

/// The four corners of face f.
std::array<int, 4> faceCorners(int face) noexcept {
  const int axis = face >> 1, side = face & 1;
  std::array<int, 4> out{};
  int n = 0;
  for (int c = 0; c < 8; ++c)
    if (((c >> axis) & 1) == side) out[static_cast<std::size_t>(n++)] = c;
  return out;
}

void unite(std::array<int, 12>& parent, int a, int b) noexcept {
  a = findRoot(parent, a);
  b = findRoot(parent, b);
  if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
}

/// Unites the two set bits of a 2-edge mask.
void unitePair(std::array<int, 12>& parent, std::uint16_t pair) noexcept {
  assert(countBits(pair) == 2);
  const unsigned bits = pair;
  const int a = std::countr_zero(bits);
  const int b = std::countr_zero(bits & (bits - 1u));
  unite(parent, a, b);
}

struct DmcTable {
  std::array<DmcEntry, 256> base;
  std::array<DmcEntry, 256> alternative;

  DmcTable() {
    for (int c = 0; c < 256; ++c) {
      const auto config = static_cast<std::uint8_t>(c);
      base[static_cast<std::size_t>(c)] = detail::buildDmcEntry(config, 0);
      const int f = base[static_cast<std::size_t>(c)].doubleFace;
      alternative[static_cast<std::size_t>(c)] =
          f < 0 ? base[static_cast<std::size_t>(c)] : detail::buildDmcEntry(config, static_cast<std::uint8_t>(1u << f));
      alternative[static_cast<std::size_t>(c)].doubleFace = static_cast<std::int8_t>(f);
    }
  }
};

const DmcTable& table() noexcept {
  static const DmcTable t;
  return t;
}

}  // namespace

bool isAmbiguousFace(std::uint8_t config, int face) noexcept {
  const auto c = faceCorners(face);
  // Corners 0 and 3 of the list are one diagonal, 1 and 2 the other.
  const bool a = inside(config, c[0]), b = inside(config, c[1]), d = inside(config, c[2]), e = inside(config, c[3]);
  return a == e && b == d && a != b;
}

namespace detail {

DmcEntry buildDmcEntry(std::uint8_t config, std::uint8_t flippedFaces) noexcept {
  DmcEntry entry;
  entry.vertexOfEdge.fill(-1);
  const std::uint16_t bipolar = bipolarEdgeMask(config);
  if (bipolar == 0) return entry;

  std::array<int, 12> parent{};
  for (int e = 0; e < 12; ++e) parent[static_cast<std::size_t>(e)] = e;

  for (int f = 0; f < 6; ++f) {
    const std::uint16_t onFace = static_cast<std::uint16_t>(bipolar & cellFaceEdgeMask(f));
    if (onFace == 0) continue;
    if (!isAmbiguousFace(config, f)) {
      unitePair(parent, onFace);  // exactly two bipolar edges on a non-ambiguous face
      continue;
    }
    // Ambiguous face: pair the edges around each corner of the separated phase.
    const bool separateInside = ((flippedFaces >> f) & 1) == 0;
    for (int corner : faceCorners(f))
      if (inside(config, corner) == separateInside) unitePair(parent, cell::cellFaceEdgesAtCorner(f, corner));
  }

  // Groups, ordered by their lowest edge.
  std::array<int, 12> groupOfRoot{};
  groupOfRoot.fill(-1);
  for (int e = 0; e < 12; ++e) {
    if (((bipolar >> e) & 1) == 0) continue;
    const int r = findRoot(parent, e);
    int& g = groupOfRoot[static_cast<std::size_t>(r)];
    if (g < 0) g = entry.vertexCount++;
    assert(g < 4);
    entry.groups[static_cast<std::size_t>(g)] =
        static_cast<std::uint16_t>(entry.groups[static_cast<std::size_t>(g)] | (1u << e));
    entry.vertexOfEdge[static_cast<std::size_t>(e)] = static_cast<std::int8_t>(g);
  }

  // A group that holds all four bipolar edges of an ambiguous face passes through it twice.
  for (int f = 0; f < 6; ++f) {
    if (!isAmbiguousFace(config, f)) continue;
    const std::uint16_t onFace = static_cast<std::uint16_t>(bipolar & cellFaceEdgeMask(f));
    for (int g = 0; g < entry.vertexCount; ++g)
      if ((entry.groups[static_cast<std::size_t>(g)] & onFace) == onFace) {
        assert(entry.doubleFace < 0);  // at most one such face per configuration
        entry.doubleFace = static_cast<std::int8_t>(f);
      }
  }
  return entry;
}

}  // namespace detail

const DmcEntry& dmcEntry(std::uint8_t config, bool alternative) noexcept {
  const DmcTable& t = table();
  return alternative ? t.alternative[config] : t.base[config];
}

}  // namespace isovdb::cell
