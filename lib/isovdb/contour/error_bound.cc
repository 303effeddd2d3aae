// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/contour/error_bound.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>

#include "isovdb/cell/cell_geometry.h"
#include "isovdb/cell/dmc_table.h"
#include "isovdb/cell/dual_vertex.h"
#include "isovdb/cell/meta_cell_samples.h"
#include "isovdb/cell/trilinear.h"
#include "isovdb/contour/voxel_dmc.h"
#include "isovdb/mesh/triangle_grid.h"
#include "isovdb/octree/build.h"
#include "isovdb/octree/sample_phases.h"
#include "isovdb/octree/unit_edge_crossings.h"

namespace isovdb::contour {

namespace {

/// Side of the bins the meta-cell's triangles are sorted into for the distance queries
/// (voxels): a coarse leaf's triangles are up to twice its size long.
constexpr double kBinVoxels = 4.0;

/// Mesh points and leaves per task: the check runs inside a meta-cell's task, and where
/// that block is the last one left (a 256^3 volume has 8) its loops are all the work there is.
constexpr std::size_t kPointGrain = 4096;
constexpr std::size_t kLeafGrain = 256;

/// True if `point` (meta-cell offsets, a vertex of the mesh) lies on a bipolar unit edge of
/// the lattice (two whole coordinates) on a face of the leaf of `tree` holding it, as the edge
/// point of a Ju-Udeshi fan does, and regular mode's quad on that edge may lie farther than
/// `radius` from it. The level proxy (cell::levelWithin) takes regular mode's
/// mesh to follow the level; where its quad sags away from the edge's own crossing it does
/// not, and a fan through that crossing beside a coarser leaf lay 0.513 voxel from regular
/// mode's quad at E = 0.5 (a 64^3 blobs mask) while on the level. The bound is either
/// diagonal's distance, whichever is larger (regular mode keeps one of them, or fans through
/// the crossing itself), so it is an upper bound on the distance to regular mode's mesh.
/// False (nothing to add) off unit edges, on edges near the meta-cell's boundary, and around
/// cells with several vertices, which the proxy keeps.
bool edgePointOffRegularQuad(const cell::MetaCellSamples& samples, const octree::LinearOctree& tree, const Vec3f& point,
                             const cell::DualVertexOptions& options, float radius) {
  int axis = -1, whole = 0;
  for (int a = 0; a < 3; ++a) {
    if (point[a] == std::floor(point[a]))
      ++whole;
    else
      axis = a;
  }
  if (whole != 2) return false;
  std::array<int, 3> start{};
  for (int a = 0; a < 3; ++a) start[static_cast<std::size_t>(a)] = static_cast<int>(std::floor(point[a]));
  if (std::any_of(start.begin(), start.end(), [&](int c) { return c < 0 || c >= samples.size; })) return false;
  // A fan's edge point lies on a minimal edge, on a face of each leaf around it; a coarse
  // leaf's own vertex with two whole coordinates (the centre of a flat patch: a tenth of the
  // gyroid's vertices, on a crossing too) lies inside its leaf and is not measured: four
  // vertices each made the gyroid's check 40 % slower.
  const std::int64_t found = tree.findLeafContaining(std::array<float, 3>{point[0], point[1], point[2]});
  if (found == octree::LinearOctree::kNone) return false;
  const octree::OctreeLeaf& leaf = tree.leaf(static_cast<std::size_t>(found));
  bool onLeafFace = false;  // the leaf on the edge's max side: the edge lies on one of its faces
  for (int a = 0; a < 3; ++a) {
    const auto u = static_cast<std::size_t>(a);
    onLeafFace = onLeafFace || (a != axis && (start[u] == leaf.origin[u] || start[u] == leaf.origin[u] + leaf.size));
  }
  if (!onLeafFace) return false;
  std::array<int, 3> end = start;
  ++end[static_cast<std::size_t>(axis)];
  if (cell::isInside(samples.value(start), options.iso) == cell::isInside(samples.value(end), options.iso))
    return false;  // not bipolar
  std::array<Vec3d, 4> vertex{};
  for (int q = 0; q < 4; ++q) {
    const std::optional<Vec3f> v =
        unambiguousUnitVertex(samples, cell::edgeQuadrantVoxel(start, axis, q), axis, q, options);
    if (!v) return false;
    for (int a = 0; a < 3; ++a)
      vertex[static_cast<std::size_t>(q)][a] = static_cast<double>((*v)[a]) - samples.origin[a];
  }
  const Vec3d p{point[0], point[1], point[2]};
  const auto distanceTo = [&](int a, int b, int c) {
    const Vec3d x =
        mesh::closestPointOnTriangle(p, vertex[static_cast<std::size_t>(a)], vertex[static_cast<std::size_t>(b)],
                                     vertex[static_cast<std::size_t>(c)]);
    return std::sqrt((x[0] - p[0]) * (x[0] - p[0]) + (x[1] - p[1]) * (x[1] - p[1]) + (x[2] - p[2]) * (x[2] - p[2]));
  };
  // Quadrants in cyclic order around the edge: 0, 1, 3, 2.
  const double diagonal03 = std::min(distanceTo(0, 1, 3), distanceTo(0, 3, 2));
  const double diagonal12 = std::min(distanceTo(0, 1, 2), distanceTo(1, 3, 2));
  return std::max(diagonal03, diagonal12) > static_cast<double>(radius);
}

/// Keys of the leaves coarser than `finestSize` whose closed box holds a vertex, triangle
/// centroid or edge midpoint of `mesh` farther than `maxError` from the level, or a fan's
/// edge point farther than that from regular mode's quad there (edgePointOffRegularQuad).
void addLeavesOfFarMeshPoints(const cell::MetaCellSamples& samples, const octree::LinearOctree& tree,
                              const mesh::Mesh& mesh, const cell::DualVertexOptions& options, float maxError,
                              int finestSize, std::vector<octree::MortonKey>& keys) {
  const auto check = [&](Vec3f p, std::vector<octree::MortonKey>& out, bool vertex = false) {
    for (int a = 0; a < 3; ++a) p[a] -= static_cast<float>(samples.origin[a]);
    // A fan's edge point is a vertex of the mesh: only vertices are measured against
    // regular mode's quad too (midpoints of a flat patch's diagonals have two whole
    // coordinates as well).
    if (cell::levelWithin(samples, p, options, maxError) &&
        !(vertex && edgePointOffRegularQuad(samples, tree, p, options, maxError)))
      return;
    // Every leaf whose closed box holds p: a point on a face, an edge or a corner lies in several.
    constexpr float kNudge = 1e-3f;
    for (int corner = 0; corner < 8; ++corner) {
      Vec3f q = p;
      for (int a = 0; a < 3; ++a) q[a] += ((corner >> a) & 1) ? kNudge : -kNudge;
      const std::int64_t leaf = tree.findLeafContaining(q);
      if (leaf != octree::LinearOctree::kNone && tree.leaf(static_cast<std::size_t>(leaf)).size > finestSize)
        out.push_back(tree.leaf(static_cast<std::size_t>(leaf)).key);
    }
  };
  tbb::enumerable_thread_specific<std::vector<octree::MortonKey>> found;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh.positions.size(), kPointGrain),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      std::vector<octree::MortonKey>& local = found.local();
                      for (std::size_t i = r.begin(); i != r.end(); ++i) check(mesh.positions[i], local, true);
                    });
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, mesh.triangles.size(), kPointGrain),
      [&](const tbb::blocked_range<std::size_t>& r) {
        std::vector<octree::MortonKey>& local = found.local();
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
          const mesh::Triangle& t = mesh.triangles[i];
          const Vec3f& a = mesh.positions[t[0]];
          const Vec3f& b = mesh.positions[t[1]];
          const Vec3f& c = mesh.positions[t[2]];
          check({(a[0] + b[0] + c[0]) / 3.0f, (a[1] + b[1] + c[1]) / 3.0f, (a[2] + b[2] + c[2]) / 3.0f}, local);
          // Each edge from both sides: cheaper than a set of edges.
          check({0.5f * (a[0] + b[0]), 0.5f * (a[1] + b[1]), 0.5f * (a[2] + b[2])}, local);
          check({0.5f * (b[0] + c[0]), 0.5f * (b[1] + c[1]), 0.5f * (b[2] + c[2])}, local);
          check({0.5f * (c[0] + a[0]), 0.5f * (c[1] + a[1]), 0.5f * (c[2] + a[2])}, local);
        }
      });
  for (const std::vector<octree::MortonKey>& local : found) keys.insert(keys.end(), local.begin(), local.end());
}

/// What float positions near `p` (the vertex, the mass point) may be off from exact ones:
/// a thousandth of a voxel, plus a few units in the last place of p's coordinates.
double roundingMargin(const Vec3f& p) noexcept {
  const float largest = std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
  return 1e-3 + 4.0 * static_cast<double>(largest) * std::numeric_limits<float>::epsilon();
}

/// A full-resolution vertex (one DMC group of a unit cell) as the check measured it: the mass
/// point of its crossings and how far the vertex can lie from it (cell::qefReach), the vertex
/// itself where something asked for it, and its distance to the mesh.
struct UnitVertex {
  static constexpr std::uint32_t kNoTriangle = std::numeric_limits<std::uint32_t>::max();

  bool exists = false;          // the group has crossings (else no vertex)
  bool solved = false;          // position holds the vertex
  bool measuredSolved = false;  // the distance below is the vertex's (else the mass point's)
  Vec3f massPoint{};            // global voxel coordinates, as the mesh
  Vec3f position{};
  double reach = 0.0;
  /// An upper bound of the measured point's distance to the mesh (or to the leaf's own
  /// vertices), and the triangle it was measured to (none for a vertex).
  double distance = std::numeric_limits<double>::infinity();
  std::uint32_t triangle = kNoTriangle;

  const Vec3f& point() const noexcept { return solved ? position : massPoint; }
  double off() const noexcept { return solved ? 0.0 : reach; }  // |vertex - point()| at most
  const Vec3f& measured() const noexcept { return measuredSolved ? position : massPoint; }
};

/// The vertices of a leaf's crossed unit cells in its two latest slices along z: a side of
/// regular mode's mesh joins a cell to its neighbours at -x, -y and -z, visited before it
/// (forEachCrossedUnitCell goes in x-fastest order). A whole leaf's vertices by position
/// took a megabyte for a 16-voxel leaf, and its scattered slots cost the 256^3 salt's check
/// a third more.
class SliceVertices {
 public:
  struct Cell {
    std::uint32_t leaf = 0;  // the leaf (reset's count) and slice whose cell the entry holds
    int z = 0;
    std::uint8_t config = 0;
    bool readsAlike = false;  // Wenger's and the voxel reading group its edges alike
    std::array<UnitVertex, 4> vertex{};
  };

  /// Starts a leaf of `size` voxels: the entries of the leaves before go stale (not cleared:
  /// a 16-voxel leaf's two slices take 100 KB).
  void reset(int size) {
    size_ = size;
    const std::size_t n = 2 * static_cast<std::size_t>(size) * static_cast<std::size_t>(size);
    if (cells_.size() < n) cells_.resize(n);
    if (++leaf_ == 0) {  // wrapped: every entry is stale
      for (Cell& c : cells_) c.leaf = 0;
      leaf_ = 1;
    }
  }
  /// Marks `cell` as the entry of the cell in slice `z` of the current leaf.
  void claim(Cell& cell, int z) const noexcept {
    cell.leaf = leaf_;
    cell.z = z;
  }
  /// True if `cell` holds the cell in slice `z` of the current leaf.
  bool holds(const Cell& cell, int z) const noexcept { return cell.leaf == leaf_ && cell.z == z; }
  /// The entry of the unit cell at `local` (offsets in the leaf).
  Cell& at(const std::array<int, 3>& local) noexcept {
    return cells_[(static_cast<std::size_t>(local[2] & 1) * static_cast<std::size_t>(size_) +
                   static_cast<std::size_t>(local[1])) *
                      static_cast<std::size_t>(size_) +
                  static_cast<std::size_t>(local[0])];
  }

 private:
  int size_ = 0;
  std::uint32_t leaf_ = 0;
  std::vector<Cell> cells_;
};

double squaredDistance(const Vec3f& a, const Vec3f& b) noexcept {
  double d2 = 0.0;
  for (int c = 0; c < 3; ++c) d2 += (static_cast<double>(a[c]) - b[c]) * (static_cast<double>(a[c]) - b[c]);
  return d2;
}

/// True if every vertex full-resolution contouring places in the unit cells of `leaf` that
/// the surface crosses, and the sides of regular mode's quads between two of those cells, lie
/// within `maxError` of the mesh in `grid` or of `ownVertices` (the leaf's vertices in the
/// mesh, given for a leaf on the meta-cell's boundary): manifold DMC's groups (dmc_table.h),
/// a QEF vertex for a single group and mass points for several, as contour/leaf_groups.cc
/// places them at 1 voxel. True, unchecked, for a boundary leaf whose face on the boundary
/// the surface crosses (the seam covers it). The sides matter where the adaptive mesh folds:
/// on the rim of the frog skeleton's half-voxel sheets two regular vertices were within 0.4
/// voxel of the adaptive mesh and the side between them 0.509 from it, at E = 0.5.
bool unitCellVerticesWithin(const cell::MetaCellSamples& samples, const octree::SamplePhases& phases,
                            const octree::UnitEdgeCrossings* crossings, const octree::OctreeLeaf& leaf,
                            cell::DualVertexOptions options, const mesh::TriangleGrid& grid, float maxError,
                            std::span<const Vec3f> ownVertices, SliceVertices& slices) {
  // A leaf on the meta-cell's boundary whose face there the surface crosses lies beside the
  // seam's triangles, stitched later with the neighbour's leaves: its vertices are left to the
  // octree's criterion (kPlaneShare). Otherwise the block's mesh and the leaf's own vertex must
  // cover them: a one-voxel finger ending just short of a seam crosses no face of it.
  if (octree::crossesMetaCellBoundary(phases, leaf.origin, leaf.size)) return true;
  options.positionOnly = true;
  slices.reset(leaf.size);
  std::uint32_t hint = UnitVertex::kNoTriangle;  // the last triangle close enough
  // The distance from p to the mesh (its triangles, or one of the leaf's own vertices, which
  // the seam's triangles, stitched later and so not in `grid`, pass through) found for the
  // first of them within `reach`, else +infinity; `triangle` receives the triangle.
  const auto within = [&](const Vec3f& p, double reach, std::uint32_t& triangle) {
    for (const Vec3f& v : ownVertices)
      if (const double d2 = squaredDistance(p, v); d2 <= reach * reach) return std::sqrt(d2);
    double found = 0.0;
    if (!grid.within(p, reach, &hint, &found)) return std::numeric_limits<double>::infinity();
    triangle = hint;
    return found;
  };
  // The crossings of group `group` of the unit cell at `cell`, and the options its vertex uses.
  std::array<Vec3f, 12> points;
  std::array<Vec3f, 12> normals;
  std::uint16_t edges = 0;
  const auto gather = [&](const std::array<int, 3>& cell, std::uint16_t group) {
    return cell::gatherCrossings(
        cell, 1, group, [&](const std::array<int, 3>& start, int axis) { return crossings->find(start, axis); }, points,
        normals, edges);
  };
  const auto optionsOf = [&](std::uint8_t config) {
    cell::DualVertexOptions o = options;
    o.massPointOnly = cell::dmcEntry(config).vertexCount > 1;
    return o;
  };
  // The vertex from the `n` crossings gathered last.
  const auto solveGathered = [&](UnitVertex& v, const std::array<int, 3>& cell, std::uint8_t config, std::size_t n) {
    v.position = cell::dualVertexFromCrossings(samples, cell, 1, std::span<const Vec3f>(points.data(), n),
                                               std::span<const Vec3f>(normals.data(), n), edges, optionsOf(config))
                     .position;
    v.solved = true;
  };
  // (Without crossings, measure solves every vertex itself.)
  const auto solve = [&](UnitVertex& v, const std::array<int, 3>& cell, std::uint8_t config, int g) {
    if (!v.solved)
      solveGathered(v, cell, config, gather(cell, cell::dmcEntry(config).groups[static_cast<std::size_t>(g)]));
  };
  // Places and measures group g's vertex of the crossed cell at `cell`: false where it lies
  // beyond the bound.
  const auto measure = [&](UnitVertex& v, const std::array<int, 3>& cell, std::uint8_t config, int g) {
    const std::uint16_t group = cell::dmcEntry(config).groups[static_cast<std::size_t>(g)];
    if (crossings == nullptr || options.sharpFeatures) {  // (sharp features slide the minimiser)
      const cell::DualVertex d = octree::cellDualVertex(samples, cell, 1, group, optionsOf(config), crossings);
      v.exists = d.valid();
      v.solved = v.measuredSolved = true;
      v.massPoint = v.position = d.position;
      if (!v.exists) return true;
      v.distance = within(v.position, maxError, v.triangle);
      return v.distance <= static_cast<double>(maxError);
    }
    const std::size_t n = gather(cell, group);
    if (n == 0) return true;  // no vertex
    v.exists = true;
    // The vertex lies within qefReach of the mass point (the QEF's minimiser clamped into
    // the cell, which holds the mass point; or the mass point itself): where the mass point
    // is that much nearer the mesh, the eigendecomposition is not needed to tell.
    const cell::QefReach reach =
        cell::qefReach(std::span<const Vec3f>(points.data(), n), std::span<const Vec3f>(normals.data(), n),
                       {options.singularValueThreshold});
    v.massPoint = reach.massPoint;
    for (int a = 0; a < 3; ++a) v.massPoint[a] += static_cast<float>(samples.origin[a]);
    v.reach = optionsOf(config).massPointOnly ? 0.0 : reach.reach;
    const double slack = static_cast<double>(maxError) - v.reach - roundingMargin(v.massPoint);
    if (slack > 0.0) {
      const double d = within(v.massPoint, slack, v.triangle);
      if (d <= slack) {
        v.distance = d;
        return true;
      }
    }
    solveGathered(v, cell, config, n);
    v.measuredSolved = true;
    v.distance = within(v.position, maxError, v.triangle);
    return v.distance <= static_cast<double>(maxError);
  };
  // Regular mode's mesh joins the vertices of two face-neighbouring unit cells (the groups
  // holding a bipolar edge of their shared face) by a side of the quad around that edge. A
  // side lies within an end's measured distance to the mesh plus its distance from that end
  // (the distance to a set is 1-Lipschitz), or within the bound all along if an end's
  // triangle is near its midpoint (the distance to a triangle is convex); only where neither
  // tells is the midpoint measured. Cells whose readings differ (Wenger's and the voxel one)
  // are left out: regular mode's corners there are not these.
  const auto sideWithin = [&](UnitVertex& a, const std::array<int, 3>& cellA, std::uint8_t configA, int gA,
                              UnitVertex& b, const std::array<int, 3>& cellB, std::uint8_t configB, int gB) {
    if (!a.exists || !b.exists) return true;
    Vec3f mid{};
    const auto near = [&] {
      for (int c = 0; c < 3; ++c) mid[c] = 0.5f * (a.point()[c] + b.point()[c]);
      const double allowed = static_cast<double>(maxError) - 0.5 * (a.off() + b.off()) - roundingMargin(mid);
      for (const UnitVertex* v : {&a, &b})
        if (const double spare = allowed - v->distance;
            spare >= 0.0 && squaredDistance(mid, v->measured()) <= spare * spare)
          return true;
      for (const UnitVertex* v : {&a, &b})
        if (v->triangle != UnitVertex::kNoTriangle && grid.distanceTo(mid, v->triangle) <= allowed) return true;
      return false;
    };
    if (near()) return true;
    solve(a, cellA, configA, gA);  // the vertices themselves
    solve(b, cellB, configB, gB);
    if (near()) return true;
    std::uint32_t unused = 0;
    return within(mid, maxError, unused) <= static_cast<double>(maxError);
  };

  bool inBound = true;
  octree::forEachCrossedUnitCell(
      phases, leaf.origin, leaf.size, [&](const std::array<int, 3>& origin, std::uint8_t config) {
        if (!inBound) return;
        const std::array<int, 3> local{origin[0] - leaf.origin[0], origin[1] - leaf.origin[1],
                                       origin[2] - leaf.origin[2]};
        SliceVertices::Cell& here = slices.at(local);
        slices.claim(here, local[2]);
        here.config = config;
        const cell::DmcEntry& entry = cell::dmcEntry(config);
        here.readsAlike = entry.groups == voxelDmcEntry(config).groups;
        for (int g = 0; g < entry.vertexCount && inBound; ++g) {
          here.vertex[static_cast<std::size_t>(g)] = UnitVertex{};
          inBound = measure(here.vertex[static_cast<std::size_t>(g)], origin, config, g);
        }
        if (!inBound || !here.readsAlike) return;
        // The sides to the cells before it along each axis, in the leaf.
        for (int axis = 0; axis < 3 && inBound; ++axis) {
          if (local[static_cast<std::size_t>(axis)] == 0) continue;
          // Corner c of a cell lies at (c & 1, c >> 1 & 1, c >> 2 & 1): the shared face holds
          // this cell's corners with bit `axis` clear.
          const auto lowFace = static_cast<std::uint8_t>(axis == 0 ? 0x55 : axis == 1 ? 0x33 : 0x0F);
          const auto face = static_cast<std::uint8_t>(config & lowFace);
          if (face == 0 || face == lowFace) continue;  // no bipolar edge on the shared face
          std::array<int, 3> before = origin, beforeLocal = local;
          --before[static_cast<std::size_t>(axis)];
          --beforeLocal[static_cast<std::size_t>(axis)];
          SliceVertices::Cell& there = slices.at(beforeLocal);
          if (!slices.holds(there, beforeLocal[2]) || !there.readsAlike) continue;  // (crossed: visited)
          if (entry.vertexCount == 1 && cell::dmcEntry(there.config).vertexCount == 1) {
            // One vertex each (most cells): the face's bipolar edges all join these two.
            inBound = sideWithin(here.vertex[0], origin, config, 0, there.vertex[0], before, there.config, 0);
            continue;
          }
          std::uint32_t pairsSeen = 0;  // bit 4 g + h: groups (g, h) joined already
          for (const int along : cell::otherAxes(axis)) {
            const auto uv = cell::otherAxes(along);
            for (int end = 0; end < 2 && inBound; ++end) {
              // The edge's quadrant (cell::edgeQuadrantVoxel) for each cell: along `axis` bit 1
              // for this cell, 0 for the one before; along the third axis 1 - end for both.
              const auto quadrantOf = [&](int axisBit) {
                return uv[0] == axis ? axisBit | ((1 - end) << 1) : (1 - end) | (axisBit << 1);
              };
              const int g = cell::dmcVertexOfEdge(config, false, along, quadrantOf(1));
              const int h = cell::dmcVertexOfEdge(there.config, false, along, quadrantOf(0));
              if (g < 0 || h < 0) continue;  // not bipolar
              const std::uint32_t pair = 1u << (4 * g + h);
              if (pairsSeen & pair) continue;
              pairsSeen |= pair;
              inBound = sideWithin(here.vertex[static_cast<std::size_t>(g)], origin, config, g,
                                   there.vertex[static_cast<std::size_t>(h)], before, there.config, h);
            }
          }
        }
      });
  return inBound;
}

/// Keys of the leaves coarser than `finestSize` holding a full-resolution vertex farther than
/// `maxError` from `mesh`: the other side of the bound. A coarse leaf's vertex can sit on the
/// level set and still miss a part of the surface regular mode meshes (a one-voxel slit of
/// background along the leaf's edge, whose unit-cell vertices lie 0.6 voxel from the slit's
/// crossings). On the meta-cell's boundary the seam's triangles, which stitching makes later,
/// pass through the leaf's own vertices (`seam`'s positions): there a full-resolution vertex
/// counts as covered within reach of the mesh or of those vertices. Without `seam` such
/// leaves are left out.
void addLeavesMissingFullResolutionVertices(const cell::MetaCellSamples& samples, const octree::LinearOctree& tree,
                                            const mesh::Mesh& mesh, const cell::DualVertexOptions& options,
                                            float maxError, int finestSize, const octree::UnitEdgeCrossings* crossings,
                                            const octree::SamplePhases* givenPhases, const MetaCellSeam* seam,
                                            std::vector<octree::MortonKey>& keys) {
  if (!std::isfinite(maxError)) return;  // nothing lies farther than that
  // The seam cells' vertex positions by key (seam cells are the surface leaves on the boundary).
  std::vector<std::pair<octree::MortonKey, std::span<const Vec3f>>> seamVertices;
  if (seam) {
    seamVertices.reserve(seam->cells.size());
    for (const SeamCell& c : seam->cells)
      seamVertices.emplace_back(
          c.key, std::span<const Vec3f>(c.positions.data(), cell::dmcEntry(c.cornerSigns, c.alternative).vertexCount));
    std::sort(seamVertices.begin(), seamVertices.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  }
  const auto ownVertices = [&](const octree::OctreeLeaf& leaf) -> std::optional<std::span<const Vec3f>> {
    if (!octree::touchesMetaCellBoundary(leaf.origin, leaf.size, samples.size)) return std::span<const Vec3f>{};
    const auto at = std::lower_bound(seamVertices.begin(), seamVertices.end(), leaf.key,
                                     [](const auto& entry, octree::MortonKey key) { return entry.first < key; });
    if (at == seamVertices.end() || at->first != leaf.key) return std::nullopt;  // not checked
    return at->second;
  };
  const auto checked = [&](const octree::OctreeLeaf& leaf) {
    return leaf.surface && leaf.size > finestSize && ownVertices(leaf).has_value();
  };
  const auto& leaves = tree.leaves();
  if (std::none_of(leaves.begin(), leaves.end(), checked)) return;  // no grid, no phases
  std::optional<octree::SamplePhases> ownPhases;
  if (!givenPhases) ownPhases.emplace(samples, options.iso);
  const octree::SamplePhases& phases = givenPhases ? *givenPhases : *ownPhases;
  const mesh::TriangleGrid grid(mesh, std::max(kBinVoxels, 2.0 * maxError));
  tbb::enumerable_thread_specific<std::vector<octree::MortonKey>> found;
  tbb::enumerable_thread_specific<SliceVertices> slices;
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, leaves.size(), kLeafGrain), [&](const tbb::blocked_range<std::size_t>& r) {
        std::vector<octree::MortonKey>& local = found.local();
        SliceVertices& slice = slices.local();
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
          if (!leaves[i].surface || leaves[i].size <= finestSize) continue;
          const std::optional<std::span<const Vec3f>> own = ownVertices(leaves[i]);
          if (own &&
              !unitCellVerticesWithin(samples, phases, crossings, leaves[i], options, grid, maxError, *own, slice))
            local.push_back(leaves[i].key);
        }
      });
  for (const std::vector<octree::MortonKey>& local : found) keys.insert(keys.end(), local.begin(), local.end());
}

}  // namespace

std::vector<octree::MortonKey> leavesBeyondErrorBound(const cell::MetaCellSamples& samples,
                                                      const octree::LinearOctree& tree, const mesh::Mesh& mesh,
                                                      const cell::DualVertexOptions& options, float maxError,
                                                      int finestSize, const octree::UnitEdgeCrossings* crossings,
                                                      const octree::SamplePhases* phases, const MetaCellSeam* seam) {
  std::vector<octree::MortonKey> keys;
  maxError -= octree::kErrorBoundMargin;  // what the samples do not see (octree/build.h)
  addLeavesOfFarMeshPoints(samples, tree, mesh, options, maxError, finestSize, keys);
  // The costlier side once the mesh's own points hold: the pass would be built again anyway.
  if (keys.empty())
    addLeavesMissingFullResolutionVertices(samples, tree, mesh, options, maxError, finestSize, crossings, phases, seam,
                                           keys);
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

}  // namespace isovdb::contour
