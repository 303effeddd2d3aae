// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/reservoir/hex_marching_cubes.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>
#include <span>
#include <stdexcept>

#include "isovdb/huge_pages.h"
#include "isovdb/reservoir/jacobian_normals.h"

namespace isovdb::reservoir {
namespace {

// Faces as corner cycles, counter-clockwise seen from outside (right-handed parameter space).
/// Where a corner lies exactly at the iso-value, the vertices of its edges sit this
/// fraction of the edge away from it (at least 16 float steps of the coordinates).
constexpr double kCornerOffset = 1e-3;
/// Beyond this fraction the offset would move the surface visibly: the corner is shared.
constexpr double kMaxCornerOffset = 0.02;

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

/// What the cells of one thread make, block after block. A vertex is recorded by its weld
/// key alone, once per cell that makes it; positions are computed once per distinct vertex
/// after welding (they depend on the key only), so the records stay small. The arrays grow
/// into huge pages (huge_pages.h): on a virtual machine a 4 KiB page fault costs
/// microseconds, and vectors per block, grown by doubling, faulted in twice their size and
/// took as long as the contouring itself on a first run.
struct ThreadOutput {
  std::vector<std::uint64_t> keys;                                 // one per vertex a cell makes
  std::vector<Vec3d> gradients;                                    // beside keys (with normals)
  std::vector<std::pair<std::uint64_t, Eigen::Vector3f>> centres;  // centre vertices' positions
  std::vector<std::array<std::uint32_t, 3>> triangles;             // into keys, from its block's first
  std::vector<std::pair<std::uint64_t, Vec3d>> faultSides;         // crossings on fault faces (faultFaces)
};

/// What a block of consecutive cells made: where it lies in its thread's arrays.
struct BlockOutput {
  const ThreadOutput* thread = nullptr;
  std::size_t firstKey = 0, keyCount = 0, firstCentre = 0, centreCount = 0, firstTriangle = 0, triangleCount = 0,
              firstFaultSide = 0, faultSideCount = 0;
  std::int64_t cutCells = 0;
  int ambiguousFaces = 0;

  std::span<const std::uint64_t> keys() const { return {thread->keys.data() + firstKey, keyCount}; }
  std::span<const Vec3d> gradients() const { return {thread->gradients.data() + firstKey, keyCount}; }
  std::span<const std::pair<std::uint64_t, Eigen::Vector3f>> centres() const {
    return {thread->centres.data() + firstCentre, centreCount};
  }
  std::span<const std::array<std::uint32_t, 3>> triangles() const {
    return {thread->triangles.data() + firstTriangle, triangleCount};
  }
  std::span<const std::pair<std::uint64_t, Vec3d>> faultSides() const {
    return {thread->faultSides.data() + firstFaultSide, faultSideCount};
  }
};

/// Weld keys: an edge crossing is keyed by its edge's two point ids (lower first); these
/// bits mark the other two kinds.
constexpr std::uint64_t kCornerKey = std::uint64_t{1} << 62;  ///< the vertex is a grid point
constexpr std::uint64_t kCentreKey = std::uint64_t{1} << 63;  ///< a loop's centre inside a cell

/// Where the surface crosses the edge between points `a` and `b`: its weld key and its
/// place `t` along the edge from the lower id. The same in every cell that holds the edge.
struct EdgeCrossing {
  std::uint64_t key;
  std::uint32_t from, to;  ///< point ids, from < to
  double t;
  bool nearCorner = false;  ///< t held off a corner at (or a rounding error from) the iso-value
};

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
  double offset = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double along = std::abs(pb[axis] - pa[axis]);
    if (!(along > 0)) continue;
    const auto coordinate = static_cast<float>(std::max(std::abs(pa[axis]), std::abs(pb[axis])));
    // The float step above a finite non-negative float: its bit pattern plus one.
    const double ulp = std::bit_cast<float>(std::bit_cast<std::uint32_t>(coordinate) + 1) - coordinate;
    offset = std::min(offset, std::max(kCornerOffset, 16.0 * ulp / along));
  }
  double& t = crossing.t;
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

Eigen::Vector3f crossingPosition(const CornerPointGrid& grid, const EdgeCrossing& crossing) {
  const Vec3d& pa = grid.points[crossing.from];
  const Vec3d& pb = grid.points[crossing.to];
  return (pa + crossing.t * (pb - pa)).cast<float>();
}

/// Cells per block: blocks are the unit of parallel work and their outputs are merged in
/// order, so the mesh does not depend on the thread count.
constexpr std::size_t kBlockCells = 4096;

/// The Jacobian's determinant at the cell's centre, from its points (the corners welded:
/// the array the edge crossings read too, where the cell's own corners would be one more
/// stream from memory).
double centreJacobian(const CornerPointGrid& grid, const std::array<std::uint32_t, 8>& ids) {
  std::array<Vec3d, 8> p;
  for (int c = 0; c < 8; ++c) p[c] = grid.points[ids[c]];
  const Vec3d u = 0.25 * (p[1] - p[0] + p[3] - p[2] + p[5] - p[4] + p[7] - p[6]);
  const Vec3d v = 0.25 * (p[2] - p[0] + p[3] - p[1] + p[6] - p[4] + p[7] - p[5]);
  const Vec3d w = 0.25 * (p[4] - p[0] + p[5] - p[1] + p[6] - p[2] + p[7] - p[3]);
  return u.dot(v.cross(w));
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

/// Whether the cell's edge between corners `a` and `b` lies on a fault across the face
/// that holds it on `axis` (the face on the corners' side): the neighbour across is usable
/// but holds other points there (a throw, or layers that do not meet). The sheets of both
/// sides end on the same pillar plane there and crossed each other (Reek: 19 of its 23
/// self-intersecting pairs); such crossings are moved off the face. An edge the neighbour
/// shares stays: its vertex is the neighbour's too.
bool onFault(const CornerPointGrid& grid, const CornerField& field, std::size_t cell, const std::array<int, 3>& ijk,
             int a, int b, int axis) {
  const int side = (a >> axis) & 1;
  std::array<int, 3> n = ijk;
  n[axis] += side ? 1 : -1;
  if (n[axis] < 0 || n[axis] >= grid.dims[axis]) return false;
  const std::size_t neighbour = grid.cellIndex(n[0], n[1], n[2]);
  if (!field.usable[neighbour]) return false;
  const auto& ids = grid.pointIds[cell];
  const auto& across = grid.pointIds[neighbour];
  return across[a ^ (1 << axis)] != ids[a] || across[b ^ (1 << axis)] != ids[b];
}

void contourCell(const CornerPointGrid& grid, const CornerField& field, std::size_t cell, const std::array<int, 3>& ijk,
                 const HexContourOptions& options, ThreadOutput& out, BlockOutput& block) {
  const auto& ids = grid.pointIds[cell];
  std::array<double, 8> g;
  std::array<bool, 8> above;
  int aboveCount = 0;
  for (int c = 0; c < 8; ++c) {
    g[c] = field.pointValues[ids[c]] - options.iso;
    above[c] = g[c] >= 0;
    aboveCount += above[c];
  }
  if (aboveCount == 0 || aboveCount == 8) return;
  if (collapsed(grid, cell)) return;
  ++block.cutCells;
  // The most a cell makes: a vertex per edge and a centre per loop (at most four), a
  // triangle per loop edge.
  growHuge(out.keys, 16);
  if (options.normals) growHuge(out.gradients, 16);
  growHuge(out.centres, 4);
  growHuge(out.triangles, 12);

  // Segments: next[start edge] = end edge, from an above->below crossing to a below->above one.
  std::array<int, 12> next;
  std::array<std::array<int, 2>, 12> edgeCorners{};
  next.fill(-1);
  auto link = [&](int a0, int b0, int a1, int b1) {  // crossing (a0,b0) -> crossing (a1,b1)
    const int from = edgeId(a0, b0), to = edgeId(a1, b1);
    next[from] = to;
    edgeCorners[from] = {a0, b0};
    edgeCorners[to] = {a1, b1};
  };
  for (const auto& f : kFaces) {
    int crossings = 0;
    for (int e = 0; e < 4; ++e) crossings += above[f[e]] != above[f[(e + 1) % 4]];
    if (crossings == 2) {
      int down = -1, up = -1;  // edge positions (CCW) where the sign goes above->below / below->above
      for (int e = 0; e < 4; ++e) {
        const int a = f[e], b = f[(e + 1) % 4];
        if (above[a] && !above[b]) down = e;
        if (!above[a] && above[b]) up = e;
      }
      link(f[down], f[(down + 1) % 4], f[up], f[(up + 1) % 4]);
    } else if (crossings == 4) {
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

  const double det = centreJacobian(grid, ids);
  // A corner's gradient serves each of its edges that the surface crosses (up to three).
  std::array<Vec3d, 8> gradientAt;
  std::uint8_t gradientKnown = 0;
  auto gradientOf = [&](int corner) -> const Vec3d& {
    if (!(gradientKnown >> corner & 1)) {
      gradientAt[static_cast<std::size_t>(corner)] = cornerGradient(grid, field, cell, ijk, corner);
      gradientKnown |= static_cast<std::uint8_t>(1 << corner);
    }
    return gradientAt[static_cast<std::size_t>(corner)];
  };
  const bool flip = det < 0 || (det == 0 && grid.orientation < 0);
  // From a fault face's centre to the cell's: the side its crossings move to.
  const auto intoCell = [&](int axis, int side) {
    Vec3d cellCentre = Vec3d::Zero(), faceCentre = Vec3d::Zero();
    for (int c = 0; c < 8; ++c) {
      cellCentre += grid.points[ids[c]];
      if (((c >> axis) & 1) == side) faceCentre += grid.points[ids[c]];
    }
    return Vec3d(cellCentre / 8 - faceCentre / 4);
  };
  const std::size_t cellFirst = out.keys.size();
  const auto firstVertex = static_cast<std::uint32_t>(cellFirst - block.firstKey);  // the block's numbering
  std::array<EdgeCrossing, 12> crossingOf;
  std::array<int, 12> vertexOf;
  vertexOf.fill(-1);
  auto vertex = [&](int edge) {
    if (vertexOf[edge] >= 0) return vertexOf[edge];
    int a = edgeCorners[edge][0], b = edgeCorners[edge][1];
    if (ids[a] > ids[b]) std::swap(a, b);  // crossEdge's order
    const EdgeCrossing crossing = crossEdge(grid, field, options.iso, ids[a], ids[b]);
    crossingOf[edge] = crossing;
    out.keys.push_back(crossing.key);
    // Off fault faces (onFault); not those held a little way off a corner at the iso-value,
    // whose neighbours on the corner's other edges lie as close (Emerald FACIES 0.5: moved,
    // they met them: 8 zero-area triangles).
    if (!crossing.nearCorner) {
      Vec3d side = Vec3d::Zero();
      for (int axis = 0; axis < 3; ++axis)  // the edge's two faces, across the other two axes
        if (!(((a ^ b) >> axis) & 1) && onFault(grid, field, cell, ijk, a, b, axis))
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
  };
  std::array<bool, 12> visited{};
  int loopIndex = 0;
  for (int start = 0; start < 12; ++start) {
    if (next[start] < 0 || visited[start]) continue;
    std::array<int, 12> edges{}, loop{};
    std::size_t n = 0;
    for (int e = start; !visited[e]; e = next[e]) {
      visited[e] = true;
      edges[n++] = e;
    }
    for (std::size_t i = 0; i < n; ++i) loop[i] = vertex(edges[i]);
    // A fan apex whose diagonals leave every face: else a centre vertex inside the cell.
    int apex = -1;
    for (std::size_t a = 0; a < n && apex < 0; ++a) {
      bool ok = true;
      for (std::size_t m = 2; m + 1 < n && ok; ++m) ok = (faceMask(edges[a]) & faceMask(edges[(a + m) % n])) == 0;
      if (ok) apex = static_cast<int>(a);
    }
    if (apex >= 0) {
      for (std::size_t m = 1; m + 1 < n; ++m) emit(loop[apex], loop[(apex + m) % n], loop[(apex + m + 1) % n]);
    } else {
      const std::uint64_t key = kCentreKey | (static_cast<std::uint64_t>(cell) << 4) | loopIndex;
      Eigen::Vector3f sum = Eigen::Vector3f::Zero();
      Vec3d gradient = Vec3d::Zero();
      for (std::size_t m = 0; m < n; ++m) {
        sum += crossingPosition(grid, crossingOf[edges[m]]);
        if (options.normals) gradient += out.gradients[cellFirst + static_cast<std::size_t>(loop[m])];
      }
      out.centres.emplace_back(key, sum / static_cast<float>(n));
      const int c = static_cast<int>(out.keys.size() - cellFirst);
      out.keys.push_back(key);
      if (options.normals) out.gradients.push_back(gradient / static_cast<double>(n));
      for (std::size_t m = 0; m < n; ++m) emit(c, loop[m], loop[(m + 1) % n]);
    }
    ++loopIndex;
  }
}

/// A crossing on a fault face moved into its own side (`side`: the sum of its cells' vectors
/// from the face's centre to the cell's) by a thousandth of that, and at least 16 float
/// steps of its largest coordinate, so that the move shows in the float positions. The
/// faces on the two sides of a fault are different bilinear patches, rarely one plane, so
/// some pairs remain (Reek PORO 0.2: 23 -> 11); a hundredth left 4 there but folded
/// Emerald's FACIES 0.5 (1 -> 17 pairs), whose vertices sit a thousandth of an edge from
/// corners at the iso-value.
Eigen::Vector3f offFault(const Eigen::Vector3f& position, const Vec3d& side) {
  const double length = side.norm();
  if (!(length > 0)) return position;
  const float largest = position.cwiseAbs().maxCoeff();
  const double ulp = std::bit_cast<float>(std::bit_cast<std::uint32_t>(largest) + 1) - largest;
  const double step = std::min(std::max(1e-3 * length, 16.0 * ulp), 0.05 * length);
  return (position.cast<double>() + step / length * side).cast<float>();
}

/// A vertex record: its weld key and its slot (the blocks' records numbered in order).
struct Record {
  std::uint64_t key;
  std::uint32_t slot;
};

/// The blocks' records ordered by key, then by slot. Edge crossings (all but a few) are
/// counted out by their lower point id, in slot order (a counting sort: linear in the
/// records and the points), then ordered by the upper id inside each point's bucket (a
/// handful of records); the corner and centre records follow, sorted.
std::vector<Record> weldOrder(const std::vector<BlockOutput>& outputs, const std::vector<std::size_t>& firstSlot,
                              std::size_t points) {
  std::vector<std::uint32_t> bucketStart;  // bucket p: [bucketStart[p], bucketStart[p + 1])
  assignHuge(bucketStart, points + 1, 0U);
  std::vector<Record> special;
  for (std::size_t block = 0; block < outputs.size(); ++block)
    for (std::size_t n = 0; n < outputs[block].keyCount; ++n) {
      const std::uint64_t key = outputs[block].keys()[n];
      if (key & (kCornerKey | kCentreKey))
        special.push_back({key, static_cast<std::uint32_t>(firstSlot[block] + n)});
      else
        ++bucketStart[(key >> 32) + 1];
    }
  std::partial_sum(bucketStart.begin(), bucketStart.end(), bucketStart.begin());
  const std::size_t crossings = bucketStart.back();
  std::vector<Record> records;
  resizeHuge(records, crossings + special.size());  // the mesh's arrays are fresh memory: huge pages (huge_pages.h)
  {
    std::vector<std::uint32_t> next;
    reserveHuge(next, points);
    next.assign(bucketStart.begin(), bucketStart.end() - 1);
    for (std::size_t block = 0; block < outputs.size(); ++block)
      for (std::size_t n = 0; n < outputs[block].keyCount; ++n)
        if (const std::uint64_t key = outputs[block].keys()[n]; !(key & (kCornerKey | kCentreKey)))
          records[next[key >> 32]++] = {key, static_cast<std::uint32_t>(firstSlot[block] + n)};
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points, 4096), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t point = r.begin(); point != r.end(); ++point) {
      // Insertion sort by key: stable, so slots stay in order among equal keys.
      const auto first = records.begin() + bucketStart[point];
      const auto last = records.begin() + bucketStart[point + 1];
      for (auto it = first; it != last; ++it)
        for (auto at = it; at != first && (at - 1)->key > at->key; --at) std::iter_swap(at - 1, at);
    }
  });
  std::sort(special.begin(), special.end(),
            [](const Record& a, const Record& b) { return a.key != b.key ? a.key < b.key : a.slot < b.slot; });
  std::copy(special.begin(), special.end(), records.begin() + static_cast<std::ptrdiff_t>(crossings));
  return records;
}

}  // namespace

HexContourResult contourHexahedra(const CornerPointGrid& grid, const CornerField& field,
                                  const HexContourOptions& options, Interrupter* interrupter) {
  const std::size_t cells = grid.cellCount();
  std::vector<BlockOutput> outputs((cells + kBlockCells - 1) / kBlockCells);
  tbb::enumerable_thread_specific<ThreadOutput> threadOutputs;
  // Groups of blocks in parallel; progress and cancellation between groups, on this thread.
  constexpr std::size_t kGroupBlocks = 64;
  const ProgressStage progress(interrupter, "marching cubes");
  const auto nx = static_cast<std::size_t>(grid.dims[0]), ny = static_cast<std::size_t>(grid.dims[1]);
  for (std::size_t group = 0; group < outputs.size(); group += kGroupBlocks) {
    progress.update(static_cast<double>(group), static_cast<double>(outputs.size()));
    const std::size_t last = std::min(outputs.size(), group + kGroupBlocks);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(group, last), [&](const tbb::blocked_range<std::size_t>& r) {
      ThreadOutput& out = threadOutputs.local();
      for (std::size_t block = r.begin(); block != r.end(); ++block) {
        BlockOutput& made = outputs[block];
        made.thread = &out;
        made.firstKey = out.keys.size();
        made.firstCentre = out.centres.size();
        made.firstTriangle = out.triangles.size();
        made.firstFaultSide = out.faultSides.size();
        const std::size_t first = block * kBlockCells, end = std::min(cells, first + kBlockCells);
        // (i, j, k) stepped along with the cell index: no division per cell.
        std::array<int, 3> ijk{static_cast<int>(first % nx), static_cast<int>(first / nx % ny),
                               static_cast<int>(first / (nx * ny))};
        for (std::size_t cell = first; cell < end; ++cell) {
          if (field.usable[cell]) contourCell(grid, field, cell, ijk, options, out, made);
          if (++ijk[0] == grid.dims[0]) {
            ijk[0] = 0;
            if (++ijk[1] == grid.dims[1]) {
              ijk[1] = 0;
              ++ijk[2];
            }
          }
        }
        made.keyCount = out.keys.size() - made.firstKey;
        made.centreCount = out.centres.size() - made.firstCentre;
        made.triangleCount = out.triangles.size() - made.firstTriangle;
        made.faultSideCount = out.faultSides.size() - made.firstFaultSide;
      }
    });
  }
  progress.update(1, 1);

  // Welding: every record (key, slot) ordered by key, then by slot, so each distinct vertex
  // is a run of records in the order the blocks made them: its index is its rank among
  // the keys, and its gradients are summed in block order (normals independent of the
  // thread count).
  HexContourResult result;
  std::vector<std::size_t> firstSlot(outputs.size() + 1, 0);
  for (std::size_t block = 0; block < outputs.size(); ++block) {
    result.cutCells += outputs[block].cutCells;
    result.ambiguousFaces += outputs[block].ambiguousFaces;
    firstSlot[block + 1] = firstSlot[block] + outputs[block].keyCount;
  }
  const std::size_t slots = firstSlot.back();
  if (slots >= std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("marching cubes: more than 2^32 vertex records; mesh indices are 32-bit");
  const std::vector<Record> records = weldOrder(outputs, firstSlot, grid.points.size());
  std::vector<std::uint32_t> vertexOfSlot, runStart;
  resizeHuge(vertexOfSlot, slots);
  reserveHuge(runStart, slots + 1);
  for (std::size_t n = 0; n < slots; ++n) {
    if (n == 0 || records[n].key != records[n - 1].key) runStart.push_back(static_cast<std::uint32_t>(n));
    vertexOfSlot[records[n].slot] = static_cast<std::uint32_t>(runStart.size() - 1);
  }
  const std::size_t vertices = runStart.size();
  runStart.push_back(static_cast<std::uint32_t>(slots));

  // Crossings on fault faces, each with the sum of its cells' sides (in block order).
  std::vector<std::pair<std::uint64_t, Vec3d>> faultSides;
  for (const BlockOutput& made : outputs)
    faultSides.insert(faultSides.end(), made.faultSides().begin(), made.faultSides().end());
  std::stable_sort(faultSides.begin(), faultSides.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  {
    std::size_t kept = 0;
    for (std::size_t n = 0; n < faultSides.size(); ++n)
      if (kept > 0 && faultSides[kept - 1].first == faultSides[n].first)
        faultSides[kept - 1].second += faultSides[n].second;
      else
        faultSides[kept++] = faultSides[n];
    faultSides.resize(kept);
    result.faultVertices = static_cast<std::int64_t>(kept);
  }

  mesh::Mesh& m = result.mesh;
  resizeHuge(m.positions, vertices);
  std::vector<Vec3d> gradients;
  if (options.normals) resizeHuge(gradients, vertices);
  const auto blockOf = [&](std::uint32_t slot) {
    return static_cast<std::size_t>(std::upper_bound(firstSlot.begin(), firstSlot.end(), slot) - firstSlot.begin() - 1);
  };
  tbb::parallel_for(std::size_t{0}, vertices, [&](std::size_t v) {
    const std::uint64_t key = records[runStart[v]].key;
    Eigen::Vector3f position;
    if (key & kCentreKey) {
      const auto centres = outputs[((key & ~kCentreKey) >> 4) / kBlockCells].centres();
      position = std::lower_bound(centres.begin(), centres.end(), key, [](const auto& centre, std::uint64_t k) {
                   return centre.first < k;
                 })->second;
    } else if (key & kCornerKey) {
      position = grid.points[key & 0xffffffffU].cast<float>();
    } else {
      const EdgeCrossing crossing = crossEdge(grid, field, options.iso, static_cast<std::uint32_t>(key >> 32),
                                              static_cast<std::uint32_t>(key & 0xffffffffU));
      position = crossingPosition(grid, crossing);
      const auto fault = std::lower_bound(faultSides.begin(), faultSides.end(), key,
                                          [](const auto& side, std::uint64_t k) { return side.first < k; });
      if (fault != faultSides.end() && fault->first == key) position = offFault(position, fault->second);
    }
    m.positions[v] = {position.x(), position.y(), position.z()};
    if (!options.normals) return;
    Vec3d sum = Vec3d::Zero();
    for (std::uint32_t n = runStart[v]; n < runStart[v + 1]; ++n) {
      const std::uint32_t slot = records[n].slot;
      const std::size_t block = blockOf(slot);
      sum += outputs[block].gradients()[slot - firstSlot[block]];
    }
    gradients[v] = sum;
  });

  // Triangles in block order, those that welding collapsed dropped: counted, then written.
  std::vector<std::size_t> firstTriangle(outputs.size() + 1, 0);
  const auto welded = [&](std::size_t block, const std::array<std::uint32_t, 3>& t) {
    const std::size_t base = firstSlot[block];
    return mesh::Triangle{vertexOfSlot[base + t[0]], vertexOfSlot[base + t[1]], vertexOfSlot[base + t[2]]};
  };
  const auto kept = [](const mesh::Triangle& t) { return t[0] != t[1] && t[1] != t[2] && t[0] != t[2]; };
  tbb::parallel_for(std::size_t{0}, outputs.size(), [&](std::size_t block) {
    for (const auto& t : outputs[block].triangles()) firstTriangle[block + 1] += kept(welded(block, t));
  });
  for (std::size_t block = 0; block < outputs.size(); ++block) firstTriangle[block + 1] += firstTriangle[block];
  resizeHuge(m.triangles, firstTriangle.back());
  tbb::parallel_for(std::size_t{0}, outputs.size(), [&](std::size_t block) {
    std::size_t next = firstTriangle[block];
    for (const auto& t : outputs[block].triangles())
      if (const mesh::Triangle tri = welded(block, t); kept(tri)) m.triangles[next++] = tri;
  });
  if (options.normals) {
    // Fallback for vertices without a usable gradient (collapsed cells): area-weighted face
    // normals, summed only when some vertex needs them.
    const auto usable = [](const Vec3d& normal) { return normal.norm() > 0 && normal.allFinite(); };
    std::vector<Vec3d> faceNormals;
    if (!std::all_of(gradients.begin(), gradients.end(), usable)) {
      assignHuge(faceNormals, vertices, Vec3d::Zero());
      for (const auto& t : m.triangles) {
        const Vec3d a(m.positions[t[0]][0], m.positions[t[0]][1], m.positions[t[0]][2]);
        const Vec3d b(m.positions[t[1]][0], m.positions[t[1]][1], m.positions[t[1]][2]);
        const Vec3d c(m.positions[t[2]][0], m.positions[t[2]][1], m.positions[t[2]][2]);
        const Vec3d n = (b - a).cross(c - a);
        for (int k = 0; k < 3; ++k) faceNormals[t[k]] += n;
      }
    }
    resizeHuge(m.normals, vertices);
    tbb::parallel_for(std::size_t{0}, vertices, [&](std::size_t v) {
      Vec3d normal = -gradients[v];
      if (!usable(normal)) normal = faceNormals[v];
      if (normal.norm() > 0) normal.normalize();
      m.normals[v] = {static_cast<float>(normal.x()), static_cast<float>(normal.y()), static_cast<float>(normal.z())};
    });
  }
  return result;
}

}  // namespace isovdb::reservoir
