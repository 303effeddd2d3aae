#include "isovdb/contour/adaptive_contour.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <string>
#include <unordered_map>
#include <vector>

#include "isovdb/contour/dual_vertex.h"
#include "isovdb/contour/edge_intersection.h"
#include "isovdb/contour/ju_udeshi.h"
#include "isovdb/errors.h"
#include "isovdb/octree/morton.h"

namespace isovdb::contour {
namespace {

using octree::LinearOctree;
using octree::OctreeLeaf;

/// Cell vertices and edge points keep this fraction of the cell / edge size
/// away from the cell boundary / edge ends, so that the envelopes are not
/// degenerate (the dual vertex solver returns points in the closed cell).
constexpr double kInteriorMargin = 1e-3;

/// Quadrant visited at each position of the cycle around an edge (bit 0 = +u, bit 1 = +v):
/// counter-clockwise seen from +axis when (u, v, axis) is right-handed (axis x and z).
constexpr std::array<int, 4> kCycle{0, 1, 3, 2};

/// One sign-changing minimal edge, ready to be triangulated.
struct EdgeRecord {
  int cellCount = 0;
  std::array<std::int64_t, 4> cells{};    ///< leaf indices in polygon order (outward orientation)
  std::array<std::int64_t, 4> faceIds{};  ///< unique id of the face between cell i and i + 1
  std::array<Vec3d, 4> facePoints{};
  Vec3d edgePoint{0, 0, 0};
  std::array<bool, 4> crossed{true, true, true, true};  ///< per face: the cell-to-cell segment crosses it
  EdgeTriangulation how;
  bool uncrossedFace = false;  ///< a face's cell-to-cell segment misses it
};

/// Records of one leaf's owned edges plus its skip counters.
struct LeafEdges {
  std::vector<EdgeRecord> records;
  std::int32_t boundary = 0;
  std::int32_t withoutVertex = 0;
};

Vec3d cellPointInside(const DualVertex& v, const OctreeLeaf& leaf, const std::array<int, 3>& origin) {
  Vec3d p{};
  const double m = kInteriorMargin * leaf.size;
  for (int a = 0; a < 3; ++a) {
    const double lo = origin[a] + leaf.origin[a];
    p[a] = std::clamp(static_cast<double>(v.position[a]), lo + m, lo + leaf.size - m);
  }
  return p;
}

/// Builds the records of the minimal edges owned by `leafIndex`.
void collectLeafEdges(const octree::MetaCellSamples& samples, const LinearOctree& tree,
                      const std::vector<DualVertex>& vertices, const std::vector<Vec3d>& cellPoints,
                      std::size_t leafIndex, const AdaptiveContourOptions& options, LeafEdges& out) {
  const OctreeLeaf& leaf = tree.leaf(leafIndex);
  const std::uint16_t bipolar = leaf.bipolarEdges();
  const int s = leaf.size;
  const std::array<int, 3>& g = samples.origin;
  for (int e = 0; e < 12; ++e) {
    if (!((bipolar >> e) & 1)) continue;
    const int axis = octree::cellEdgeAxis(e);
    const int c0 = octree::cellEdgeCorner(e, 0);
    const auto uv = octree::otherAxes(axis);
    std::array<int, 3> start = leaf.origin;
    for (int a = 0; a < 3; ++a) start[a] += ((c0 >> a) & 1) * s;
    const std::array<std::int64_t, 4> around = tree.leavesAroundEdge(start, axis);
    // This leaf's quadrant: on the min side of the edge where the edge is on its max side.
    const int own = (1 - ((c0 >> uv[0]) & 1)) | ((1 - ((c0 >> uv[1]) & 1)) << 1);
    // Minimal: no leaf around is smaller. Owner: the first quadrant holding a leaf of this size.
    bool minimal = true, owner = true, outside = false;
    for (int q = 0; q < 4; ++q) {
      const std::int64_t l = around[static_cast<std::size_t>(q)];
      if (l == LinearOctree::kNone) {
        outside = true;
        continue;
      }
      const int size = tree.leaf(static_cast<std::size_t>(l)).size;
      if (size < s) minimal = false;
      if (size == s && q < own) owner = false;
    }
    if (!minimal || !owner) continue;
    if (outside) {
      ++out.boundary;
      continue;
    }
    // Distinct leaves in cyclic order (a coarser leaf fills two consecutive quadrants).
    std::array<std::int64_t, 4> cells{};
    int k = 0;
    for (int pos = 0; pos < 4; ++pos) {
      const int q = kCycle[static_cast<std::size_t>(pos)];
      const std::int64_t l = around[static_cast<std::size_t>(q)];
      if (k > 0 && cells[static_cast<std::size_t>(k - 1)] == l) continue;
      cells[static_cast<std::size_t>(k)] = l;
      ++k;
    }
    if (k > 1 && cells[static_cast<std::size_t>(k - 1)] == cells[0]) --k;
    bool haveVertices = k >= 3;
    for (int i = 0; i < k; ++i)
      if (!vertices[static_cast<std::size_t>(cells[static_cast<std::size_t>(i)])].valid()) haveVertices = false;
    if (!haveVertices) {
      ++out.withoutVertex;
      continue;
    }
    // Outward orientation: the normal points from the inside end to the outside end.
    const bool startInside = (leaf.cornerSigns >> c0) & 1;
    const bool ccw = axis != 1;
    if (ccw != startInside) {
      std::reverse(cells.begin(), cells.begin() + k);
    }
    // Quadrants of each leaf (bit mask over the 4 quadrants).
    auto quadrantsOf = [&](std::int64_t l) {
      int mask = 0;
      for (int q = 0; q < 4; ++q)
        if (around[static_cast<std::size_t>(q)] == l) mask |= 1 << q;
      return mask;
    };

    EdgeRecord r;
    r.cellCount = k;
    r.cells = cells;
    EdgeEnvelope env;
    env.cellCount = k;
    std::array<bool, 4> crossed{};
    for (int i = 0; i < k; ++i) {
      const std::int64_t a = cells[static_cast<std::size_t>(i)];
      const std::int64_t b = cells[static_cast<std::size_t>((i + 1) % k)];
      env.cellPoints[static_cast<std::size_t>(i)] = cellPoints[static_cast<std::size_t>(a)];
      // The two leaves touch across the quadrant boundary on axis uv[bit].
      const int qa = quadrantsOf(a), qb = quadrantsOf(b);
      int bit = -1, sideA = 0;
      for (int x = 0; x < 4 && bit < 0; ++x)
        for (int y = 0; y < 4 && bit < 0; ++y)
          if (((qa >> x) & 1) && ((qb >> y) & 1) && std::popcount(static_cast<unsigned>(x ^ y)) == 1) {
            bit = (x ^ y) == 1 ? 0 : 1;
            sideA = (x >> bit) & 1;
          }
      const int n = uv[static_cast<std::size_t>(bit)];
      const OctreeLeaf& la = tree.leaf(static_cast<std::size_t>(a));
      const OctreeLeaf& lb = tree.leaf(static_cast<std::size_t>(b));
      // The minimal face is the smaller leaf's face; on a tie, the min-side leaf's max face.
      const bool aIsFace = la.size < lb.size || (la.size == lb.size && sideA == 0);
      const std::int64_t fl = aIsFace ? a : b;
      const OctreeLeaf& lf = tree.leaf(static_cast<std::size_t>(fl));
      const int fSide = aIsFace ? (sideA == 0 ? 1 : 0) : (sideA == 0 ? 0 : 1);
      r.faceIds[static_cast<std::size_t>(i)] = fl * 6 + 2 * n + fSide;
      MinimalFace face;
      face.axis = n;
      face.coordinate = static_cast<double>(g[n] + start[n]);
      for (int x = 0; x < 3; ++x) face.min[x] = static_cast<double>(g[x] + lf.origin[x]);
      face.size = lf.size;
      const Vec3d& pa = cellPoints[static_cast<std::size_t>(a)];
      const Vec3d& pb = cellPoints[static_cast<std::size_t>(b)];
      const FacePoint fp = sideA == 0 ? computeFacePoint(pa, pb, face) : computeFacePoint(pb, pa, face);
      r.facePoints[static_cast<std::size_t>(i)] = fp.point;
      env.facePoints[static_cast<std::size_t>(i)] = fp.point;
      crossed[static_cast<std::size_t>(i)] = fp.crossed;
      if (!fp.crossed) r.uncrossedFace = true;
    }
    for (int a = 0; a < 3; ++a) {
      env.edgeStart[a] = g[a] + start[a];
      env.edgeEnd[a] = g[a] + start[a] + (a == axis ? s : 0);
    }
    // Edge point v_e: the crossing on the edge, kept off its ends.
    r.edgePoint = env.edgeStart;
    double t = 0.5 * s;
    EdgeIntersection ix;
    if (intersectEdge(samples, start, axis, s, options.iso, ix)) t = ix.point[axis] - start[axis];
    const double m = kInteriorMargin * s;
    r.edgePoint[axis] = env.edgeStart[axis] + std::clamp(t, m, s - m);
    r.how = chooseTriangulation(env, crossed, options.intersectionFree);
    if (options.intersectionFree) r.crossed = crossed;
    out.records.push_back(r);
  }
}

}  // namespace

mesh::Mesh contourAdaptive(const octree::MetaCellSamples& samples, const octree::LinearOctree& tree,
                           const AdaptiveContourOptions& options, AdaptiveContourStats* stats) {
  if (tree.metaCellSize() != samples.size)
    throw InputError("contourAdaptive: octree meta-cell size " + std::to_string(tree.metaCellSize()) +
                     " differs from the samples' size " + std::to_string(samples.size));
  AdaptiveContourStats local;
  mesh::Mesh result;
  const std::size_t leafCount = tree.leafCount();
  const std::vector<DualVertex> vertices = computeLeafVertices(
      samples, tree, DualVertexOptions{.iso = options.iso, .singularValueThreshold = options.singularValueThreshold});
  std::vector<Vec3d> cellPoints(leafCount);
  std::vector<LeafEdges> perLeaf(leafCount);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, leafCount, 256), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i)
      if (vertices[i].valid()) cellPoints[i] = cellPointInside(vertices[i], tree.leaf(i), samples.origin);
  });
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, leafCount, 64), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i)
      if (tree.leaf(i).bipolarEdges() != 0) collectLeafEdges(samples, tree, vertices, cellPoints, i, options, perLeaf[i]);
  });

  // Vertices: the used leaf vertices in leaf order, then face and edge points in edge order.
  std::vector<std::uint32_t> leafVertex(leafCount, UINT32_MAX);
  for (const LeafEdges& le : perLeaf) {
    local.boundaryEdges += le.boundary;
    local.edgesWithoutVertex += le.withoutVertex;
    for (const EdgeRecord& r : le.records)
      for (int i = 0; i < r.cellCount; ++i) leafVertex[static_cast<std::size_t>(r.cells[static_cast<std::size_t>(i)])] = 0;
  }
  auto addVertex = [&](const Vec3d& p) {
    result.positions.push_back({static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])});
    return static_cast<std::uint32_t>(result.positions.size() - 1);
  };
  for (std::size_t i = 0; i < leafCount; ++i)
    if (leafVertex[i] == 0) leafVertex[i] = addVertex(cellPoints[i]);

  // v_f of uncrossed faces: one mesh vertex per face, shared by every edge on it.
  std::unordered_map<std::int64_t, std::uint32_t> faceVertex;
  std::vector<std::array<int, 3>> local3;
  for (const LeafEdges& le : perLeaf) {
    for (const EdgeRecord& r : le.records) {
      const int k = r.cellCount;
      std::array<std::uint32_t, 9> index{};
      for (int i = 0; i < k; ++i) {
        index[static_cast<std::size_t>(i)] = leafVertex[static_cast<std::size_t>(r.cells[static_cast<std::size_t>(i)])];
        if (r.crossed[static_cast<std::size_t>(i)]) continue;
        auto [it, inserted] = faceVertex.try_emplace(r.faceIds[static_cast<std::size_t>(i)], 0u);
        if (inserted) it->second = addVertex(r.facePoints[static_cast<std::size_t>(i)]);
        index[static_cast<std::size_t>(kFaceVertex + i)] = it->second;
      }
      if (r.how.fan) {
        index[kEdgeVertex] = addVertex(r.edgePoint);
        ++local.fannedEdges;
      }
      if (r.uncrossedFace) ++local.uncrossedFaceEdges;
      triangulateEdge(k, r.crossed, r.how, local3);
      for (const auto& t : local3)
        result.triangles.push_back({index[static_cast<std::size_t>(t[0])], index[static_cast<std::size_t>(t[1])],
                                    index[static_cast<std::size_t>(t[2])]});
      ++local.minimalEdges;
      if (k == 4) ++local.quads;
      else ++local.triangles3;
    }
  }
  local.trianglesAddedByFans =
      static_cast<std::int64_t>(result.triangles.size()) - (2 * local.quads + local.triangles3);
  if (stats) *stats = local;
  return result;
}

}  // namespace isovdb::contour
