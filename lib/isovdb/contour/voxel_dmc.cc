// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/contour/voxel_dmc.h"

#include <algorithm>
#include <bit>
#include <cassert>

#include "isovdb/bit_count.h"
#include "isovdb/cell/dual_vertex.h"
#include "isovdb/cell/meta_cell_samples.h"
#include "isovdb/contour/ju_udeshi.h"
#include "isovdb/contour/regular_contour.h"
#include "isovdb/octree/morton.h"
#include "isovdb/octree/unit_edge_crossings.h"

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

std::optional<Vec3f> unambiguousUnitVertex(const cell::MetaCellSamples& samples, const std::array<int, 3>& cell,
                                           int axis, int quadrant, const cell::DualVertexOptions& options,
                                           const octree::UnitEdgeCrossings* crossings) {
  if (std::any_of(cell.begin(), cell.end(), [&](int c) { return c < 0 || c >= samples.size; })) return std::nullopt;
  const std::uint8_t config = cell::cellCornerSigns(samples, cell, 1, options.iso);
  const cell::DmcEntry& entry = cell::dmcEntry(config);
  if (entry.vertexCount != 1 || voxelDmcEntry(config).vertexCount != 1 ||
      cell::dmcVertexOfEdge(config, false, axis, quadrant) < 0)
    return std::nullopt;
  const cell::DualVertex v = octree::cellDualVertex(samples, cell, 1, entry.groups[0], options, crossings);
  if (!v.valid()) return std::nullopt;
  return v.position;
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

VoxelEdgePolygon voxelEdgePolygon(const std::array<VoxelEdgeCell, 4>& cells, int axis, const FaceCornerFn& between) {
  static constexpr std::array<int, 4> kCounterClockwise{0, 1, 3, 2};
  VoxelEdgePolygon polygon;
  auto& corners = polygon.corners;
  std::size_t& size = polygon.size;
  for (int k = 0; k < 4; ++k) {
    const int q = kCounterClockwise[static_cast<std::size_t>(k)];
    const int prev = kCounterClockwise[static_cast<std::size_t>((k + 3) % 4)];
    const int next = kCounterClockwise[static_cast<std::size_t>((k + 1) % 4)];
    const VoxelEdgeCell& cell = cells[static_cast<std::size_t>(q)];
    const int edge = 4 * axis + (3 - q);
    const int towardNext = sharedFace(axis, q, next);
    const std::uint32_t first = vertexOnFace(cell, edge, sharedFace(axis, q, prev));
    const std::uint32_t second = vertexOnFace(cell, edge, towardNext);
    corners[size++] = first;
    if (second != first) {
      corners[size++] = second;
      polygon.plainQuad = false;
    }
    // The face to the next cell is split if its owner (the cell on its min side) says so.
    const bool ownerIsThis = (towardNext & 1) != 0;
    const int owner = ownerIsThis ? q : next;
    const int ownerFace = ownerIsThis ? towardNext : (towardNext ^ 1);
    const VoxelEdgeCell& ownerCell = cells[static_cast<std::size_t>(owner)];
    const int faceAxis = ownerFace >> 1;
    if (((ownerCell.splitFaces >> faceAxis) & 1) == 0) {
      if (!between) continue;
      const std::uint32_t corner = between(q, next);
      if (corner == kNoVertex) continue;
      corners[size++] = corner;
      polygon.plainQuad = false;
      continue;
    }
    const int ownerEdge = 4 * axis + (3 - owner);
    const int c0 = cellEdgeCorner(ownerEdge, 0), c1 = cellEdgeCorner(ownerEdge, 1);
    const int outsideEnd = inside(ownerCell.config, c0) ? c1 : c0;
    const int slot = outsideCornersOf(ownerCell.config, ownerFace)[1] == outsideEnd ? 1 : 0;
    if (polygon.apex < 0) polygon.apex = static_cast<int>(size);
    corners[size++] = ownerCell.splitVertices[static_cast<std::size_t>(splitVertexSlot(faceAxis, slot))];
    polygon.plainQuad = false;
  }
  // Counter-clockwise in (u, v) is +axis for x and z, -axis for y; outward = from the inside end
  // (the min end is corner 0 of cell 3) to the outside end.
  polygon.minEndInside = inside(cells[3].config, 0);
  polygon.reversed = polygon.minEndInside != (axis != 1);
  return polygon;
}

int fanVoxelEdgePolygon(const VoxelEdgePolygon& polygon, std::uint32_t centre, std::vector<mesh::Triangle>& out) {
  const std::size_t size = polygon.size;
  for (std::size_t i = 0; i < size; ++i) {
    const std::size_t from = polygon.reversed ? (size - i) % size : i;
    const std::size_t to = polygon.reversed ? size - 1 - i : (i + 1) % size;
    out.push_back(mesh::Triangle{centre, polygon.corners[from], polygon.corners[to]});
  }
  return static_cast<int>(size);
}

int voxelEdgeTriangles(const std::array<VoxelEdgeCell, 4>& cells, int axis, const std::array<int, 3>& edgeStart,
                       int cellSize, std::vector<mesh::Triangle>& out, const EdgePointFn& edgePoint) {
  const VoxelEdgePolygon polygon = voxelEdgePolygon(cells, axis);
  if (polygon.plainQuad) {
    std::array<std::uint32_t, 4> v{};
    std::array<mesh::Vec3f, 4> p{};
    for (int q = 0; q < 4; ++q) {
      const VoxelEdgeCell& cell = cells[static_cast<std::size_t>(q)];
      const int g = voxelDmcEntry(cell.config).vertexOfEdge[static_cast<std::size_t>(4 * axis + 3 - q)];
      v[static_cast<std::size_t>(q)] = cell.vertices[static_cast<std::size_t>(g)];
      p[static_cast<std::size_t>(q)] = cell.positions[static_cast<std::size_t>(g)];
    }
    return voxelQuadTriangles(v, p, axis, polygon.minEndInside, edgeStart, cellSize, edgePoint, out);
  }
  if (edgePoint) return fanVoxelEdgePolygon(polygon, edgePoint(), out);
  const std::size_t size = polygon.size;
  const auto apex = static_cast<std::size_t>(std::max(polygon.apex, 0));
  // Fanned from the apex, walking the polygon forwards or backwards.
  const auto at = [&](std::size_t i) {
    return polygon.corners[polygon.reversed ? (apex + size - i) % size : (apex + i) % size];
  };
  for (std::size_t i = 1; i + 1 < size; ++i) out.push_back(mesh::Triangle{at(0), at(i), at(i + 1)});
  return static_cast<int>(size) - 2;
}

int voxelQuadTriangles(const std::array<std::uint32_t, 4>& v, const std::array<mesh::Vec3f, 4>& p, int axis,
                       bool minEndInside, const std::array<int, 3>& edgeStart, int size, const EdgePointFn& edgePoint,
                       std::vector<mesh::Triangle>& out) {
  const auto quad = regularEdgeQuad(v, p, axis, minEndInside);
  if (!edgePoint) {
    out.insert(out.end(), quad.begin(), quad.end());
    return 2;
  }
  // Ju–Udeshi's envelope of the edge: the cells' vertices in cyclic order (quadrants 0, 1,
  // 3, 2) and the points where the segments between neighbours cross their shared faces.
  static constexpr std::array<int, 4> kCycle{0, 1, 3, 2};
  EdgeEnvelope envelope;
  bool crossed = true;
  for (int a = 0; a < 3; ++a) {
    envelope.edgeStart[a] = edgeStart[static_cast<std::size_t>(a)];
    envelope.edgeEnd[a] = edgeStart[static_cast<std::size_t>(a)] + (a == axis ? size : 0);
  }
  const auto point = [&](int q) {
    const mesh::Vec3f& x = p[static_cast<std::size_t>(q)];
    return Vec3d{x[0], x[1], x[2]};
  };
  for (int k = 0; k < 4; ++k) {
    const int q = kCycle[static_cast<std::size_t>(k)], next = kCycle[static_cast<std::size_t>((k + 1) % 4)];
    envelope.cellPoints[static_cast<std::size_t>(k)] = point(q);
    const QuadrantFace shared = faceBetweenQuadrants(edgeStart, axis, size, q, next);
    const FacePoint fp = shared.firstOnMinSide ? computeFacePoint(point(q), point(next), shared.face)
                                               : computeFacePoint(point(next), point(q), shared.face);
    envelope.facePoints[static_cast<std::size_t>(k)] = fp.point;
    crossed = crossed && fp.crossed;
  }
  const auto position = [&](std::uint32_t id) {
    for (int q = 0; q < 4; ++q)
      if (v[static_cast<std::size_t>(q)] == id) return point(q);
    return Vec3d{0, 0, 0};
  };
  const auto inside = [&](const std::array<mesh::Triangle, 2>& pair) {
    // The diagonal joins cyclic positions 0 and 2 (quadrants 0, 3) or 1 and 3.
    const bool diagonal03 = std::find(pair[1].begin(), pair[1].end(), v[0]) != pair[1].end() &&
                            std::find(pair[0].begin(), pair[0].end(), v[0]) != pair[0].end();
    if (crossed && clearlyInsideEnvelope(envelope, diagonal03 ? 0 : 1)) return true;
    for (const mesh::Triangle& t : pair)
      if (!triangleInEnvelope(envelope, position(t[0]), position(t[1]), position(t[2]))) return false;
    return true;
  };
  if (inside(quad)) {
    out.insert(out.end(), quad.begin(), quad.end());
    return 2;
  }
  // The other diagonal, else the fan through the edge's crossing, both in the quad's
  // orientation: its corners in order are (V0, V1, V2) + V3 whichever diagonal it took.
  const mesh::Triangle& a = quad[0];
  const mesh::Triangle& b = quad[1];
  const bool diagonal02 = a[0] == b[0];  // (V0, V1, V2), (V0, V2, V3); else (V0, V1, V3), (V1, V2, V3)
  const std::array<std::uint32_t, 4> ring = diagonal02 ? std::array<std::uint32_t, 4>{a[0], a[1], a[2], b[2]}
                                                       : std::array<std::uint32_t, 4>{a[0], a[1], b[1], b[2]};
  const std::array<mesh::Triangle, 2> other =
      diagonal02 ? std::array<mesh::Triangle, 2>{mesh::Triangle{ring[0], ring[1], ring[3]},
                                                 mesh::Triangle{ring[1], ring[2], ring[3]}}
                 : std::array<mesh::Triangle, 2>{mesh::Triangle{ring[0], ring[1], ring[2]},
                                                 mesh::Triangle{ring[0], ring[2], ring[3]}};
  if (inside(other)) {
    out.insert(out.end(), other.begin(), other.end());
    return 2;
  }
  const std::uint32_t centre = edgePoint();
  for (int k = 0; k < 4; ++k)
    out.push_back(
        mesh::Triangle{centre, ring[static_cast<std::size_t>(k)], ring[static_cast<std::size_t>((k + 1) % 4)]});
  return 4;
}

}  // namespace isovdb::contour
