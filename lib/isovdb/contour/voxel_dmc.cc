// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/contour/voxel_dmc.h"

#include <bit>
#include <cassert>

#include "isovdb/bit_count.h"
#include "isovdb/contour/regular_contour.h"
#include "isovdb/octree/morton.h"

namespace isovdb::contour {

namespace {

using octree::bipolarEdgeMask;
using octree::cellEdgeCorner;
using octree::cellFaceEdgeMask;
using octree::otherAxes;

bool inside(std::uint8_t config, int corner) noexcept { return ((config >> corner) & 1) != 0; }

/// Face of a cell on the min (side 0) or max (side 1) end of `axis`.
int faceIndex(int axis, int side) noexcept { return 2 * axis + side; }

/// The outside corners of face f, ascending (two on an ambiguous face).
std::array<int, 2> outsideCornersOf(std::uint8_t config, int face) noexcept {
  std::array<int, 2> out{-1, -1};
  int n = 0;
  for (int c = 0; c < 8 && n < 2; ++c)
    if (((c >> (face >> 1)) & 1) == (face & 1) && !inside(config, c)) out[static_cast<std::size_t>(n++)] = c;
  return out;
}

struct VoxelTables {
  std::array<cell::DmcEntry, 256> entries;
  std::array<TubeSectors, 256> tubes;

  VoxelTables() {
    for (int c = 0; c < 256; ++c) {
      const auto config = static_cast<std::uint8_t>(c);
      entries[static_cast<std::size_t>(c)] = cell::detail::buildDmcEntry(config, 0x3f);
      if (!isTubeConfig(config)) continue;
      // Inside corners a and a ^ 7: sector k = the face along axis k at a, and the face along
      // axis k + 1 at a ^ 7. Each pair is 60 degrees apart around the diagonal, all slanted the
      // same way, so the sectors tile the annulus.
      const int a = std::countr_zero(static_cast<unsigned>(config));
      const std::uint16_t bipolar = bipolarEdgeMask(config);
      TubeSectors& t = tubes[static_cast<std::size_t>(c)];
      for (int k = 0; k < 3; ++k) {
        const int next = (k + 1) % 3;
        const int nearA = faceIndex(k, (a >> k) & 1);
        const int nearB = faceIndex(next, 1 - ((a >> next) & 1));
        t.sectorOfFace[static_cast<std::size_t>(nearA)] = static_cast<std::int8_t>(k);
        t.sectorOfFace[static_cast<std::size_t>(nearB)] = static_cast<std::int8_t>(k);
        t.edges[static_cast<std::size_t>(k)] =
            static_cast<std::uint16_t>(bipolar & (cellFaceEdgeMask(nearA) | cellFaceEdgeMask(nearB)));
      }
    }
  }
};

const VoxelTables& tables() noexcept {
  static const VoxelTables t;
  return t;
}

/// Face of cell q shared with cell q' (q ^ q' is 1 or 2) around an edge along `axis`.
int sharedFace(int axis, int q, int other) noexcept {
  const auto uv = otherAxes(axis);
  const int bit = (q ^ other) == 1 ? 0 : 1;
  const bool plusSide = ((q >> bit) & 1) != 0;  // the cell is on the + side: the edge is on its min face
  return faceIndex(uv[static_cast<std::size_t>(bit)], plusSide ? 0 : 1);
}

/// Cell q's vertex on face f at the edge (its local edge e).
std::uint32_t vertexOnFace(const VoxelEdgeCell& cell, int edge, int face) noexcept {
  if (isTubeConfig(cell.config))
    return cell
        .vertices[static_cast<std::size_t>(tubeSectors(cell.config).sectorOfFace[static_cast<std::size_t>(face)])];
  const int g = voxelDmcEntry(cell.config).vertexOfEdge[static_cast<std::size_t>(edge)];
  assert(g >= 0);
  return cell.vertices[static_cast<std::size_t>(g)];
}

}  // namespace

const cell::DmcEntry& voxelDmcEntry(std::uint8_t config) noexcept { return tables().entries[config]; }

bool isTubeConfig(std::uint8_t config) noexcept {
  if (countBits(static_cast<unsigned>(config)) != 2) return false;
  const int a = std::countr_zero(static_cast<unsigned>(config));
  return inside(config, a ^ 7);
}

const TubeSectors& tubeSectors(std::uint8_t config) noexcept { return tables().tubes[config]; }

int voxelCellVertexCount(std::uint8_t config) noexcept {
  return isTubeConfig(config) ? 3 : voxelDmcEntry(config).vertexCount;
}

std::array<std::uint16_t, 2> splitVertexEdges(std::uint8_t config, int face) noexcept {
  const std::uint16_t bipolar = bipolarEdgeMask(config);
  const auto corners = outsideCornersOf(config, face);
  return {static_cast<std::uint16_t>(bipolar & octree::cellFaceEdgesAtCorner(face, corners[0])),
          static_cast<std::uint16_t>(bipolar & octree::cellFaceEdgesAtCorner(face, corners[1]))};
}

int voxelEdgeTriangles(const std::array<VoxelEdgeCell, 4>& cells, int axis, std::vector<mesh::Triangle>& out) {
  static constexpr std::array<int, 4> kCounterClockwise{0, 1, 3, 2};
  std::array<std::uint32_t, 12> polygon{};
  std::size_t size = 0;
  int apex = -1;  // first split vertex
  bool plainQuad = true;
  for (int k = 0; k < 4; ++k) {
    const int q = kCounterClockwise[static_cast<std::size_t>(k)];
    const int prev = kCounterClockwise[static_cast<std::size_t>((k + 3) % 4)];
    const int next = kCounterClockwise[static_cast<std::size_t>((k + 1) % 4)];
    const VoxelEdgeCell& cell = cells[static_cast<std::size_t>(q)];
    const int edge = 4 * axis + (3 - q);
    const int towardNext = sharedFace(axis, q, next);
    const std::uint32_t first = vertexOnFace(cell, edge, sharedFace(axis, q, prev));
    const std::uint32_t second = vertexOnFace(cell, edge, towardNext);
    polygon[size++] = first;
    if (second != first) {
      polygon[size++] = second;
      plainQuad = false;
    }
    // The face to the next cell is split if its owner (the cell on its min side) says so.
    const bool ownerIsThis = (towardNext & 1) != 0;
    const int owner = ownerIsThis ? q : next;
    const int ownerFace = ownerIsThis ? towardNext : (towardNext ^ 1);
    const VoxelEdgeCell& ownerCell = cells[static_cast<std::size_t>(owner)];
    const int faceAxis = ownerFace >> 1;
    if (((ownerCell.splitFaces >> faceAxis) & 1) == 0) continue;
    const int ownerEdge = 4 * axis + (3 - owner);
    const int c0 = cellEdgeCorner(ownerEdge, 0), c1 = cellEdgeCorner(ownerEdge, 1);
    const int outsideEnd = inside(ownerCell.config, c0) ? c1 : c0;
    const int slot = outsideCornersOf(ownerCell.config, ownerFace)[1] == outsideEnd ? 1 : 0;
    if (apex < 0) apex = static_cast<int>(size);
    polygon[size++] = ownerCell.splitVertices[static_cast<std::size_t>(splitVertexSlot(faceAxis, slot))];
    plainQuad = false;
  }

  // Counter-clockwise in (u, v) is +axis for x and z, -axis for y; outward = from the inside end
  // (the min end is corner 0 of cell 3) to the outside end.
  const bool minEndInside = inside(cells[3].config, 0);
  if (plainQuad) {
    std::array<std::uint32_t, 4> v{};
    std::array<mesh::Vec3f, 4> p{};
    for (int q = 0; q < 4; ++q) {
      const VoxelEdgeCell& cell = cells[static_cast<std::size_t>(q)];
      const int g = voxelDmcEntry(cell.config).vertexOfEdge[static_cast<std::size_t>(4 * axis + 3 - q)];
      v[static_cast<std::size_t>(q)] = cell.vertices[static_cast<std::size_t>(g)];
      p[static_cast<std::size_t>(q)] = cell.positions[static_cast<std::size_t>(g)];
    }
    const auto quad = regularEdgeQuad(v, p, axis, minEndInside);
    out.insert(out.end(), quad.begin(), quad.end());
    return 2;
  }
  const bool reversed = minEndInside != (axis != 1);
  if (apex < 0) apex = 0;
  // Fanned from the apex, walking the polygon forwards or backwards.
  const auto at = [&](std::size_t i) {
    const std::size_t a = static_cast<std::size_t>(apex);
    return polygon[reversed ? (a + size - i) % size : (a + i) % size];
  };
  for (std::size_t i = 1; i + 1 < size; ++i) out.push_back(mesh::Triangle{at(0), at(i), at(i + 1)});
  return static_cast<int>(size) - 2;
}

}  // namespace isovdb::contour
