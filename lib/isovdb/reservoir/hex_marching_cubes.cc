// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/reservoir/hex_marching_cubes.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <Eigen/Dense>

#include <algorithm>
#include <limits>
#include <cmath>

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

struct CellVertex {
  std::uint64_t key;
  Eigen::Vector3f position;
  Vec3d gradient;
};

/// What a block of consecutive cells makes (one per block, not per cell: a grid of
/// millions of cells holds a surface in a few percent of them).
struct BlockOutput {
  std::vector<CellVertex> vertices;
  std::vector<std::array<int, 3>> triangles;  // into vertices
  std::int64_t cutCells = 0;
  int ambiguousFaces = 0;
};

/// Cells per block: blocks are the unit of parallel work and their outputs are merged in
/// order, so the mesh does not depend on the thread count.
constexpr std::size_t kBlockCells = 4096;

double centreJacobian(const std::array<Vec3d, 8>& p) {
  Eigen::Matrix3d j;
  j.col(0) = 0.25 * (p[1] - p[0] + p[3] - p[2] + p[5] - p[4] + p[7] - p[6]);
  j.col(1) = 0.25 * (p[2] - p[0] + p[3] - p[1] + p[6] - p[4] + p[7] - p[5]);
  j.col(2) = 0.25 * (p[4] - p[0] + p[5] - p[1] + p[6] - p[2] + p[7] - p[3]);
  return j.determinant();
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

void contourCell(const CornerPointGrid& grid, const CornerField& field, std::size_t cell,
                 const HexContourOptions& options, BlockOutput& out) {
  std::array<double, 8> g;
  std::array<bool, 8> above;
  int aboveCount = 0;
  for (int c = 0; c < 8; ++c) {
    g[c] = field.value(grid, cell, c) - options.iso;
    above[c] = g[c] >= 0;
    aboveCount += above[c];
  }
  if (aboveCount == 0 || aboveCount == 8) return;
  if (collapsed(grid, cell)) return;
  ++out.cutCells;

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
      ++out.ambiguousFaces;
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

  const auto& ids = grid.pointIds[cell];
  const double det = centreJacobian(grid.corners[cell]);
  // A corner's gradient serves each of its edges that the surface crosses (up to three).
  std::array<Vec3d, 8> gradientAt;
  std::uint8_t gradientKnown = 0;
  auto gradientOf = [&](int corner) -> const Vec3d& {
    if (!(gradientKnown >> corner & 1)) {
      gradientAt[static_cast<std::size_t>(corner)] = cornerGradient(grid, field, cell, corner);
      gradientKnown |= static_cast<std::uint8_t>(1 << corner);
    }
    return gradientAt[static_cast<std::size_t>(corner)];
  };
  const bool flip = det < 0 || (det == 0 && grid.orientation < 0);
  std::array<int, 12> vertexOf;
  vertexOf.fill(-1);
  auto vertex = [&](int edge) {
    if (vertexOf[edge] >= 0) return vertexOf[edge];
    int a = edgeCorners[edge][0], b = edgeCorners[edge][1];
    if (ids[a] > ids[b]) std::swap(a, b);  // canonical order: identical result in every cell
    const double va = field.pointValues[ids[a]], vb = field.pointValues[ids[b]];
    double t = std::clamp((options.iso - va) / (vb - va), 0.0, 1.0);
    const Vec3d& pa = grid.points[ids[a]];
    const Vec3d& pb = grid.points[ids[b]];
    CellVertex v;
    v.key = (static_cast<std::uint64_t>(ids[a]) << 32) | ids[b];
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
      const double ulp = std::nextafter(coordinate, std::numeric_limits<float>::max()) - coordinate;
      offset = std::min(offset, std::max(kCornerOffset, 16.0 * ulp / along));
    }
    if (t < offset || t > 1.0 - offset) {
      if (offset <= kMaxCornerOffset)
        t = std::clamp(t, offset, 1.0 - offset);
      else
        v.key = (std::uint64_t{1} << 62) | ids[t < 0.5 ? a : b];
    }
    v.position = (pa + t * (pb - pa)).cast<float>();
    v.gradient = options.normals ? Vec3d((1 - t) * gradientOf(a) + t * gradientOf(b)) : Vec3d::Zero();
    vertexOf[edge] = static_cast<int>(out.vertices.size());
    out.vertices.push_back(v);
    return vertexOf[edge];
  };
  // Faces holding each cell edge: a fan diagonal between two crossings of one face
  // would coincide with the neighbour cell's diagonal (an edge of four triangles).
  const auto faceMask = [](int edge) { return kEdgeFaces[static_cast<std::size_t>(edge)]; };
  auto emit = [&](int a, int b, int c) {
    std::array<int, 3> tri{a, c, b};  // faces towards lower values
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
      CellVertex centre;
      centre.key = (std::uint64_t{1} << 63) | (static_cast<std::uint64_t>(cell) << 4) | loopIndex;
      Eigen::Vector3f sum = Eigen::Vector3f::Zero();
      Vec3d gradient = Vec3d::Zero();
      for (std::size_t m = 0; m < n; ++m) {
        sum += out.vertices[static_cast<std::size_t>(loop[m])].position;
        gradient += out.vertices[static_cast<std::size_t>(loop[m])].gradient;
      }
      centre.position = sum / static_cast<float>(n);
      centre.gradient = gradient / static_cast<double>(n);
      const int c = static_cast<int>(out.vertices.size());
      out.vertices.push_back(centre);
      for (std::size_t m = 0; m < n; ++m) emit(c, loop[m], loop[(m + 1) % n]);
    }
    ++loopIndex;
  }
}

}  // namespace

HexContourResult contourHexahedra(const CornerPointGrid& grid, const CornerField& field,
                                  const HexContourOptions& options, Interrupter* interrupter) {
  const std::size_t cells = grid.cellCount();
  std::vector<BlockOutput> outputs((cells + kBlockCells - 1) / kBlockCells);
  // Groups of blocks in parallel; progress and cancellation between groups, on this thread.
  constexpr std::size_t kGroupBlocks = 64;
  const ProgressStage progress(interrupter, "marching cubes");
  for (std::size_t group = 0; group < outputs.size(); group += kGroupBlocks) {
    progress.update(static_cast<double>(group), static_cast<double>(outputs.size()));
    const std::size_t last = std::min(outputs.size(), group + kGroupBlocks);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(group, last), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t block = r.begin(); block != r.end(); ++block) {
        const std::size_t end = std::min(cells, (block + 1) * kBlockCells);
        for (std::size_t cell = block * kBlockCells; cell < end; ++cell)
          if (field.usable[cell]) contourCell(grid, field, cell, options, outputs[block]);
      }
    });
  }
  progress.update(1, 1);

  HexContourResult result;
  std::vector<std::uint64_t> keys;
  std::size_t cellVertices = 0;
  for (const BlockOutput& out : outputs) cellVertices += out.vertices.size();
  reserveHuge(keys, cellVertices);  // the mesh's arrays are fresh memory: huge pages (huge_pages.h)
  for (const BlockOutput& out : outputs) {
    result.cutCells += out.cutCells;
    result.ambiguousFaces += out.ambiguousFaces;
    for (const CellVertex& v : out.vertices) keys.push_back(v.key);
  }
  tbb::parallel_sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  mesh::Mesh& m = result.mesh;
  resizeHuge(m.positions, keys.size());
  std::vector<Vec3d> gradients;
  assignHuge(gradients, keys.size(), Vec3d::Zero());
  // Each block's vertices found among the keys in parallel; the sums below stay in block
  // order, so the normals do not depend on the thread count.
  std::vector<std::vector<std::uint32_t>> indices(outputs.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, outputs.size()), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t block = r.begin(); block != r.end(); ++block) {
      const std::vector<CellVertex>& vertices = outputs[block].vertices;
      indices[block].resize(vertices.size());
      for (std::size_t n = 0; n < vertices.size(); ++n)
        indices[block][n] =
            static_cast<std::uint32_t>(std::lower_bound(keys.begin(), keys.end(), vertices[n].key) - keys.begin());
    }
  });
  std::size_t triangles = 0;
  for (const BlockOutput& out : outputs) triangles += out.triangles.size();
  reserveHuge(m.triangles, triangles);
  for (std::size_t block = 0; block < outputs.size(); ++block) {
    const BlockOutput& out = outputs[block];
    const std::vector<std::uint32_t>& index = indices[block];
    for (std::size_t n = 0; n < out.vertices.size(); ++n) {
      const CellVertex& v = out.vertices[n];
      m.positions[index[n]] = {v.position.x(), v.position.y(), v.position.z()};
      gradients[index[n]] += v.gradient;
    }
    for (const auto& t : out.triangles) {
      const mesh::Triangle tri{index[static_cast<std::size_t>(t[0])], index[static_cast<std::size_t>(t[1])],
                               index[static_cast<std::size_t>(t[2])]};
      if (tri[0] != tri[1] && tri[1] != tri[2] && tri[0] != tri[2]) m.triangles.push_back(tri);
    }
  }
  if (options.normals) {
    // Fallback for vertices without a usable gradient (collapsed cells): area-weighted face normals.
    std::vector<Vec3d> faceNormals;
    assignHuge(faceNormals, keys.size(), Vec3d::Zero());
    for (const auto& t : m.triangles) {
      const Vec3d a(m.positions[t[0]][0], m.positions[t[0]][1], m.positions[t[0]][2]);
      const Vec3d b(m.positions[t[1]][0], m.positions[t[1]][1], m.positions[t[1]][2]);
      const Vec3d c(m.positions[t[2]][0], m.positions[t[2]][1], m.positions[t[2]][2]);
      const Vec3d n = (b - a).cross(c - a);
      for (int k = 0; k < 3; ++k) faceNormals[t[k]] += n;
    }
    resizeHuge(m.normals, keys.size());
    for (std::size_t n = 0; n < keys.size(); ++n) {
      Vec3d normal = -gradients[n];
      if (!(normal.norm() > 0) || !normal.allFinite()) normal = faceNormals[n];
      if (normal.norm() > 0) normal.normalize();
      m.normals[n] = {static_cast<float>(normal.x()), static_cast<float>(normal.y()), static_cast<float>(normal.z())};
    }
  }
  return result;
}

}  // namespace isovdb::reservoir
