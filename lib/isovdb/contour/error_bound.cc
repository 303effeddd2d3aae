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
    const std::array<int, 3> origin = cell::edgeQuadrantVoxel(start, axis, q);
    if (std::any_of(origin.begin(), origin.end(), [&](int c) { return c < 0 || c >= samples.size; })) return false;
    const std::uint8_t config = cell::cellCornerSigns(samples, origin, 1, options.iso);
    const cell::DmcEntry& entry = cell::dmcEntry(config);
    if (entry.vertexCount != 1 || voxelDmcEntry(config).vertexCount != 1 ||
        cell::dmcVertexOfEdge(config, false, axis, q) < 0)
      return false;
    const cell::DualVertex v = cell::computeDualVertex(samples, origin, 1, entry.groups[0], options);
    if (!v.valid()) return false;
    for (int a = 0; a < 3; ++a)
      vertex[static_cast<std::size_t>(q)][a] = static_cast<double>(v.position[a]) - samples.origin[a];
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

/// True if every vertex full-resolution contouring places in the unit cells of `leaf` that
/// the surface crosses lies within `maxError` of the mesh in `grid` or of `ownVertices` (the
/// leaf's vertices in the mesh, given for a leaf on the meta-cell's boundary): manifold DMC's
/// groups (dmc_table.h), a QEF vertex for a single group and mass points for several, as
/// contour/leaf_groups.cc places them at 1 voxel. True, unchecked, for a boundary leaf whose
/// face on the boundary the surface crosses (the seam covers it).
bool unitCellVerticesWithin(const cell::MetaCellSamples& samples, const octree::SamplePhases& phases,
                            const octree::UnitEdgeCrossings* crossings, const octree::OctreeLeaf& leaf,
                            cell::DualVertexOptions options, const mesh::TriangleGrid& grid, float maxError,
                            std::span<const Vec3f> ownVertices) {
  // A leaf on the meta-cell's boundary whose face there the surface crosses lies beside the
  // seam's triangles, stitched later with the neighbour's leaves: its vertices are left to the
  // octree's criterion (kPlaneShare). Otherwise the block's mesh and the leaf's own vertex must
  // cover them: a one-voxel finger ending just short of a seam crosses no face of it.
  if (octree::crossesMetaCellBoundary(phases, leaf.origin, leaf.size)) return true;
  options.positionOnly = true;
  bool within = true;
  std::uint32_t hint = std::numeric_limits<std::uint32_t>::max();  // the last triangle close enough
  // Within `reach` of the mesh: of its triangles, or of one of the leaf's own vertices, which
  // the seam's triangles (stitched later, so not in `grid`) pass through.
  const auto covered = [&](const Vec3f& p, double reach) {
    for (const Vec3f& v : ownVertices) {
      double d2 = 0.0;
      for (int a = 0; a < 3; ++a) d2 += (static_cast<double>(p[a]) - v[a]) * (static_cast<double>(p[a]) - v[a]);
      if (d2 <= reach * reach) return true;
    }
    return grid.within(p, reach, &hint);
  };
  octree::forEachCrossedUnitCell(
      phases, leaf.origin, leaf.size, [&](const std::array<int, 3>& origin, std::uint8_t config) {
        if (!within) return;
        const cell::DmcEntry& entry = cell::dmcEntry(config);
        options.massPointOnly = entry.vertexCount > 1;
        for (int g = 0; g < entry.vertexCount && within; ++g) {
          const std::uint16_t group = entry.groups[static_cast<std::size_t>(g)];
          if (crossings == nullptr || options.sharpFeatures) {  // (sharp features slide the minimiser)
            const cell::DualVertex v = octree::cellDualVertex(samples, origin, 1, group, options, crossings);
            within = !v.valid() || covered(v.position, maxError);
            continue;
          }
          std::array<Vec3f, 12> points;
          std::array<Vec3f, 12> normals;
          std::uint16_t edges = 0;
          const std::size_t n = cell::gatherCrossings(
              origin, 1, group, [&](const std::array<int, 3>& start, int axis) { return crossings->find(start, axis); },
              points, normals, edges);
          if (n == 0) continue;  // no vertex
          const std::span<const Vec3f> p(points.data(), n), normal(normals.data(), n);
          // The vertex lies within qefReach of the mass point (the QEF's minimiser clamped into
          // the cell, which holds the mass point; or the mass point itself): where the mass point
          // is that much nearer the mesh, the eigendecomposition is not needed to tell.
          const cell::QefReach reach = cell::qefReach(p, normal, {options.singularValueThreshold});
          Vec3f mass = reach.massPoint;
          for (int a = 0; a < 3; ++a) mass[a] += static_cast<float>(samples.origin[a]);
          const double slack =
              static_cast<double>(maxError) - (options.massPointOnly ? 0.0 : reach.reach) - roundingMargin(mass);
          if (slack > 0.0 && covered(mass, slack)) continue;
          const cell::DualVertex v = cell::dualVertexFromCrossings(samples, origin, 1, p, normal, edges, options);
          within = covered(v.position, maxError);
        }
      });
  return within;
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
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, leaves.size(), kLeafGrain), [&](const tbb::blocked_range<std::size_t>& r) {
        std::vector<octree::MortonKey>& local = found.local();
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
          if (!leaves[i].surface || leaves[i].size <= finestSize) continue;
          const std::optional<std::span<const Vec3f>> own = ownVertices(leaves[i]);
          if (own && !unitCellVerticesWithin(samples, phases, crossings, leaves[i], options, grid, maxError, *own))
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
