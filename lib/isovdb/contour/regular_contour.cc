// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/contour/regular_contour.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "isovdb/cell/dmc_table.h"
#include "isovdb/cell/dual_vertex.h"
#include "isovdb/contour/box_caps.h"
#include "isovdb/contour/leaf_groups.h"
#include "isovdb/contour/quad_diagonal.h"
#include "isovdb/contour/voxel_dmc.h"
#include "isovdb/errors.h"
#include "isovdb/octree/criteria.h"
#include "isovdb/octree/morton.h"
#include "isovdb/octree/unit_edge_crossings.h"
#include "isovdb/octree/unit_leaf_index.h"

namespace isovdb::contour {

namespace {

using cell::MetaCellSamples;
using octree::LinearOctree;
using octree::OctreeLeaf;

constexpr std::size_t kGrain = 256;
/// Provisional ids of a chunk's edge points (a block has far fewer than 2^31 vertices).
constexpr std::uint32_t kChunkVertex = std::uint32_t{1} << 31;
/// Edge points stay this fraction of the edge away from its ends.
constexpr float kEdgePointMargin = 1e-3f;

/// Where the surface crosses edge `e` of `leaf`, in voxels from the edge's start corner,
/// kept off its ends (the midpoint where the samples show no crossing, which a bipolar edge
/// always has).
float edgePointOffset(const MetaCellSamples& samples, const OctreeLeaf& leaf, int e,
                      const cell::ContourSettings& options, const octree::UnitEdgeCrossings* crossings) {
  const double t =
      octree::leafEdgeCrossing(samples, leaf.origin, leaf.size, e, options.iso, options.sharpFeatures, crossings);
  const auto length = static_cast<float>(leaf.size);
  const float margin = kEdgePointMargin * length;
  const float offset = std::clamp(std::isfinite(t) ? static_cast<float>(t) : 0.5f * length, margin, length - margin);
  if (!options.capBox) return offset;
  // An edge that leaves the box has its point on the cap, beside the face (box_caps.h).
  std::array<int, 3> start = cell::cellEdgeStart(leaf.origin, leaf.size, e);
  for (std::size_t a = 0; a < 3; ++a) start[a] += samples.origin[a];
  return edgePointBesideDataBox(offset, start, cell::cellEdgeAxis(e), leaf.size, margin, *options.capBox);
}

}  // namespace

std::array<mesh::Triangle, 2> regularEdgeQuad(const std::array<std::uint32_t, 4>& v,
                                              const std::array<mesh::Vec3f, 4>& p, int axis,
                                              bool minEndInside) noexcept {
  // Quadrants 0,1,3,2 turn counter-clockwise in the (u, v) plane: normal +axis for x and z
  // ((u, v, axis) right-handed), -axis for y. Outward = from the inside end to the outside end.
  const bool plusAxis = minEndInside;  // the normal must point towards +axis
  const bool ccwIsPlus = axis != 1;
  std::array<int, 4> order{0, 1, 3, 2};
  if (plusAxis != ccwIsPlus) order = {0, 2, 3, 1};
  const auto P = [&](int k) -> Eigen::Vector3d {
    return Eigen::Map<const Eigen::Vector3f>(p[static_cast<std::size_t>(order[static_cast<std::size_t>(k)])].data())
        .cast<double>();
  };
  const auto V = [&](int k) { return v[static_cast<std::size_t>(order[static_cast<std::size_t>(k)])]; };
  if (firstDiagonalIsBetter(P(0), P(1), P(2), P(3)))
    return {mesh::Triangle{V(0), V(1), V(2)}, mesh::Triangle{V(0), V(2), V(3)}};
  return {mesh::Triangle{V(0), V(1), V(3)}, mesh::Triangle{V(1), V(2), V(3)}};
}

MetaCellMesh contourRegularMetaCell(const cell::MetaCellSamples& samples, const LinearOctree& regularTree,
                                    const cell::ContourSettings& options, RegularContourStats* stats,
                                    const octree::SamplePhases* phases) {
  if (samples.size != regularTree.metaCellSize())
    throw InputError("contourRegular: samples.size " + std::to_string(samples.size) +
                     " differs from the octree's meta-cell size " + std::to_string(regularTree.metaCellSize()));

  const std::size_t n = regularTree.leafCount();
  const auto& leaves = regularTree.leaves();
  const int metaSize = regularTree.metaCellSize();

  // 1. Corner configurations: the tree's. Checked against the samples on every 64th leaf (a
  // tree built at another isovalue differs on almost every surface leaf); reading all eight
  // corners of every leaf again was 3 % of the contouring.
  std::vector<std::uint8_t> configs(n);
  for (std::size_t i = 0; i < n; ++i) configs[i] = leaves[i].cornerSigns;
  for (std::size_t i = 0; i < n; i += 64)
    if (cell::cellCornerSigns(samples, leaves[i].origin, leaves[i].size, options.iso) != configs[i])
      throw InputError("contourRegular: leaf " + std::to_string(i) +
                       " has corner signs that differ from the samples at iso " + std::to_string(options.iso) +
                       " (octree built with another isovalue)");

  // 2. Grouping with Wenger's manifold fix, and 3. one vertex per group (leaves in stored
  // order, groups in table order).
  const LeafGroups groups =
      groupLeaves(samples, regularTree, std::move(configs), options.iso, options.manifoldFix, options.topology);
  const std::vector<std::uint8_t>& config = groups.configs;
  const std::vector<char>& alternative = groups.alternative;
  const std::vector<std::uint32_t>& vertexBase = groups.firstVertex;
  const std::size_t vertexCount = groups.totalVertices();

  MetaCellMesh result;
  mesh::Mesh& out = result.mesh;
  // 1-voxel leaves (every leaf with a vertex at the default depths) read their crossings
  // from a table that finds each once, not once per cell around the edge, where the
  // table pays for its memory (UnitEdgeCrossings::pays).
  const auto unitLeafCount = static_cast<std::size_t>(
      std::count_if(leaves.begin(), leaves.end(), [](const OctreeLeaf& l) { return l.size == 1; }));
  std::optional<octree::UnitEdgeCrossings> crossings;
  if (octree::UnitEdgeCrossings::pays(metaSize, unitLeafCount)) {
    if (phases)
      crossings.emplace(samples, *phases, options.iso, options.sharpFeatures);
    else
      crossings.emplace(samples, options.iso, options.sharpFeatures);
  }
  out.positions = placeGroupVertices(samples, regularTree, groups, cell::dualVertexOptions(options),
                                     crossings ? &*crossings : nullptr, options.capBox);

  // 4. Quads (voxel topology: polygons): each interior bipolar edge by its owner leaf (the edge is
  // the owner's local edge 4 * axis, the owner in quadrant 3); edges on the meta-cell boundary are
  // left to stitching. Chunks of leaves in order keep the output independent of the threads.
  const std::size_t chunks = (n + kGrain - 1) / kGrain;
  std::vector<std::vector<mesh::Triangle>> chunkTriangles(chunks);
  std::vector<std::vector<mesh::Vec3f>> chunkPoints(chunks);  // edge points of fanned polygons
  std::vector<std::int64_t> chunkEdges(chunks, 0);
  std::vector<std::int32_t> leafBoundaryEdges(n, 0);
  // Constant-time lookups of the cells around an edge, where the index pays for its memory.
  std::optional<octree::UnitLeafIndex> unitLeaves;
  if (octree::UnitLeafIndex::pays(metaSize, n)) unitLeaves.emplace(regularTree);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks), [&](const tbb::blocked_range<std::size_t>& r) {
    // A fanned polygon's edge point is a vertex of its own, numbered after the cells' vertices
    // once every chunk's count is known. Made once per range (a std::function made per edge
    // would allocate), it reads the edge from these.
    std::array<int, 3> edgeStart{};
    const OctreeLeaf* edgeLeaf = nullptr;
    int edgeAxis = 0;
    std::size_t chunk = 0;
    const EdgePointFn noEdgePoint;
    const EdgePointFn addEdgePoint = [&] {
      // The leaf's local edge 4 * axis starts at its origin.
      const float t = edgePointOffset(samples, *edgeLeaf, 4 * edgeAxis, options, crossings ? &*crossings : nullptr);
      mesh::Vec3f point{};
      for (int a = 0; a < 3; ++a)
        point[static_cast<std::size_t>(a)] =
            static_cast<float>(edgeStart[static_cast<std::size_t>(a)]) + (a == edgeAxis ? t : 0.0f);
      chunkPoints[chunk].push_back(point);
      return kChunkVertex | static_cast<std::uint32_t>(chunkPoints[chunk].size() - 1);
    };
    for (std::size_t c = r.begin(); c != r.end(); ++c) {
      chunk = c;
      std::vector<mesh::Triangle>& triangles = chunkTriangles[c];
      for (std::size_t i = c * kGrain; i < std::min(n, (c + 1) * kGrain); ++i) {
        const std::uint16_t bipolar = octree::bipolarEdgeMask(config[i]);
        if (bipolar == 0) continue;
        const OctreeLeaf& leaf = leaves[i];
        for (int axis = 0; axis < 3; ++axis) {
          if (((bipolar >> (4 * axis)) & 1) == 0) continue;
          const auto around = unitLeaves ? unitLeaves->leavesAroundEdge(leaf.origin, axis)
                                         : regularTree.leavesAroundEdge(leaf.origin, axis);
          assert(around[3] == static_cast<std::int64_t>(i));
          if (std::find(around.begin(), around.end(), LinearOctree::kNone) != around.end()) {
            ++leafBoundaryEdges[i];
            continue;
          }
          bool regular = true;  // the four leaves have the same size (the precondition)
          for (const std::int64_t j : around)
            regular = regular && leaves[static_cast<std::size_t>(j)].size == leaf.size;
          assert(regular);
          if (!regular) continue;
          ++chunkEdges[c];
          // The voxel reading's cells without tube sectors or split faces give the edge one
          // vertex each: its quad (voxelEdgeTriangles' own first case), without gathering
          // every vertex of the four cells.
          const bool plainVoxelQuad = groups.voxels && std::all_of(around.begin(), around.end(), [&](std::int64_t j) {
                                        const auto u = static_cast<std::size_t>(j);
                                        return groups.splitFaces[u] == 0 && !isTubeConfig(config[u]);
                                      });
          if (groups.voxels) {
            for (int a = 0; a < 3; ++a) edgeStart[static_cast<std::size_t>(a)] = samples.origin[a] + leaf.origin[a];
            edgeLeaf = &leaf;
            edgeAxis = axis;
            const EdgePointFn& edgePoint = options.intersectionFree ? addEdgePoint : noEdgePoint;
            if (plainVoxelQuad) {
              std::array<std::uint32_t, 4> ids{};
              std::array<mesh::Vec3f, 4> positions{};
              for (int q = 0; q < 4; ++q) {
                const auto j = static_cast<std::size_t>(around[static_cast<std::size_t>(q)]);
                const int g = voxelDmcEntry(config[j]).vertexOfEdge[static_cast<std::size_t>(4 * axis + 3 - q)];
                assert(g >= 0);
                ids[static_cast<std::size_t>(q)] = vertexBase[j] + static_cast<std::uint32_t>(g);
                positions[static_cast<std::size_t>(q)] = out.positions[ids[static_cast<std::size_t>(q)]];
              }
              voxelQuadTriangles(ids, positions, axis, (config[i] & 1) != 0, edgeStart, leaf.size, edgePoint,
                                 triangles);
              continue;
            }
            std::array<VoxelEdgeCell, 4> cells;
            for (int q = 0; q < 4; ++q)
              cells[static_cast<std::size_t>(q)] = voxelEdgeCell(
                  groups, static_cast<std::size_t>(around[static_cast<std::size_t>(q)]), {}, out.positions);
            voxelEdgeTriangles(cells, axis, edgeStart, leaf.size, triangles, edgePoint);
            continue;
          }
          appendRegularEdgeQuad(
              [&](int q) -> std::optional<EdgeVertex> {
                const auto j = static_cast<std::size_t>(around[static_cast<std::size_t>(q)]);
                const int g = cell::dmcVertexOfEdge(config[j], alternative[j] != 0, axis, q);
                assert(g >= 0);
                const std::uint32_t id = vertexBase[j] + static_cast<std::uint32_t>(g);
                return EdgeVertex{id, out.positions[id]};
              },
              axis, (config[i] & 1) != 0, triangles);
        }
      }
    }
  });

  // The edge points after the cells' vertices, chunk by chunk (independent of the threads).
  for (std::size_t c = 0; c < chunks; ++c) {
    if (chunkPoints[c].empty()) continue;  // a chunk's triangles name only its own edge points
    const auto base = static_cast<std::uint32_t>(out.positions.size());
    for (mesh::Triangle& t : chunkTriangles[c])
      for (std::uint32_t& v : t)
        if (v != kNoVertex && (v & kChunkVertex) != 0) v = base + (v & ~kChunkVertex);
    out.positions.insert(out.positions.end(), chunkPoints[c].begin(), chunkPoints[c].end());
  }
  std::size_t triangleCount = 0;
  for (const auto& t : chunkTriangles) triangleCount += t.size();
  out.triangles.reserve(triangleCount);
  for (auto& t : chunkTriangles) {
    out.triangles.insert(out.triangles.end(), t.begin(), t.end());
    std::vector<mesh::Triangle>().swap(t);
  }

  // 5. Seam: leaves with dual vertices on the meta-cell boundary, in key (Z) order.
  for (std::size_t i = 0; i < n; ++i) {
    const OctreeLeaf& leaf = leaves[i];
    const cell::DmcEntry& entry = groups.entry(i);
    if (entry.vertexCount == 0 || !octree::touchesMetaCellBoundary(leaf.origin, leaf.size, metaSize)) continue;
    SeamCell cell = seamCellOf(leaf, samples.origin, alternative[i] != 0);  // config[i] is leaf.cornerSigns
    if (groups.voxels) {  // the stitcher's edge points (voxelEdgeTriangles)
      const std::uint16_t bipolar = octree::bipolarEdgeMask(config[i]);
      for (int e = 0; e < 12; ++e) {
        float& t = cell.edgeCrossing[static_cast<std::size_t>(e)];
        t = std::numeric_limits<float>::quiet_NaN();
        if (((bipolar >> e) & 1) == 0) continue;
        t = edgePointOffset(samples, leaf, e, options, crossings ? &*crossings : nullptr);
      }
    }
    const VoxelEdgeCell vertices = voxelEdgeCell(groups, i, {}, out.positions);
    cell.vertices = vertices.vertices;
    cell.positions = vertices.positions;
    cell.splitFaces = vertices.splitFaces;
    cell.splitVertices = vertices.splitVertices;
    result.seam.cells.push_back(cell);
  }

  if (stats) {
    RegularContourStats s;
    for (std::size_t i = 0; i < n; ++i) {
      if (groups.vertexCount(i) > 0) ++s.cells;
      s.boundaryEdges += leafBoundaryEdges[i];
    }
    s.manifoldFixes = groups.manifoldFixes;
    s.fixesBeyondApron = groups.fixesBeyondApron;
    s.vertices = static_cast<std::int64_t>(vertexCount);
    for (const std::int64_t edges : chunkEdges) s.quads += edges;
    if (groups.voxels)
      for (std::size_t i = 0; i < n; ++i) s.tubeCells += isTubeConfig(config[i]) ? 1 : 0;
    s.seamCells = static_cast<std::int64_t>(result.seam.cells.size());
    *stats = s;
  }
  return result;
}

mesh::Mesh contourRegular(const cell::MetaCellSamples& samples, const LinearOctree& regularTree,
                          const cell::ContourSettings& options, RegularContourStats* stats) {
  return contourRegularMetaCell(samples, regularTree, options, stats).mesh;
}

}  // namespace isovdb::contour
