// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/contour/adaptive_contour.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "isovdb/bit_count.h"
#include "isovdb/contour/adaptive_edges.h"
#include "isovdb/contour/box_caps.h"
#include "isovdb/cell/cell_geometry.h"
#include "isovdb/cell/dual_vertex.h"
#include "isovdb/contour/leaf_groups.h"
#include "isovdb/errors.h"
#include "isovdb/octree/morton.h"

namespace isovdb::contour {

MetaCellMesh contourAdaptiveMetaCell(const cell::MetaCellSamples& samples, const octree::LinearOctree& tree,
                                     const cell::ContourSettings& options, AdaptiveContourStats* stats,
                                     const octree::UnitEdgeCrossings* crossings) {
  if (tree.metaCellSize() != samples.size)
    throw InputError("contourAdaptive: octree meta-cell size " + std::to_string(tree.metaCellSize()) +
                     " differs from the samples' size " + std::to_string(samples.size));
  AdaptiveContourStats local;
  MetaCellMesh result;
  mesh::Mesh& mesh = result.mesh;
  const std::size_t leafCount = tree.leafCount();
  const int metaSize = tree.metaCellSize();
  // One vertex per DMC group (several only at the maximum depth, see octree/build.h),
  // strictly inside its cell.
  std::vector<std::uint8_t> configs(leafCount);
  for (std::size_t i = 0; i < leafCount; ++i) configs[i] = tree.leaf(i).cornerSigns;
  // A mask read as the voxel object: the cells where that reading differs from MDMC's are
  // one voxel, with one-voxel neighbours (octree/build.cc); they take the voxel reading's
  // groups, tubes and split faces, every other leaf has one reading.
  const bool voxels = options.adaptiveReadsVoxels();
  const LeafGroups groups = groupLeaves(samples, tree, std::move(configs), options.iso, options.manifoldFix,
                                        voxels ? cell::RegularTopology::Voxels : cell::RegularTopology::Mdmc);
  std::vector<char> voxelCells;
  if (voxels) {
    voxelCells.resize(leafCount);
    for (std::size_t i = 0; i < leafCount; ++i)
      voxelCells[i] = tree.leaf(i).size == 1 && cell::voxelReadingDiffers(tree.leaf(i).cornerSigns);
  }
  const std::vector<mesh::Vec3f> positions =
      placeGroupVertices(samples, tree, groups, cell::dualVertexOptions(options), crossings);
  // placeGroupVertices keeps each cell vertex strictly inside its cell (split vertices on
  // their face). A cap's vertex (its leaf lies beyond a face of the data's box) is then held
  // within 2 * kInteriorMargin of that face: the cap is flat on the face before the
  // triangulation is chosen (box_caps.h).
  std::vector<Vec3d> cellPoints(positions.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, leafCount, 256), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i)
      for (std::uint32_t v = groups.firstVertex[i]; v < groups.firstVertex[i + 1]; ++v) {
        const mesh::Vec3f& p = positions[v];
        cellPoints[v] = Vec3d{p[0], p[1], p[2]};
        if (options.dataBox)
          cellPoints[v] = besideDataBox(cellPoints[v], tree.leaf(i), samples.origin, *options.dataBox);
      }
  });
  // Crossing on edge e of a leaf, in voxels from the edge's start corner (NaN: none).
  auto crossing = [&](std::size_t leafIndex, int e) -> double {
    const octree::OctreeLeaf& leaf = tree.leaf(leafIndex);
    return octree::leafEdgeCrossing(samples, leaf.origin, leaf.size, e, options.iso, options.sharpFeatures, crossings);
  };
  // Constant-time lookups of the leaves around each edge where the index pays for its
  // memory, as in regular contouring: a binary search in Z order missed the cache on every
  // neighbour.
  std::optional<octree::UnitLeafIndex> unitLeaves;
  if (octree::UnitLeafIndex::pays(metaSize, leafCount)) unitLeaves.emplace(tree);
  // Regular mode's vertex of a unit cell beside a unit edge: the diagonals of quads mixing
  // one-voxel leaves with a coarser one follow regular mode's (adaptive_edges.cc).
  cell::DualVertexOptions regularOptions = cell::dualVertexOptions(options);
  regularOptions.positionOnly = true;
  const auto regularVertex = [&](const std::array<int, 3>& start, int axis, int quadrant) -> std::optional<Vec3d> {
    const std::optional<Vec3f> v = unambiguousUnitVertex(samples, cell::edgeQuadrantVoxel(start, axis, quadrant), axis,
                                                         quadrant, regularOptions, crossings);
    if (!v) return std::nullopt;
    return Vec3d{(*v)[0], (*v)[1], (*v)[2]};
  };
  const AdaptiveTree source{.tree = &tree,
                            .origin = samples.origin,
                            .firstVertex = &groups.firstVertex,
                            .cellPoints = &cellPoints,
                            .alternative = &groups.alternative,
                            .crossing = crossing,
                            .inRegion = {},
                            .unitLeaves = unitLeaves ? &*unitLeaves : nullptr,
                            .voxelCells = voxels ? &voxelCells : nullptr,
                            .regularVertex = regularVertex};
  // Records in fixed chunks of leaves, in leaf order (the mesh does not depend on the
  // threads): one vector per leaf cost an allocation or two for each surface leaf.
  constexpr std::size_t kChunkLeaves = 256;
  std::vector<LeafEdges> perLeaf((leafCount + kChunkLeaves - 1) / kChunkLeaves);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, perLeaf.size()), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t c = r.begin(); c != r.end(); ++c) {
      // Each bipolar edge is met from its (up to) four leaves and kept by one: a quarter of
      // the chunk's bipolar edges, reserved so that the 280-byte records are not copied
      // again as the vector grows (a sixth of collectMinimalEdges' time).
      const std::size_t end = std::min(leafCount, (c + 1) * kChunkLeaves);
      std::size_t bipolar = 0;
      for (std::size_t i = c * kChunkLeaves; i < end; ++i)
        bipolar += static_cast<std::size_t>(countBits(tree.leaf(i).bipolarEdges()));
      perLeaf[c].records.reserve(bipolar / 4 + 8);
      for (std::size_t i = c * kChunkLeaves; i < end; ++i)
        if (tree.leaf(i).bipolarEdges() != 0) collectMinimalEdges(source, i, options.intersectionFree, perLeaf[c]);
    }
  });

  // Seam cells: leaves with a sign change that touch the meta-cell boundary; they keep their vertices.
  std::vector<char> isSeam(leafCount, 0);
  for (std::size_t i = 0; i < leafCount; ++i) {
    const octree::OctreeLeaf& leaf = tree.leaf(i);
    isSeam[i] = groups.vertexCount(i) > 0 && octree::touchesMetaCellBoundary(leaf.origin, leaf.size, metaSize);
  }

  // The edges of leaves read as voxels, by the leaf whose local edge 4 * axis they are (the
  // leaf in quadrant 3), as regular mode finds them: the four leaves around.
  struct VoxelEdge {
    std::array<std::int64_t, 4> around;
    std::size_t owner;
    int axis;
  };
  std::vector<VoxelEdge> voxelEdges;
  if (voxels)
    forEachVoxelReadingEdge(
        tree, voxelCells, [](const std::array<int, 3>&, int) { return true; },
        [&](const std::array<int, 3>& origin, int axis) {
          return unitLeaves ? unitLeaves->leavesAroundEdge(origin, axis) : tree.leavesAroundEdge(origin, axis);
        },
        [&](std::size_t owner, int axis, const std::array<std::int64_t, 4>& around) {
          if (std::find(around.begin(), around.end(), octree::LinearOctree::kNone) != around.end()) {
            ++local.boundaryEdges;  // left to stitching
            return;
          }
          if (std::any_of(around.begin(), around.end(),
                          [&](std::int64_t l) { return tree.leaf(static_cast<std::size_t>(l)).size != 1; }))
            throw std::logic_error("contourAdaptive: a cell read as voxels has a coarser neighbour");
          voxelEdges.push_back({around, owner, axis});
        });

  // Vertices: the used cell vertices in leaf and group order, then face and edge points in edge order.
  std::vector<std::uint32_t> meshVertex(cellPoints.size(), kNoVertex);
  constexpr std::uint32_t kUsed = 0;
  // Every vertex of the leaves around a voxel edge, and of the seam's leaves read as voxels
  // (the stitcher cannot add their split vertices: it has no positions for them).
  const auto useAll = [&](std::size_t l) {
    for (std::uint32_t v = groups.firstVertex[l]; v < groups.firstVertex[l + 1]; ++v) meshVertex[v] = kUsed;
  };
  for (const VoxelEdge& e : voxelEdges)
    for (const std::int64_t l : e.around) useAll(static_cast<std::size_t>(l));
  if (voxels)
    for (std::size_t i = 0; i < leafCount; ++i)
      if (voxelCells[i] && isSeam[i]) useAll(i);
  for (const LeafEdges& le : perLeaf) {
    local.boundaryEdges += le.boundary;
    local.edgesWithoutVertex += le.withoutVertex;
    for (const EdgeRecord& r : le.records)
      for (std::size_t i = 0; i < static_cast<std::size_t>(r.cellCount); ++i)
        meshVertex[groups.firstVertex[static_cast<std::size_t>(r.cells[i])] + static_cast<std::size_t>(r.groups[i])] =
            kUsed;
  }
  const VertexAdder addVertex = appendingTo(mesh);
  for (std::size_t v = 0; v < cellPoints.size(); ++v)
    if (meshVertex[v] == kUsed) meshVertex[v] = addVertex(cellPoints[v]);

  FaceVertexMap faceVertices;
  const auto cellVertex = [&](std::int64_t l, int g) {
    return meshVertex[groups.firstVertex[static_cast<std::size_t>(l)] + static_cast<std::size_t>(g)];
  };
  for (const LeafEdges& le : perLeaf) {
    for (const EdgeRecord& r : le.records) {
      emitEdgeRecord(r, cellVertex, addVertex, faceVertices, mesh.triangles);
      if (r.apartFromRegular > 0.0f)
        for (std::size_t i = 0; i < 4; ++i)
          if (tree.leaf(static_cast<std::size_t>(r.cells[i])).size > 1)
            result.apartFromRegular.push_back({r.cells[i], r.apartFromRegular});
      if (r.how.fan) ++local.fannedEdges;
      if (r.uncrossedFace) ++local.uncrossedFaceEdges;
      ++local.minimalEdges;
      if (r.cellCount == 4)
        ++local.quads;
      else
        ++local.triangles3;
    }
  }
  local.trianglesAddedByFans = static_cast<std::int64_t>(mesh.triangles.size()) - (2 * local.quads + local.triangles3);
  for (const VoxelEdge& e : voxelEdges) {
    VoxelReadingEdge edge;
    edge.axis = e.axis;
    for (std::size_t a = 0; a < 3; ++a) edge.start[a] = samples.origin[a] + tree.leaf(e.owner).origin[a];
    edge.crossing = crossing(e.owner, 4 * e.axis);
    for (int q = 0; q < 4; ++q) {
      const auto l = static_cast<std::size_t>(e.around[static_cast<std::size_t>(q)]);
      const auto uq = static_cast<std::size_t>(q);
      edge.cells[uq] = voxelEdgeCell(groups, l, meshVertex, {});
      edge.voxelCell[uq] = voxelCells[l] != 0;
      const int g = voxelDmcEntry(groups.configs[l]).vertexOfEdge[static_cast<std::size_t>(4 * e.axis + 3 - q)];
      edge.groups[uq] = g;
      edge.points[uq] = cellPoints[groups.firstVertex[l] + static_cast<std::size_t>(std::max(g, 0))];
    }
    emitVoxelReadingEdge(edge, addVertex, faceVertices, mesh.triangles);
    ++local.voxelEdges;
  }

  // The seam: boundary leaves with their vertex (if a polygon here used it) and edge crossings,
  // and the face points made here on faces that touch the boundary.
  for (std::size_t i = 0; i < leafCount; ++i) {
    if (!isSeam[i]) continue;
    const octree::OctreeLeaf& leaf = tree.leaf(i);
    SeamCell cell = seamCellOf(leaf, samples.origin, groups.alternative[i] != 0);
    if (voxels) {
      const VoxelEdgeCell vertices = voxelEdgeCell(groups, i, meshVertex, {});
      cell.splitFaces = vertices.splitFaces;
      cell.splitVertices = vertices.splitVertices;
    }
    for (std::size_t g = 0; g < static_cast<std::size_t>(groups.cellVertexCount(i)); ++g) {
      cell.vertices[g] = meshVertex[groups.firstVertex[i] + g];
      const Vec3d& p = cellPoints[groups.firstVertex[i] + g];  // float-exact (placeGroupVertices, besideDataBox)
      cell.positions[g] = {static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])};
    }
    for (int e = 0; e < 12; ++e)
      cell.edgeCrossing[static_cast<std::size_t>(e)] = ((leaf.bipolarEdges() >> e) & 1)
                                                           ? static_cast<float>(crossing(i, e))
                                                           : std::numeric_limits<float>::quiet_NaN();
    result.seam.cells.push_back(cell);
  }
  for (const auto& [face, vertex] : faceVertices) {
    std::array<int, 3> offset{};
    for (int a = 0; a < 3; ++a) offset[a] = face.min[a] - samples.origin[a];
    bool touches = false;
    for (int a = 0; a < 3; ++a) {
      const int extent = a == face.axis ? 0 : face.size;
      touches = touches || offset[a] == 0 || offset[a] + extent == metaSize;
    }
    if (touches) result.seam.faces.push_back({face, vertex});
  }
  local.seamCells = static_cast<std::int64_t>(result.seam.cells.size());
  local.manifoldFixes = groups.manifoldFixes;
  for (std::size_t i = 0; i < leafCount; ++i) local.multiVertexCells += groups.vertexCount(i) > 1;
  if (stats) *stats = local;
  return result;
}

mesh::Mesh contourAdaptive(const cell::MetaCellSamples& samples, const octree::LinearOctree& tree,
                           const cell::ContourSettings& options, AdaptiveContourStats* stats) {
  return contourAdaptiveMetaCell(samples, tree, options, stats).mesh;
}

}  // namespace isovdb::contour
