// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/reservoir/hex_cell_contour.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "isovdb/huge_pages.h"
#include "isovdb/reservoir/hex_cell.h"
#include "isovdb/reservoir/jacobian_normals.h"

namespace isovdb::reservoir::hex {
namespace {

// Faces as corner cycles, counter-clockwise seen from outside (right-handed parameter space).
/// Where a corner lies exactly at the iso-value, the vertices of its edges sit this
/// fraction of the edge away from it (at least 16 float steps of the coordinates).
constexpr double kCornerOffset = 1e-3;
/// Beyond this fraction the offset would move the surface visibly: the corner is shared.
constexpr double kMaxCornerOffset = 0.02;

/// A fan whose diagonals come nearer a face of the cell than this fraction of the cell's
/// extent across it (or leave the cell) gives way to a centre vertex that stays deeper.
/// Measured on Reek (PORO 0.1-0.3, 9 iso-values) and Emerald (PORO, FACIES), with the fault
/// move (hex_marching_cubes.cc) at a thousandth then, self-intersecting pairs / triangles
/// against the first fan apex in loop order: only fans chosen by depth
/// 192 -> 122 / +0.0 %; centres where a diagonal leaves the cell (0) 91 / +0.9 %; 0.1: 89 /
/// +5.3 %; 0.15: 86 / +6.5 %. On thin layers with 3 m twists (FansStayInsideThinTwistedCells'
/// grids, 10 seeds) 0.1 left 37 pairs where 0 left 73 and the first apex 137.
constexpr double kFanDepthForCentre = 0.1;

/// A segment of the surface on a face whose chord runs farther than this fraction of both
/// cells' thickness off the face's bilinear patch gets a face point: the patch's point
/// halfway between its two crossings (in the face's parameters), shared by both cells; the
/// loop's fan is then chosen among its crossings and face points as before. Reek's 3 m
/// layers lie under faces whose corners sit up to 10 m off the plane of the other three: a
/// chord across such a face ran up to 2.5 m off it, through the next cell of the column, and
/// the triangles on both sides of it crossed. Self-intersecting pairs away from pinched
/// cells over Reek PORO 0.1-0.3 (9 iso-values), Emerald PORO 0.1-0.3 (5) and FACIES 0.5,
/// and regular27cell PORO 0.45 / their triangles: no face points 39 / 198,784; per segment
/// at 0.05: 13 / 220,251; 0.1: 8 / 207,717; 0.15: 8 / 203,983; 0.2: 12 / 201,878 (against
/// the thinner cell's thickness instead of both: the same pairs, 0.5 % more triangles, and
/// the neighbour's points read for every face). Per face (every segment of a face whose
/// centre bows that far; the first version): 0.2: 10 / 223,382, but Emerald PORO 0.1 / 0.25
/// went from 0 / 3 to 3 / 5 pairs, fans hugging a face that the surface runs almost along.
/// On 120 grids of 3 m layers under 100 m columns whose pillars move up to 3 or 6 m
/// (twistedLayers, 20 seeds, PORO 0.15 / 0.2 / 0.25): 1,206 pairs without, 80 per segment
/// at 0.1 (+16 % triangles), 61 per face at 0.2 (+41 %).
constexpr double kFaceWarp = 0.1;

/// Corner c's parameter coordinates in the cell: its bits.
Vec3d cornerParameters(int c) {
  return {static_cast<double>(c & 1), static_cast<double>((c >> 1) & 1), static_cast<double>((c >> 2) & 1)};
}

constexpr int kFaces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};

constexpr int edgeId(int a, int b) {  // 12 edges: axis * 4 + the other two bits
  const int axisBit = a ^ b;
  const int axis = axisBit == 1 ? 0 : axisBit == 2 ? 1 : 2;
  const int base = a & ~axisBit;
  int rest = 0, r = 0;
  for (int bit = 0; bit < 3; ++bit)
    if (bit != axis) rest |= ((base >> bit) & 1) << r++;
  return axis * 4 + rest;
}

/// edgeId of each pair of corners that share an edge (-1 for the others), looked up where
/// cells are contoured (computed there bit by bit: 1-2 % of Marching Cubes on Reek).
constexpr std::array<std::array<std::int8_t, 8>, 8> kEdgeIds = [] {
  std::array<std::array<std::int8_t, 8>, 8> ids{};
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b) {
      const int bit = a ^ b;
      ids[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)] =
          static_cast<std::int8_t>(bit == 1 || bit == 2 || bit == 4 ? edgeId(a, b) : -1);
    }
  return ids;
}();

/// How a face is cut, indexed by which of its corners lie above the iso-value (bit e for
/// kFaces' corner e): its sign changes and, where there are two, the positions of the
/// edges where the sign goes above -> below (down) and below -> above (up), counter-clockwise.
struct FaceCase {
  int crossings = 0, down = -1, up = -1;
};
constexpr std::array<FaceCase, 16> kFaceCases = [] {
  std::array<FaceCase, 16> cases{};
  for (int mask = 0; mask < 16; ++mask) {
    FaceCase& c = cases[static_cast<std::size_t>(mask)];
    for (int e = 0; e < 4; ++e) {
      const bool from = mask >> e & 1, to = mask >> ((e + 1) % 4) & 1;
      c.crossings += from != to;
      if (from && !to) c.down = e;
      if (!from && to) c.up = e;
    }
  }
  return cases;
}();

/// The faces a cell's surface cuts, in face order, by which of its corners lie above the
/// iso-value (bit c for corner c): for a face with two crossings its segment, from the
/// crossing on edge (a0, b0) to the one on (a1, b1); a face with four is ambiguous and is
/// resolved per cell (the asymptotic decider). One look-up per cell where each of the six
/// faces was tested: Marching Cubes on Reek 2.6 % faster.
struct FaceCut {
  std::int8_t face = 0;
  bool ambiguous = false;
  std::int8_t a0 = 0, b0 = 0, a1 = 0, b1 = 0;
};
struct CellCuts {
  int count = 0;
  std::array<FaceCut, 6> faces{};
};
constexpr std::array<CellCuts, 256> kCellCuts = [] {
  std::array<CellCuts, 256> table{};
  for (int cellCase = 0; cellCase < 256; ++cellCase) {
    CellCuts& cuts = table[static_cast<std::size_t>(cellCase)];
    for (int face = 0; face < 6; ++face) {
      const auto& f = kFaces[face];
      int faceMask = 0;
      for (int e = 0; e < 4; ++e) faceMask |= (cellCase >> f[e] & 1) << e;
      const FaceCase& faceCase = kFaceCases[static_cast<std::size_t>(faceMask)];
      if (faceCase.crossings == 0) continue;
      FaceCut& cut = cuts.faces[static_cast<std::size_t>(cuts.count++)];
      cut.face = static_cast<std::int8_t>(face);
      cut.ambiguous = faceCase.crossings == 4;
      if (cut.ambiguous) continue;
      cut.a0 = static_cast<std::int8_t>(f[faceCase.down]);
      cut.b0 = static_cast<std::int8_t>(f[(faceCase.down + 1) & 3]);
      cut.a1 = static_cast<std::int8_t>(f[faceCase.up]);
      cut.b1 = static_cast<std::int8_t>(f[(faceCase.up + 1) & 3]);
    }
  }
  return table;
}();

/// The faces (bits of kFaces) that hold each edge (edgeId's numbering).
constexpr std::array<int, 12> kEdgeFaces = [] {
  std::array<int, 12> masks{};
  for (int a = 0; a < 8; ++a)
    for (int axisBit : {1, 2, 4}) {
      if (a & axisBit) continue;
      const int b = a | axisBit;
      int mask = 0;
      for (int f = 0; f < 6; ++f) {
        int found = 0;
        for (int c : kFaces[f]) found += c == a || c == b;
        mask |= (found == 2) << f;
      }
      masks[static_cast<std::size_t>(edgeId(a, b))] = mask;
    }
  return masks;
}();

/// The Jacobian's determinant at the cell's centre, from its points (the corners welded:
/// the array the edge crossings read too, where the cell's own corners would be one more
/// stream from memory).
/// Written per coordinate: as one Eigen expression of sixteen terms the sums were not
/// inlined and took 5 % of Marching Cubes on Reek (the same operations, in the same order).
double centreJacobian(const std::array<Vec3d, 8>& p) {
  Vec3d u, v, w;
  for (int i = 0; i < 3; ++i) {
    u[i] = 0.25 * (p[1][i] - p[0][i] + p[3][i] - p[2][i] + p[5][i] - p[4][i] + p[7][i] - p[6][i]);
    v[i] = 0.25 * (p[2][i] - p[0][i] + p[3][i] - p[1][i] + p[6][i] - p[4][i] + p[7][i] - p[5][i]);
    w[i] = 0.25 * (p[4][i] - p[0][i] + p[5][i] - p[1][i] + p[6][i] - p[2][i] + p[7][i] - p[3][i]);
  }
  return u.dot(v.cross(w));
}

/// Four times the cell's extent across `axis`: from the sum of the corners of its face on
/// the low side to that of the face on the high side.
template <int Axis>
Vec3d spanAcrossAxis(const std::array<Vec3d, 8>& p) {
  constexpr int kBit = 1 << Axis;
  Vec3d span = Vec3d::Zero();
  for (int c = 0; c < 8; ++c)
    if (c & kBit) span += p[static_cast<std::size_t>(c)] - p[static_cast<std::size_t>(c ^ kBit)];
  return span;
}
Vec3d spanAcross(const std::array<Vec3d, 8>& p, int axis) {
  // One loop per axis: with the axis a constant the tests fold away (2 % of Marching Cubes
  // on Reek with the axis a variable).
  return axis == 0 ? spanAcrossAxis<0>(p) : axis == 1 ? spanAcrossAxis<1>(p) : spanAcrossAxis<2>(p);
}

// A cell of zero thickness along one axis (a pinched layer): the cells on both
// sides share its points, so its surface would only double theirs.
bool collapsed(const CornerPointGrid& grid, std::size_t cell) {
  const auto& ids = grid.pointIds[cell];
  for (int axisBit : {1, 2, 4}) {
    bool all = true;
    for (int c = 0; c < 8 && all; ++c)
      if (!(c & axisBit)) all = ids[c] == ids[c | axisBit];
    if (all) return true;
  }
  return false;
}

/// How the cells around the cell's edge between corners `a` and `b` hold it.
/// - faultAxes (a bit per axis): the usable cell beside it across the face that holds the
///   edge on that axis holds other points there (a throw, or layers that do not meet). The
///   sheets of both sides end on the same pillar plane there and crossed each other (Reek:
///   19 of its 23 self-intersecting pairs); such crossings are moved off the face. An edge
///   the neighbour shares stays: its vertex is the neighbour's too.
/// - lone: the usable cells that hold the edge (the same two points) fall apart into groups
///   joined by whole shared faces, and this cell's group is not all of them: a cell diagonal
///   across the edge whose cells beside are across a fault or unusable, or a cell beside
///   that shares the edge but not the rest of the face. The groups' sheets met only at one
///   vertex there (non-manifold), so each group makes its own (kLoneEdgeKey), keyed by its
///   lowest cell and that cell's edge, and moves it off the faces its group does not share
///   (`apartAxes`).
struct EdgeSharing {
  int faultAxes = 0;
  bool lone = false;
  int apartAxes = 0;
  std::size_t groupCell = 0;
  int groupEdge = 0;
};

/// `ownFaces` remembers, per face of this cell (axis * 2 + side; -1 unknown), whether the
/// cell beside holds all of it: a cut cell asks for each face once, not once per crossing.
EdgeSharing edgeSharing(const CornerPointGrid& grid, const CornerField& field, const HexCell& cell, int a, int b,
                        std::array<std::int8_t, 6>& ownFaces) {
  const int edgeAxis = (a ^ b) == 1 ? 0 : (a ^ b) == 2 ? 1 : 2;
  const int p = (edgeAxis + 1) % 3, q = (edgeAxis + 2) % 3, flipP = 1 << p, flipQ = 1 << q;
  // The cells around the edge: 0 this one, 1 beside across p, 2 beside across q, 3 diagonal;
  // each one's corners are this cell's with `flips` toggled.
  std::array<std::size_t, 4> around{cell.index, cell.neighbour(p, (a >> p) & 1), cell.neighbour(q, (a >> q) & 1),
                                    HexCell::kNone};
  const std::array<int, 4> flips{0, flipP, flipQ, flipP | flipQ};
  const auto holds = [&](int n) {
    const auto& ids = grid.pointIds[around[static_cast<std::size_t>(n)]];
    const int flip = flips[static_cast<std::size_t>(n)];
    return ids[static_cast<std::size_t>(a ^ flip)] == cell.id(a) &&
           ids[static_cast<std::size_t>(b ^ flip)] == cell.id(b);
  };
  EdgeSharing sharing;
  std::array<bool, 4> held{true, false, false, false};
  // Whether cells n and m (around the edge, sharing a face: they differ by one flip) hold the
  // whole face between them.
  const auto shareFace = [&](int n, int m) {
    const int across = flips[static_cast<std::size_t>(n)] ^ flips[static_cast<std::size_t>(m)];
    const int axis = across == 1 ? 0 : across == 2 ? 1 : 2;
    const auto& from = grid.pointIds[around[static_cast<std::size_t>(n)]];
    const auto& to = grid.pointIds[around[static_cast<std::size_t>(m)]];
    const int side = ((a ^ flips[static_cast<std::size_t>(n)]) >> axis) & 1;  // n's face towards m
    for (int c = 0; c < 8; ++c)
      if (((c >> axis) & 1) == side && from[static_cast<std::size_t>(c)] != to[static_cast<std::size_t>(c ^ across)])
        return false;
    return true;
  };
  // This cell's group: the holders reached through whole shared faces (0-1, 0-2, 1-3, 2-3).
  // A group of three or four keeps the edge's own key (no other group can be as large, and
  // a lone one splits off by itself): inside a grid both cells beside share their faces, and
  // the diagonal cell is not read.
  // A face known to be shared whole holds the edge too: its cell is not read again.
  std::array<bool, 4> inGroup{true, false, false, false};
  for (const int n : {1, 2}) {
    if (around[static_cast<std::size_t>(n)] == HexCell::kNone) continue;
    const int axis = n == 1 ? p : q;
    std::int8_t& known = ownFaces[static_cast<std::size_t>(axis * 2 + ((a >> axis) & 1))];
    if (known == 1) {
      held[static_cast<std::size_t>(n)] = inGroup[static_cast<std::size_t>(n)] = true;
      continue;
    }
    held[static_cast<std::size_t>(n)] = holds(n);
    if (!held[static_cast<std::size_t>(n)]) {
      sharing.faultAxes |= 1 << axis;
      continue;
    }
    if (known < 0) known = shareFace(0, n) ? 1 : 0;
    inGroup[static_cast<std::size_t>(n)] = known == 1;
  }
  if (inGroup[1] && inGroup[2]) return sharing;
  std::array<int, 3> at = cell.ijk;
  bool inside = true;
  for (const int axis : {p, q}) {
    int& index = at[static_cast<std::size_t>(axis)];
    index += (a >> axis) & 1 ? 1 : -1;
    inside = inside && index >= 0 && index < grid.dims[static_cast<std::size_t>(axis)];
  }
  if (inside) {
    const std::size_t diagonal = grid.cellIndex(at[0], at[1], at[2]);
    if (field.usable[diagonal]) {
      around[3] = diagonal;
      held[3] = holds(3);
    }
  }
  for (int step = 0; step < 2; ++step)
    for (const auto& [n, m] : {std::pair{0, 1}, std::pair{0, 2}, std::pair{1, 3}, std::pair{2, 3}})
      if (held[static_cast<std::size_t>(n)] && held[static_cast<std::size_t>(m)] &&
          inGroup[static_cast<std::size_t>(n)] != inGroup[static_cast<std::size_t>(m)] && shareFace(n, m))
        inGroup[static_cast<std::size_t>(n)] = inGroup[static_cast<std::size_t>(m)] = true;
  if (inGroup == held || std::count(inGroup.begin(), inGroup.end(), true) >= 3) return sharing;
  sharing.lone = true;
  sharing.groupCell = cell.index;
  for (int n = 1; n < 4; ++n)
    if (inGroup[static_cast<std::size_t>(n)] && around[static_cast<std::size_t>(n)] < sharing.groupCell)
      sharing.groupCell = around[static_cast<std::size_t>(n)];
  for (int n = 0; n < 4; ++n)
    if (inGroup[static_cast<std::size_t>(n)] && around[static_cast<std::size_t>(n)] == sharing.groupCell)
      sharing.groupEdge = edgeId(a ^ flips[static_cast<std::size_t>(n)], b ^ flips[static_cast<std::size_t>(n)]);
  if (!inGroup[1]) sharing.apartAxes |= 1 << p;
  if (!inGroup[2]) sharing.apartAxes |= 1 << q;
  return sharing;
}

/// How deep points lie in a cell: over the three axes, the least of a point's distances to
/// the cell's two faces across the axis, as a fraction of the way between them (0.5 in the
/// middle, 0 on a face, negative outside). The faces are bilinear patches, taken at the
/// point's parameters along the other two axes (for a point on a straight segment between
/// two vertices: the mean of theirs, exact where the cell is affine); each is held as its
/// four bilinear coefficients, set up once per cell.
class CellDepth {
 public:
  /// Nothing set up (Eigen leaves the coefficients uninitialised): a cut cell sets it up
  /// only for a loop of four or more vertices. (As a std::optional, its 576 bytes were
  /// cleared for every cut cell: 1.5 % of Marching Cubes on Reek.)
  CellDepth() = default;
  bool ready() const { return ready_; }
  void setUp(const std::array<Vec3d, 8>& corners) {
    ready_ = true;
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side) {
        const int p = 1 << ((axis + 1) % 3), q = 1 << ((axis + 2) % 3), base = side << axis;
        const Vec3d &c00 = corners[base], &c10 = corners[base | p], &c01 = corners[base | q],
                    &c11 = corners[base | p | q];
        faces_[axis][side] = {c00, c10 - c00, c01 - c00, c11 - c10 - c01 + c00};
      }
  }

  double operator()(const Vec3d& at, const Vec3d& param) const {
    double depth = 0.5;
    for (int axis = 0; axis < 3; ++axis) {
      const double u = param[(axis + 1) % 3], v = param[(axis + 2) % 3];
      const auto point = [&](const std::array<Vec3d, 4>& f) { return Vec3d(f[0] + u * f[1] + v * (f[2] + u * f[3])); };
      const Vec3d low = point(faces_[axis][0]), across = point(faces_[axis][1]) - low;
      const double length2 = across.squaredNorm();
      if (!(length2 > 0)) continue;  // a pinched cell: no extent on this axis here
      const double w = (at - low).dot(across) / length2;
      depth = std::min({depth, w, 1 - w});
    }
    return depth;
  }

 private:
  std::array<std::array<std::array<Vec3d, 4>, 2>, 3> faces_;  // [axis][side]: c00, d/du, d/dv, d2/dudv
  bool ready_ = false;
};

}  // namespace

EdgeCrossing crossEdge(const CornerPointGrid& grid, const CornerField& field, double iso, std::uint32_t a,
                       std::uint32_t b) {
  if (a > b) std::swap(a, b);  // canonical order: identical result in every cell
  const double va = field.pointValues[a], vb = field.pointValues[b];
  EdgeCrossing crossing{(static_cast<std::uint64_t>(a) << 32) | b, a, b, std::clamp((iso - va) / (vb - va), 0.0, 1.0)};
  const Vec3d& pa = grid.points[a];
  const Vec3d& pb = grid.points[b];
  // A corner at the iso-value (FACIES 0/1 averaged to 0.5), or within rounding of it
  // (PORO 0.4 and 0.5 averaged to 0.45), counts as above it, as if its value were a
  // little higher: each edge from it to a corner below gets its own vertex a little
  // way along the edge. Vertices at (or a rounding error from) the corner made the
  // surfaces of neighbouring cells touch there, and fold over each other where a face
  // held two such corners. The offset must show in the float positions: where the
  // coordinates are too large for that (UTM grids), the edges share the corner's vertex.
  // The offset shows where one coordinate moves by at least 16 float steps: the edge's
  // best resolved axis (a vertical pillar edge of a UTM grid moves in depth, whose floats
  // are fine, though its easting and northing are coarse).
  double& t = crossing.t;
  // The float step above a finite non-negative float: its bit pattern plus one.
  const auto floatStep = [&](int axis) {
    const auto coordinate = static_cast<float>(std::max(std::abs(pa[axis]), std::abs(pb[axis])));
    return std::bit_cast<float>(std::bit_cast<std::uint32_t>(coordinate) + 1) - static_cast<double>(coordinate);
  };
  // Most crossings lie well inside their edge: where one axis alone holds the offset
  // below kMaxCornerOffset (16 steps a good deal shorter than a fiftieth of the edge along
  // it) and t is that far from both ends, nothing below changes t: the three divisions
  // are skipped for most crossings, and the result is the same, bit for bit. Any axis will
  // do, not only the edge's longest: on a UTM grid such as Reek's the northing's float
  // steps are half a metre, and edges along it passed the test only on another axis
  // (crossEdge 10 -> 6 % of Marching Cubes there).
  if (t >= kMaxCornerOffset && t <= 1.0 - kMaxCornerOffset)
    for (int axis = 0; axis < 3; ++axis)
      if (16.0 * floatStep(axis) < 0.5 * kMaxCornerOffset * std::abs(pb[axis] - pa[axis])) return crossing;
  double offset = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double along = std::abs(pb[axis] - pa[axis]);
    if (!(along > 0)) continue;
    offset = std::min(offset, std::max(kCornerOffset, 16.0 * floatStep(axis) / along));
  }
  if (t < offset || t > 1.0 - offset) {
    crossing.nearCorner = true;
    if (offset <= kMaxCornerOffset) {
      t = std::clamp(t, offset, 1.0 - offset);
    } else {  // within 16 float steps of the corner: the corner itself
      t = t < 0.5 ? 0.0 : 1.0;
      crossing.key = kCornerKey | (t == 0.0 ? a : b);
    }
  }
  return crossing;
}

Vec3d crossingPoint(const CornerPointGrid& grid, const EdgeCrossing& crossing) {
  const Vec3d& pa = grid.points[crossing.from];
  const Vec3d& pb = grid.points[crossing.to];
  return pa + crossing.t * (pb - pa);
}

Eigen::Vector3f crossingPosition(const CornerPointGrid& grid, const EdgeCrossing& crossing) {
  return crossingPoint(grid, crossing).cast<float>();
}

void contourCell(const CornerPointGrid& grid, const CornerField& field, std::size_t cell, const std::array<int, 3>& ijk,
                 const HexContourOptions& options, ThreadOutput& out, BlockOutput& block) {
  const auto& ids = grid.pointIds[cell];
  std::array<double, 8> g;
  std::array<bool, 8> above;
  int cellCase = 0;  // bit c: corner c above
  for (int c = 0; c < 8; ++c) {
    g[c] = field.pointValues[ids[c]] - options.iso;
    above[c] = g[c] >= 0;
    cellCase |= above[c] << c;
  }
  if (cellCase == 0 || cellCase == 255) return;
  if (collapsed(grid, cell)) return;
  ++block.cutCells;
  const HexCell hex(grid, field, cell, ijk);
  // The most a cell makes: a vertex per edge, a centre per loop (at most four) and a face
  // point per segment; two triangles per segment.
  growHuge(out.keys, 28);
  if (options.normals) growHuge(out.gradients, 28);
  growHuge(out.centres, 4);
  growHuge(out.placedPoints, 24);
  growHuge(out.triangles, 24);

  // Segments: next[start edge] = end edge, from an above->below crossing to a below->above one.
  std::array<int, 12> next, linkFace;
  std::array<std::array<int, 2>, 12> edgeCorners;  // set by link() for each edge it joins
  next.fill(-1);
  linkFace.fill(-1);
  int face = 0;                                      // the face whose segments are being linked
  auto link = [&](int a0, int b0, int a1, int b1) {  // crossing (a0,b0) -> crossing (a1,b1)
    const int from = kEdgeIds[static_cast<std::size_t>(a0)][static_cast<std::size_t>(b0)];
    const int to = kEdgeIds[static_cast<std::size_t>(a1)][static_cast<std::size_t>(b1)];
    next[from] = to;
    linkFace[from] = face;
    edgeCorners[from] = {a0, b0};
    edgeCorners[to] = {a1, b1};
  };
  const CellCuts& cuts = kCellCuts[static_cast<std::size_t>(cellCase)];
  for (int i = 0; i < cuts.count; ++i) {
    const FaceCut& cut = cuts.faces[static_cast<std::size_t>(i)];
    face = cut.face;
    if (!cut.ambiguous) {
      link(cut.a0, cut.b0, cut.a1, cut.b1);
    } else {
      const auto& f = kFaces[face];
      ++block.ambiguousFaces;
      const double a = g[f[0]], b = g[f[1]], c = g[f[2]], d = g[f[3]];
      const double denominator = a + c - b - d;
      const double saddle = denominator != 0 ? (a * c - b * d) / denominator : 0.25 * (a + b + c + d);
      const bool saddleAbove = saddle >= 0;
      // Cut off the corners of the class the saddle does not belong to.
      for (int e = 0; e < 4; ++e) {
        const int corner = f[e];
        if (above[corner] == saddleAbove) continue;
        const int prev = f[(e + 3) % 4], nxt = f[(e + 1) % 4];
        // Edges (prev, corner) and (corner, nxt), oriented by the above->below rule.
        if (above[corner])
          link(corner, nxt, prev, corner);
        else
          link(prev, corner, corner, nxt);
      }
    }
  }

  const double det = centreJacobian(hex.points);
  CellDepth depthIn;  // set up for the first loop of four or more vertices
  // A corner's gradient serves each of its edges that the surface crosses (up to three).
  std::array<Vec3d, 8> gradientAt;
  std::uint8_t gradientKnown = 0;
  auto gradientOf = [&](int corner) -> const Vec3d& {
    if (!(gradientKnown >> corner & 1)) {
      gradientAt[static_cast<std::size_t>(corner)] = cornerGradient(grid, field, hex, corner);
      gradientKnown |= static_cast<std::uint8_t>(1 << corner);
    }
    return gradientAt[static_cast<std::size_t>(corner)];
  };
  const bool flip = det < 0 || (det == 0 && grid.orientation < 0);
  // From a fault face's centre to the cell's: the side its crossings move to.
  const auto intoCell = [&](int axis, int side) {
    Vec3d cellCentre = Vec3d::Zero(), faceCentre = Vec3d::Zero();
    for (int c = 0; c < 8; ++c) {
      cellCentre += hex.points[c];
      if (((c >> axis) & 1) == side) faceCentre += hex.points[c];
    }
    return Vec3d(cellCentre / 8 - faceCentre / 4);
  };
  const std::size_t cellFirst = out.keys.size();
  const auto firstVertex = static_cast<std::uint32_t>(cellFirst - block.firstKey);  // the block's numbering
  std::array<EdgeCrossing, 12> crossingOf;
  std::array<std::int8_t, 6> ownFaces;  // edgeSharing's memo of this cell's shared faces
  ownFaces.fill(-1);
  std::array<int, 12> vertexOf;
  vertexOf.fill(-1);
  auto vertex = [&](int edge) {
    if (vertexOf[edge] >= 0) return vertexOf[edge];
    int a = edgeCorners[edge][0], b = edgeCorners[edge][1];
    if (ids[a] > ids[b]) std::swap(a, b);  // crossEdge's order
    EdgeCrossing crossing = crossEdge(grid, field, options.iso, ids[a], ids[b]);
    const EdgeSharing sharing = edgeSharing(grid, field, hex, a, b, ownFaces);
    const bool lone = sharing.lone && !(crossing.key & kCornerKey);
    if (lone) {
      crossing.key = kLoneEdgeKey | (static_cast<std::uint64_t>(sharing.groupCell) << 4) |
                     static_cast<std::uint64_t>(sharing.groupEdge);
      out.placedPoints.emplace_back(crossing.key, crossingPosition(grid, crossing));
    }
    crossingOf[edge] = crossing;
    out.keys.push_back(crossing.key);
    // Off fault faces (edgeSharing); not those within kMaxCornerOffset of a corner, whose
    // neighbours on the corner's other edges lie as close: moved, they met them (Emerald
    // FACIES 0.5, crossings held off a corner at the iso-value: 8 zero-area triangles), or
    // crossed the line to the loop's far vertex and folded the fan (Reek PORO 0.1 and 0.18:
    // crossings 0.3 % of their edges from a corner moved 1.5 m; over kFaceWarp's sweep,
    // 8 -> 6 pairs away from pinched cells, the same triangles). A lone crossing moves
    // wherever it lies: unmoved, it would touch the diagonal cell's at one place (ResInsight's
    // GRID.GRDECL with a smooth property at 0.28: one pair).
    if (lone || (!crossing.nearCorner && std::min(crossing.t, 1 - crossing.t) >= kMaxCornerOffset)) {
      Vec3d side = Vec3d::Zero();
      for (int axis = 0; axis < 3; ++axis)  // the edge's two faces, across the other two axes
        if (!(((a ^ b) >> axis) & 1) && (lone ? (sharing.apartAxes >> axis & 1) : (sharing.faultAxes >> axis & 1)))
          side += intoCell(axis, (a >> axis) & 1);
      if (side != Vec3d::Zero()) {
        growHuge(out.faultSides, 1);
        out.faultSides.emplace_back(crossing.key, side);
      }
    }
    if (options.normals) {
      const double t = crossing.t;
      out.gradients.push_back((1 - t) * gradientOf(a) + t * gradientOf(b));
    }
    vertexOf[edge] = static_cast<int>(out.keys.size() - 1 - cellFirst);
    return vertexOf[edge];
  };
  // Faces holding each cell edge: a fan diagonal between two crossings of one face
  // would coincide with the neighbour cell's diagonal (an edge of four triangles).
  const auto faceMask = [](int edge) { return kEdgeFaces[static_cast<std::size_t>(edge)]; };
  auto emit = [&](int a, int b, int c) {
    std::array<std::uint32_t, 3> tri{firstVertex + a, firstVertex + c, firstVertex + b};  // faces towards lower values
    if (flip) std::swap(tri[1], tri[2]);
    out.triangles.push_back(tri);
    if (options.triangleCells) {
      growHuge(out.triangleCells, 1);
      out.triangleCells.push_back(static_cast<std::uint32_t>(cell));
    }
  };
  // Face points (kFaceWarp). The chord between two crossings at face parameters (u1, v1) and
  // (u2, v2) runs |T . n| |(u1 - u2)(v1 - v2)| / 4 off the patch at its middle, T the twist
  // c00 + c11 - c10 - c01 and n the unit normal: a segment gets a face point where that
  // exceeds kFaceWarp times the thickness of both cells of the face (this cell's first, so
  // that the neighbour's points are read only for twisted faces). Both cells see the same
  // points, parameters and thicknesses, so they decide alike. A fault face (the cell
  // across holds other points) keeps its own scheme (edgeSharing); a pinched cell's faces meet,
  // and their face points would be different vertices at one place.
  // Set on a face's first use (faceBowKnown): filling all six for every cut cell cost 1 %.
  struct FaceBow {
    bool candidate;
    double twist2;        // (T . N)^2, N the unnormalised centre normal
    double scale;         // kFaceWarp^2 |N|^2
    double thisScaled;    // scale |span|^2 of this cell (span: 4x its thickness)
    double acrossScaled;  // the same for the cell across, once needed (-1 before)
    std::size_t neighbour;
  };
  std::array<FaceBow, 6> faceBows;
  int faceBowKnown = 0;  // a bit per face
  const auto faceBow = [&](int f) -> FaceBow& {
    FaceBow& b = faceBows[static_cast<std::size_t>(f)];
    if (faceBowKnown >> f & 1) return b;
    faceBowKnown |= 1 << f;
    b = {false, 0, 0, 0, -1, HexCell::kNone};
    if (grid.cellShape[cell] & CornerPointGrid::kPinchedCell) return b;
    const int axis = f >> 1, side = f & 1, bit = 1 << axis;
    const int p = 1 << ((axis + 1) % 3), q = 1 << ((axis + 2) % 3), base = side << axis;
    const Vec3d& c00 = hex.points[static_cast<std::size_t>(base)];
    const Vec3d& c10 = hex.points[static_cast<std::size_t>(base | p)];
    const Vec3d& c01 = hex.points[static_cast<std::size_t>(base | q)];
    const Vec3d& c11 = hex.points[static_cast<std::size_t>(base | p | q)];
    const Vec3d normal = Vec3d(c10 - c00 + c11 - c01).cross(Vec3d(c01 - c00 + c11 - c10));
    const double twist = Vec3d(c00 + c11 - c10 - c01).dot(normal);
    b.twist2 = twist * twist;
    b.scale = kFaceWarp * kFaceWarp * normal.squaredNorm();
    b.thisScaled = b.scale * spanAcross(hex.points, axis).squaredNorm();
    // A segment's chord runs at most the patch centre's bow off it (|du dv| <= 1): on a face
    // that bows less than the fraction of this cell's thickness, no segment gets a point.
    if (!(b.twist2 > b.thisScaled)) return b;
    b.neighbour = hex.neighbour(axis, side);
    if (b.neighbour != HexCell::kNone) {
      // A layer of zero thickness between (collapsed) makes no surface: the cells on its far
      // side would key the face point from another face, two vertices in one place.
      if (grid.cellShape[b.neighbour] & CornerPointGrid::kPinchedCell || collapsed(grid, b.neighbour)) return b;
      const auto& across = grid.pointIds[b.neighbour];
      for (const int c : {base, base | p, base | q, base | p | q})
        if (across[static_cast<std::size_t>(c ^ bit)] != ids[static_cast<std::size_t>(c)]) return b;
    }
    b.candidate = true;
    return b;
  };
  // The face parameters (u along the face's first other axis, v along its second) of the
  // crossing on `edge`, an edge of face f: the same values in both cells of the face.
  const auto faceParameters = [&](int edge, int f) {
    const int axis = f >> 1, p = (axis + 1) % 3, q = (axis + 2) % 3;
    const EdgeCrossing& crossing = crossingOf[static_cast<std::size_t>(edge)];
    const int a = edgeCorners[edge][0], b = edgeCorners[edge][1];
    const int along = (a ^ b) == (1 << p) ? p : q;  // the edge's axis in the face
    const int low = (a >> along) & 1 ? b : a;       // its end at the axis' low side
    const double t = ids[static_cast<std::size_t>(low)] == crossing.from ? crossing.t : 1 - crossing.t;
    return std::array<double, 2>{along == p ? t : static_cast<double>((low >> p) & 1),
                                 along == q ? t : static_cast<double>((low >> q) & 1)};
  };
  // Whether the segment from crossing `edge` to crossing next[edge] gets a face point.
  const auto twistedSegment = [&](int edge) {
    const int f = linkFace[edge];
    FaceBow& b = faceBow(f);
    if (!b.candidate) return false;
    const std::array<double, 2> from = faceParameters(edge, f), to = faceParameters(next[edge], f);
    const double area = (from[0] - to[0]) * (from[1] - to[1]);
    const double off2 = b.twist2 * area * area;
    if (!(off2 > b.thisScaled)) return false;
    if (b.neighbour == HexCell::kNone) return true;
    if (b.acrossScaled < 0) {
      // The neighbour's points: this face's, and its far face's read from the grid (the
      // same values its own contouring holds, so both cells decide alike).
      const int axis = f >> 1, side = f & 1, bit = 1 << axis;
      const auto& across = grid.pointIds[b.neighbour];
      std::array<Vec3d, 8> acrossPoints;
      for (int c = 0; c < 8; ++c)
        acrossPoints[static_cast<std::size_t>(c)] = ((c >> axis) & 1) != side
                                                        ? hex.points[static_cast<std::size_t>(c ^ bit)]
                                                        : grid.points[across[static_cast<std::size_t>(c)]];
      b.acrossScaled = b.scale * spanAcross(acrossPoints, axis).squaredNorm();
    }
    return off2 > b.acrossScaled;
  };
  const auto edgeKeyOf = [&](int edge) {
    const std::uint32_t a = ids[static_cast<std::size_t>(edgeCorners[edge][0])];
    const std::uint32_t b = ids[static_cast<std::size_t>(edgeCorners[edge][1])];
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
  };
  // The face point of the segment from crossing `edge` to crossing next[edge] (both made by
  // vertex()): the face's bilinear patch at the mean of the two crossings' face parameters.
  // Key and position come out the same in both cells of the face: the face is keyed from
  // the lower cell, its segments (two on a face with four crossings) by their least edge
  // key, and the patch is evaluated in the face's own frame from the points' ids.
  const auto facePoint = [&](int edge) {
    const int f = linkFace[edge], axis = f >> 1, side = f & 1;
    const auto segmentKey = [&](int e) { return std::min(edgeKeyOf(e), edgeKeyOf(next[e])); };
    std::uint64_t segment = 0;
    for (int e = 0; e < 12; ++e)
      if (e != edge && linkFace[e] == f && segmentKey(e) < segmentKey(edge)) segment = 1;
    const std::size_t neighbour = hex.neighbour(axis, side);
    const bool neighbourOwns = neighbour != HexCell::kNone && neighbour < cell;
    const std::uint64_t key = kFaceKey | (static_cast<std::uint64_t>(neighbourOwns ? neighbour : cell) << 4) |
                              (static_cast<std::uint64_t>(neighbourOwns ? f ^ 1 : f) << 1) | segment;
    const int p = (axis + 1) % 3, q = (axis + 2) % 3, base = side << axis;
    const std::array<double, 2> from = faceParameters(edge, f), to = faceParameters(next[edge], f);
    const double u = 0.5 * from[0] + 0.5 * to[0], v = 0.5 * from[1] + 0.5 * to[1];
    const Vec3d& c00 = hex.points[static_cast<std::size_t>(base)];
    const Vec3d& c10 = hex.points[static_cast<std::size_t>(base | 1 << p)];
    const Vec3d& c01 = hex.points[static_cast<std::size_t>(base | 1 << q)];
    const Vec3d& c11 = hex.points[static_cast<std::size_t>(base | 1 << p | 1 << q)];
    const Vec3d at = c00 + u * (c10 - c00) + v * (Vec3d(c01 - c00) + u * Vec3d(c11 - c10 - c01 + c00));
    out.placedPoints.emplace_back(key, at.cast<float>());
    out.keys.push_back(key);
    if (options.normals)
      out.gradients.push_back(0.5 * (out.gradients[cellFirst + static_cast<std::size_t>(vertexOf[edge])] +
                                     out.gradients[cellFirst + static_cast<std::size_t>(vertexOf[next[edge]])]));
    return static_cast<int>(out.keys.size() - 1 - cellFirst);
  };
  std::array<bool, 12> visited{};
  int loopIndex = 0;
  for (int start = 0; start < 12; ++start) {
    if (next[start] < 0 || visited[start]) continue;
    std::array<int, 12> edges;
    std::size_t edgeCount = 0;
    for (int e = start; !visited[e]; e = next[e]) {
      visited[e] = true;
      edges[edgeCount++] = e;
    }
    for (std::size_t i = 0; i < edgeCount; ++i) vertex(edges[i]);
    // The loop's vertices: its crossings, each followed by a face point where its segment
    // lies on a twisted face (kFaceWarp). Per vertex: the faces it lies on (a fan diagonal
    // between two vertices of one face would run along it, where the neighbour's fan could
    // put the same edge), its parameters in the cell and its position.
    // Written up to n before they are read (left uninitialised: clearing them per loop cost 4 %).
    std::array<int, 24> loop, faces, edgeOf;  // edgeOf: the crossing's edge, or the segment's first
    std::array<bool, 24> isFacePoint;
    std::array<Eigen::Vector3f, 24> facePosition;
    std::size_t n = 0;
    for (std::size_t i = 0; i < edgeCount; ++i) {
      const int edge = edges[i];
      edgeOf[n] = edge;
      isFacePoint[n] = false;
      loop[n] = vertexOf[edge];
      faces[n++] = faceMask(edge);
      if (twistedSegment(edge)) {
        edgeOf[n] = edge;
        isFacePoint[n] = true;
        loop[n] = facePoint(edge);
        facePosition[n] = out.placedPoints.back().second;
        faces[n++] = 1 << linkFace[edge];
      }
    }
    const auto crossingParam = [&](int edge) {
      const EdgeCrossing& crossing = crossingOf[static_cast<std::size_t>(edge)];
      const int a = edgeCorners[edge][0], b = edgeCorners[edge][1];
      const double t = ids[static_cast<std::size_t>(a)] == crossing.from ? crossing.t : 1 - crossing.t;
      return Vec3d(cornerParameters(a) + t * (cornerParameters(b) - cornerParameters(a)));
    };
    // Parameters and positions of the vertices, for the fans' depths (loops of four or more).
    std::array<Vec3d, 24> at, param;
    if (n > 3)
      for (std::size_t i = 0; i < n; ++i) {
        const int edge = edgeOf[i];
        if (isFacePoint[i]) {
          param[i] = 0.5 * (crossingParam(edge) + crossingParam(next[edge]));
          at[i] = facePosition[i].cast<double>();
        } else {
          param[i] = crossingParam(edge);
          at[i] = crossingPoint(grid, crossingOf[static_cast<std::size_t>(edge)]);
        }
      }
    // A fan apex whose diagonals leave every face, else a centre vertex inside the cell.
    // Of several apexes, the one whose diagonals stay deepest in the cell: a cell's faces
    // are bilinear patches, and in a thin cell with twisted faces a diagonal can leave the
    // cell and cross the sheet of the cell next to it (Reek: 3 m layers whose faces twist
    // by 7 m over 230 m; the first apex in loop order left 10, 11 and 20 crossing pairs at
    // PORO 0.15, 0.2 and 0.25). Where the best fan's diagonals leave the cell or come within
    // kFanDepthForCentre of a face and a centre vertex stays deeper, the centre.
    // A triangle is its own fan (the search below would choose its first vertex).
    if (n == 3) {
      emit(loop[0], loop[1], loop[2]);
      ++loopIndex;
      continue;
    }
    if (!depthIn.ready()) depthIn.setUp(hex.points);
    // Vertex i of the loop, i < 2n (std::size_t's % by a variable n cost a division).
    const auto wrap = [n](std::size_t i) { return i >= n ? i - n : i; };
    int apex = -1;
    double apexDepth = -std::numeric_limits<double>::infinity();
    // A diagonal serves the fans of both its ends (a quad's two diagonals, its four
    // apexes): its depth is evaluated once. (at[a] + at[d] is at[d] + at[a], bit for bit.)
    std::array<std::array<double, 24>, 24> diagonalDepth;
    std::array<std::uint32_t, 24> diagonalKnown{};
    const auto depthOfDiagonal = [&](std::size_t a, std::size_t d) {
      if (!(diagonalKnown[a] >> d & 1)) {
        diagonalDepth[a][d] = diagonalDepth[d][a] = depthIn(0.5 * (at[a] + at[d]), 0.5 * (param[a] + param[d]));
        diagonalKnown[a] |= 1U << d;
        diagonalKnown[d] |= 1U << a;
      }
      return diagonalDepth[a][d];
    };
    for (std::size_t a = 0; a < n; ++a) {
      bool ok = true;
      for (std::size_t m = 2; m + 1 < n && ok; ++m) ok = (faces[a] & faces[wrap(a + m)]) == 0;
      if (!ok) continue;
      // The least depth stops as soon as it cannot beat the best apex so far (the choice is
      // the same, with fewer diagonals evaluated).
      double depth = std::numeric_limits<double>::infinity();
      for (std::size_t m = 2; m + 1 < n && depth > apexDepth + 1e-9; ++m)
        depth = std::min(depth, depthOfDiagonal(a, wrap(a + m)));
      if (depth > apexDepth + 1e-9) {  // near ties: the first in loop order, as before
        apex = static_cast<int>(a);
        apexDepth = depth;
      }
    }
    if (apex >= 0 && apexDepth < kFanDepthForCentre) {
      Vec3d centre = Vec3d::Zero(), centreParam = Vec3d::Zero();
      for (std::size_t i = 0; i < n; ++i) {
        centre += at[i] / static_cast<double>(n);
        centreParam += param[i] / static_cast<double>(n);
      }
      double depth = depthIn(centre, centreParam);
      for (std::size_t i = 0; i < n && depth > apexDepth + 1e-9; ++i)  // (stops where the fan wins)
        depth = std::min(depth, depthIn(0.5 * (centre + at[i]), 0.5 * (centreParam + param[i])));
      if (depth > apexDepth + 1e-9) apex = -1;
    }
    if (apex >= 0) {
      for (std::size_t m = 1; m + 1 < n; ++m) emit(loop[apex], loop[wrap(apex + m)], loop[wrap(apex + m + 1)]);
    } else {
      const std::uint64_t key = kCentreKey | (static_cast<std::uint64_t>(cell) << 4) | loopIndex;
      Eigen::Vector3f sum = Eigen::Vector3f::Zero();
      Vec3d gradient = Vec3d::Zero();
      for (std::size_t m = 0; m < n; ++m) {
        sum +=
            isFacePoint[m] ? facePosition[m] : crossingPosition(grid, crossingOf[static_cast<std::size_t>(edgeOf[m])]);
        if (options.normals) gradient += out.gradients[cellFirst + static_cast<std::size_t>(loop[m])];
      }
      out.centres.emplace_back(key, sum / static_cast<float>(n));
      const int c = static_cast<int>(out.keys.size() - cellFirst);
      out.keys.push_back(key);
      if (options.normals) out.gradients.push_back(gradient / static_cast<double>(n));
      for (std::size_t m = 0; m < n; ++m) emit(c, loop[m], loop[wrap(m + 1)]);
    }
    ++loopIndex;
  }
}

}  // namespace isovdb::reservoir::hex
