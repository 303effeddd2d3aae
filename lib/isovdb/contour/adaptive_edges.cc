// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/contour/adaptive_edges.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "isovdb/bit_count.h"
#include "isovdb/cell/dmc_table.h"
#include "isovdb/mesh/triangle_grid.h"
#include "isovdb/octree/morton.h"

namespace isovdb::contour {
namespace {

using octree::LinearOctree;
using octree::OctreeLeaf;

/// Quadrant visited at each position of the cycle around an edge (bit 0 = +u, bit 1 = +v):
/// counter-clockwise seen from +axis when (u, v, axis) is right-handed (axis x and z).
constexpr std::array<int, 4> kCycle{0, 1, 3, 2};

/// True when the leaves around an edge are all one voxel (coarser leaves on either side of
/// it also make four cells).
bool allOneVoxel(const LinearOctree& tree, const std::array<std::int64_t, 4>& cells) {
  return std::all_of(cells.begin(), cells.end(),
                     [&](std::int64_t l) { return tree.leaf(static_cast<std::size_t>(l)).size == 1; });
}

using Triangle3 = std::array<Vec3d, 3>;

/// The largest distance from a sample of `from` (corners, side midpoints, centroid) to the
/// nearest triangle of `to`.
double farthestSample(const std::vector<Triangle3>& from, const std::vector<Triangle3>& to) {
  const auto mid = [](const Vec3d& a, const Vec3d& b) {
    return Vec3d{0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])};
  };
  double farthest = 0.0;
  for (const Triangle3& t : from) {
    const Vec3d centroid{(t[0][0] + t[1][0] + t[2][0]) / 3.0, (t[0][1] + t[1][1] + t[2][1]) / 3.0,
                         (t[0][2] + t[1][2] + t[2][2]) / 3.0};
    for (const Vec3d& p : {t[0], t[1], t[2], mid(t[0], t[1]), mid(t[1], t[2]), mid(t[2], t[0]), centroid}) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const Triangle3& u : to) {
        const Vec3d q = mesh::closestPointOnTriangle(p, u[0], u[1], u[2]);
        nearest = std::min(nearest, std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]));
      }
      farthest = std::max(farthest, nearest);
    }
  }
  return farthest;
}

/// The triangles `how` makes of an edge's polygon (ju_udeshi.h, triangulateEdge).
std::vector<Triangle3> edgeTriangles(const EdgeEnvelope& env, const std::array<bool, 4>& crossed, EdgeTriangulation how,
                                     const Vec3d& edgePoint) {
  thread_local std::vector<std::array<int, 3>> local;
  triangulateEdge(env.cellCount, crossed, how, local);
  const auto point = [&](int i) -> const Vec3d& {
    if (i == kEdgeVertex) return edgePoint;
    return i >= kFaceVertex ? env.facePoints[static_cast<std::size_t>(i - kFaceVertex)]
                            : env.cellPoints[static_cast<std::size_t>(i)];
  };
  std::vector<Triangle3> triangles;
  for (const auto& t : local) triangles.push_back({point(t[0]), point(t[1]), point(t[2])});
  return triangles;
}

}  // namespace

Vec3d cellPointInside(const mesh::Vec3f& vertex, const OctreeLeaf& leaf, const std::array<int, 3>& treeOrigin) {
  Vec3d p{};
  const double m = kInteriorMargin * leaf.size;
  for (int a = 0; a < 3; ++a) {
    const double lo = treeOrigin[a] + leaf.origin[a], hi = lo + leaf.size;
    // Rounded to the float the mesh stores (and a seam cell keeps), still strictly inside.
    float x = static_cast<float>(std::clamp(static_cast<double>(vertex[a]), lo + m, hi - m));
    if (x <= lo) x = std::nextafter(static_cast<float>(lo), static_cast<float>(hi));
    if (x >= hi) x = std::nextafter(static_cast<float>(hi), static_cast<float>(lo));
    p[a] = x;
  }
  return p;
}

void collectMinimalEdges(const AdaptiveTree& source, std::size_t leafIndex, bool intersectionFree, LeafEdges& out) {
  const LinearOctree& tree = *source.tree;
  const std::vector<Vec3d>& cellPoints = *source.cellPoints;
  const std::vector<std::uint32_t>& firstVertex = *source.firstVertex;
  const std::vector<char>& alternative = *source.alternative;
  const OctreeLeaf& leaf = tree.leaf(leafIndex);
  const std::uint16_t bipolar = leaf.bipolarEdges();
  const int s = leaf.size;
  const std::array<int, 3>& g = source.origin;
  // One envelope for the leaf's edges: each sets every entry it reads (the first k cells
  // and faces, the edge's ends); zeroing it per edge was a tenth of this routine.
  EdgeEnvelope env;
  for (int e = 0; e < 12; ++e) {
    if (!((bipolar >> e) & 1)) continue;
    const int axis = octree::cellEdgeAxis(e);
    const int c0 = octree::cellEdgeCorner(e, 0);
    const auto uv = octree::otherAxes(axis);
    const std::array<int, 3> start = cell::cellEdgeStart(leaf.origin, s, e);
    if (source.inRegion && !source.inRegion(start, axis)) continue;
    // This leaf's quadrant: on the min side of the edge where the edge is on its max side.
    const int own = (1 - ((c0 >> uv[0]) & 1)) | ((1 - ((c0 >> uv[1]) & 1)) << 1);
    // The leaves around the edge (LinearOctree::leavesAroundEdge's), this one's quadrant
    // without a search. The quadrants before it are searched first: where one holds a leaf
    // of this size, that leaf owns the edge, and the other searches are skipped (each edge
    // between four equal leaves is met from all four; three of them stop here).
    std::array<std::int64_t, 4> around{};
    around[static_cast<std::size_t>(own)] = static_cast<std::int64_t>(leafIndex);
    const auto search = [&](int q) {
      const std::array<int, 3> voxel = cell::edgeQuadrantVoxel(start, axis, q);
      const std::int64_t l =
          source.unitLeaves ? source.unitLeaves->findLeafContainingVoxel(voxel) : tree.findLeafContainingVoxel(voxel);
      around[static_cast<std::size_t>(q)] = l;
      return l;
    };
    bool ownedBefore = false;
    for (int q = 0; q < own && !ownedBefore; ++q) {
      const std::int64_t l = search(q);
      ownedBefore = l != LinearOctree::kNone && tree.leaf(static_cast<std::size_t>(l)).size == s;
    }
    if (ownedBefore) continue;
    for (int q = own + 1; q < 4; ++q) search(q);
    // Minimal: no leaf around is smaller. Owner: the first quadrant holding a leaf of this size.
    bool minimal = true, owner = true, outside = false;
    for (int q = 0; q < 4; ++q) {
      const std::int64_t l = around[static_cast<std::size_t>(q)];
      if (l == LinearOctree::kNone) {
        // In a seam's partial tree the missing leaf is a finer one with equal corner
        // signs (not kept): the edge is not minimal, and a finer edge carries the crossing.
        if (source.partial) minimal = false;
        outside = true;
        continue;
      }
      const int size = tree.leaf(static_cast<std::size_t>(l)).size;
      if (size < s) minimal = false;
      if (size == s && q < own) owner = false;
    }
    if (!minimal || !owner) continue;
    if (source.voxelCells && std::any_of(around.begin(), around.end(), [&](std::int64_t l) {
          return l != LinearOctree::kNone && (*source.voxelCells)[static_cast<std::size_t>(l)] != 0;
        }))
      continue;  // the voxel reading's polygon (emitVoxelReadingEdge)
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
    // Quadrants of each leaf (bit mask over the 4 quadrants).
    auto quadrantsOf = [&](std::int64_t l) {
      int mask = 0;
      for (int q = 0; q < 4; ++q)
        if (around[static_cast<std::size_t>(q)] == l) mask |= 1 << q;
      return mask;
    };
    // The vertex of each leaf that represents this edge: a leaf of the edge's size has the
    // edge as a cell edge (its group by the DMC table); a coarser leaf has one vertex.
    std::array<std::int8_t, 4> groups{};
    bool haveVertices = k >= 3;
    for (int i = 0; i < k && haveVertices; ++i) {
      const auto l = static_cast<std::size_t>(cells[static_cast<std::size_t>(i)]);
      const OctreeLeaf& cell = tree.leaf(l);
      const int quadrant = std::countr_zero(static_cast<unsigned>(quadrantsOf(cells[static_cast<std::size_t>(i)])));
      const int g = cell.size == s ? cell::dmcVertexOfEdge(cell.cornerSigns, alternative[l] != 0, axis, quadrant) : 0;
      haveVertices = g >= 0 && static_cast<std::uint32_t>(g) < firstVertex[l + 1] - firstVertex[l];
      groups[static_cast<std::size_t>(i)] = static_cast<std::int8_t>(g);
    }
    if (!haveVertices) {
      ++out.withoutVertex;
      continue;
    }
    // Outward orientation: the normal points from the inside end to the outside end.
    const bool startInside = (leaf.cornerSigns >> c0) & 1;
    const bool ccw = axis != 1;
    if (ccw != startInside) {
      std::reverse(cells.begin(), cells.begin() + k);
      std::reverse(groups.begin(), groups.begin() + k);
    }
    const auto pointOf = [&](int i) -> const Vec3d& {
      const auto l = static_cast<std::size_t>(cells[static_cast<std::size_t>(i)]);
      return cellPoints[firstVertex[l] + static_cast<std::size_t>(groups[static_cast<std::size_t>(i)])];
    };

    // Filled in place: the record is 280 bytes, and copying it in was a sixth of this routine.
    EdgeRecord& r = out.records.emplace_back();
    r.cellCount = k;
    r.cells = cells;
    r.groups = groups;
    env.cellCount = k;
    std::array<bool, 4> crossed{};
    std::array<MinimalFace, 4> faces{};       // the minimal face between cell i and i + 1
    std::array<bool, 4> facesMinSideFirst{};  // cell i lies on that face's min side
    for (int i = 0; i < k; ++i) {
      const std::int64_t a = cells[static_cast<std::size_t>(i)];
      const std::int64_t b = cells[static_cast<std::size_t>((i + 1) % k)];
      env.cellPoints[static_cast<std::size_t>(i)] = pointOf(i);
      // The two leaves touch across the quadrant boundary on axis uv[bit].
      const int qa = quadrantsOf(a), qb = quadrantsOf(b);
      int bit = -1, sideA = 0;
      for (int x = 0; x < 4 && bit < 0; ++x)
        for (int y = 0; y < 4 && bit < 0; ++y)
          if (((qa >> x) & 1) && ((qb >> y) & 1) && countBits(static_cast<unsigned>(x ^ y)) == 1) {
            bit = (x ^ y) == 1 ? 0 : 1;
            sideA = (x >> bit) & 1;
          }
      const int n = uv[static_cast<std::size_t>(bit)];
      const OctreeLeaf& la = tree.leaf(static_cast<std::size_t>(a));
      const OctreeLeaf& lb = tree.leaf(static_cast<std::size_t>(b));
      // The minimal face is the smaller leaf's face; on a tie, the min-side leaf's max face.
      const bool aIsFace = la.size < lb.size || (la.size == lb.size && sideA == 0);
      const OctreeLeaf& lf = aIsFace ? la : lb;
      FaceKey& key = r.faces[static_cast<std::size_t>(i)];
      key.axis = n;
      key.size = lf.size;
      key.part = groups[static_cast<std::size_t>(aIsFace ? i : (i + 1) % k)];
      for (int x = 0; x < 3; ++x) key.min[x] = g[x] + lf.origin[x];
      key.min[n] = g[n] + start[n];
      MinimalFace face;
      face.axis = n;
      face.coordinate = static_cast<double>(key.min[n]);
      for (int x = 0; x < 3; ++x) face.min[x] = static_cast<double>(key.min[x]);
      face.size = lf.size;
      const Vec3d& pa = pointOf(i);
      const Vec3d& pb = pointOf((i + 1) % k);
      const FacePoint fp = sideA == 0 ? computeFacePoint(pa, pb, face) : computeFacePoint(pb, pa, face);
      faces[static_cast<std::size_t>(i)] = face;
      facesMinSideFirst[static_cast<std::size_t>(i)] = sideA == 0;
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
    double t = source.crossing ? source.crossing(leafIndex, e) : 0.5 * s;
    if (!std::isfinite(t)) t = 0.5 * s;
    const double m = kInteriorMargin * s;
    r.edgePoint[axis] = env.edgeStart[axis] + std::clamp(t, m, s - m);
    // A quad around a unit edge of one-voxel leaves and a coarser one: triangulated as regular
    // mode triangulates its quad there (three of its corners are regular mode's; the coarse
    // leaf's vertex lies off regular mode's). Chosen by its own corners, the frog skeleton's
    // quad at (72, 396, 106) took the other diagonal and lay 0.256 voxel from regular mode's at
    // E = 0.25.
    std::optional<EdgeEnvelope> regularEnv;
    if (source.regularVertex && s == 1 && k == 4 &&
        std::all_of(crossed.begin(), crossed.end(), [](bool c) { return c; }) && !allOneVoxel(tree, cells)) {
      regularEnv = env;
      for (int i = 0; i < 4 && regularEnv; ++i) {
        const auto l = static_cast<std::size_t>(cells[static_cast<std::size_t>(i)]);
        if (tree.leaf(l).size == 1) continue;
        const int quadrant = std::countr_zero(static_cast<unsigned>(quadrantsOf(cells[static_cast<std::size_t>(i)])));
        const std::optional<Vec3d> v = source.regularVertex(start, axis, quadrant);
        if (v)
          regularEnv->cellPoints[static_cast<std::size_t>(i)] = *v;
        else
          regularEnv.reset();
      }
      // Regular mode's face points between its vertices; its own quad has every face crossed.
      for (std::size_t i = 0; i < 4 && regularEnv; ++i) {
        const Vec3d& pa = regularEnv->cellPoints[i];
        const Vec3d& pb = regularEnv->cellPoints[(i + 1) % 4];
        const FacePoint fp =
            facesMinSideFirst[i] ? computeFacePoint(pa, pb, faces[i]) : computeFacePoint(pb, pa, faces[i]);
        regularEnv->facePoints[i] = fp.point;
        if (!fp.crossed) regularEnv.reset();
      }
    }
    if (regularEnv && intersectionFree) {
      // Regular mode's triangulation (voxel_dmc.cc, voxelQuadTriangles): its better diagonal
      // in its envelope, else the other, else the fan through the edge's crossing. The fan
      // lies in every envelope; a diagonal is kept where this quad's envelope holds it too.
      const EdgeTriangulation regular = chooseTriangulation(*regularEnv, crossed);
      r.how = regular.fan ? regular : chooseTriangulation(env, crossed, true, {}, regular.apex);
      // Where this quad's envelope refused it (the coarse leaf's vertex moved its triangles
      // out), the two surfaces part across the quad by more than their corners do, which the
      // error bound's check (this mesh against the level) does not see: a 48^3 blobs mask
      // (seed 17) at E = 0.25 lay 0.28 voxel from regular mode's quad. Measured here; the
      // bound splits the coarse leaf where it is too far (pipeline/octree_contour.cc).
      if (r.how.fan != regular.fan || r.how.apex != regular.apex) {
        // Regular mode's surface against this one, and this one against its own corners split
        // as regular mode splits them: this quad's corners themselves lie off regular mode's
        // as far as everywhere else (the check holds them), and measured against regular
        // mode's quad directly they split 600 leaves of the 256^3 blobs at E = 1 (local
        // distances up to 1.6 voxels, where the mesh elsewhere lay within the bound).
        const std::vector<Triangle3> ours = edgeTriangles(env, crossed, r.how, r.edgePoint);
        const std::vector<Triangle3> theirs = edgeTriangles(*regularEnv, crossed, regular, r.edgePoint);
        const std::vector<Triangle3> oursSplitAsTheirs = edgeTriangles(env, crossed, regular, r.edgePoint);
        r.apartFromRegular =
            static_cast<float>(std::max({farthestSample(theirs, ours), farthestSample(ours, oursSplitAsTheirs),
                                         farthestSample(oursSplitAsTheirs, ours)}));
      }
    } else {
      r.how = chooseTriangulation(env, crossed, intersectionFree);
    }
    // A mask read as voxels: four one-voxel leaves are regular mode's cells with regular
    // mode's vertices, and regular mode triangulates their quad as voxelQuadTriangles does
    // (on fields it takes this path itself). Where a face between them is not crossed and
    // neither diagonal of the plain quad fits the envelope, regular mode fans through the
    // edge's crossing: so does this edge, through its face points. A polygon through the
    // face point instead lay 0.32 voxel from that fan's apex (a 48^3 blobs mask at E =
    // 0.25), where the error bound's check cannot split any further.
    if (intersectionFree && source.voxelCells && !r.how.fan && k == 4 && r.uncrossedFace && allOneVoxel(tree, cells) &&
        !plainQuadInEnvelope(env))
      r.how = EdgeTriangulation{true, 0};
    if (intersectionFree) r.crossed = crossed;
  }
}

std::size_t emitVoxelReadingEdge(const VoxelReadingEdge& edge, const VertexAdder& addVertex,
                                 FaceVertexMap& faceVertices, std::vector<mesh::Triangle>& triangles) {
  const int axis = edge.axis;
  // A face between two leaves not read as voxels: its v_f where the segment between their
  // vertices misses it, keyed as collectMinimalEdges keys it (the min side's face and group).
  const FaceCornerFn between = [&](int q, int next) -> std::uint32_t {
    const auto uq = static_cast<std::size_t>(q), un = static_cast<std::size_t>(next);
    if (edge.voxelCell[uq] || edge.voxelCell[un]) return kNoVertex;
    const QuadrantFace shared = faceBetweenQuadrants(edge.start, axis, 1, q, next);
    const std::size_t lo = shared.firstOnMinSide ? uq : un, hi = lo == uq ? un : uq;
    FaceKey key;
    key.axis = shared.face.axis;
    key.size = 1;
    key.part = edge.groups[lo];
    for (std::size_t x = 0; x < 3; ++x) key.min[x] = static_cast<int>(shared.face.min[x]);
    const FacePoint fp = computeFacePoint(edge.points[lo], edge.points[hi], shared.face);
    if (fp.crossed) return kNoVertex;
    auto [it, inserted] = faceVertices.try_emplace(key, 0u);
    if (inserted) it->second = addVertex(fp.point);
    return it->second;
  };
  const VoxelEdgePolygon polygon = voxelEdgePolygon(edge.cells, axis, between);
  Vec3d point{static_cast<double>(edge.start[0]), static_cast<double>(edge.start[1]),
              static_cast<double>(edge.start[2])};
  const double t = std::isfinite(edge.crossing) ? edge.crossing : 0.5;
  point[axis] += std::clamp(t, kInteriorMargin, 1.0 - kInteriorMargin);
  if (!polygon.plainQuad) return static_cast<std::size_t>(fanVoxelEdgePolygon(polygon, addVertex(point), triangles));
  // Four corners, each face crossed: a quad in its envelope keeps a diagonal, as regular
  // mode's quads (voxelQuadTriangles), else the same fan.
  std::array<std::uint32_t, 4> vertices{};
  std::array<mesh::Vec3f, 4> positions{};
  for (std::size_t q = 0; q < 4; ++q) {
    vertices[q] = edge.cells[q].vertices[static_cast<std::size_t>(std::max(edge.groups[q], 0))];
    positions[q] = {static_cast<float>(edge.points[q][0]), static_cast<float>(edge.points[q][1]),
                    static_cast<float>(edge.points[q][2])};
  }
  const EdgePointFn edgePoint = [&] { return addVertex(point); };
  return static_cast<std::size_t>(
      voxelQuadTriangles(vertices, positions, axis, polygon.minEndInside, edge.start, 1, edgePoint, triangles));
}

VertexAdder appendingTo(mesh::Mesh& mesh, std::uint32_t base) {
  return [&mesh, base](const Vec3d& p) {
    mesh.positions.push_back({static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])});
    return base + static_cast<std::uint32_t>(mesh.positions.size() - 1);
  };
}

std::size_t emitEdgeRecord(const EdgeRecord& r, const CellVertexFn& cellVertex, const VertexAdder& addVertex,
                           FaceVertexMap& faceVertices, std::vector<mesh::Triangle>& triangles) {
  const int k = r.cellCount;
  std::array<std::uint32_t, 9> index{};
  for (int i = 0; i < k; ++i) {
    index[static_cast<std::size_t>(i)] =
        cellVertex(r.cells[static_cast<std::size_t>(i)], r.groups[static_cast<std::size_t>(i)]);
    if (r.crossed[static_cast<std::size_t>(i)]) continue;
    auto [it, inserted] = faceVertices.try_emplace(r.faces[static_cast<std::size_t>(i)], 0u);
    if (inserted) it->second = addVertex(r.facePoints[static_cast<std::size_t>(i)]);
    index[static_cast<std::size_t>(kFaceVertex + i)] = it->second;
  }
  if (r.how.fan) index[kEdgeVertex] = addVertex(r.edgePoint);
  thread_local std::vector<std::array<int, 3>> local;
  triangulateEdge(k, r.crossed, r.how, local);
  for (const auto& t : local)
    triangles.push_back({index[static_cast<std::size_t>(t[0])], index[static_cast<std::size_t>(t[1])],
                         index[static_cast<std::size_t>(t[2])]});
  return local.size();
}

}  // namespace isovdb::contour
