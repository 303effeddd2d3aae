// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/stitch/stitch_seams.h"

#include <cmath>
#include <vector>

#include "isovdb/contour/adaptive_edges.h"
#include "isovdb/cell/dmc_table.h"
#include "isovdb/contour/regular_contour.h"
#include "isovdb/contour/voxel_dmc.h"
#include "isovdb/octree/morton.h"

namespace isovdb::stitch {

namespace {

using contour::SeamCell;
using octree::LinearOctree;

/// A kept cell as voxel_dmc.h reads it.
contour::VoxelEdgeCell voxelEdgeCell(const SeamCell& cell) {
  contour::VoxelEdgeCell out;
  out.config = cell.cornerSigns;
  out.splitFaces = cell.splitFaces;
  out.vertices = cell.vertices;
  out.positions = cell.positions;
  out.splitVertices = cell.splitVertices;
  return out;
}

/// Regular mode: the quad (voxel topology: polygon) of every bipolar edge the seam owns, by its owner (the leaf in
/// quadrant 3).
void stitchRegular(const Seam& seam, const EdgeOctree& edgeTree, int s, bool voxels, mesh::Mesh& out,
                   StitchStats& stats) {
  const LinearOctree& tree = edgeTree.tree;
  for (std::size_t i = 0; i < tree.leafCount(); ++i) {
    const octree::OctreeLeaf& leaf = tree.leaf(i);
    const std::uint16_t bipolar = octree::bipolarEdgeMask(leaf.cornerSigns);
    for (int axis = 0; axis < 3; ++axis) {
      if (((bipolar >> (4 * axis)) & 1) == 0 || !seam.ownsEdge(leaf.origin, axis, s)) continue;
      const auto around = tree.leavesAroundEdge(leaf.origin, axis);
      if (voxels) {
        std::array<contour::VoxelEdgeCell, 4> cells;
        bool complete = true;
        for (int q = 0; q < 4 && complete; ++q) {
          const std::int64_t j = around[static_cast<std::size_t>(q)];
          complete = j != LinearOctree::kNone && edgeTree.cells[static_cast<std::size_t>(j)]->size == leaf.size;
          if (complete)
            cells[static_cast<std::size_t>(q)] = voxelEdgeCell(*edgeTree.cells[static_cast<std::size_t>(j)]);
        }
        if (!complete) {
          ++stats.missingCells;
          continue;
        }
        contour::voxelEdgeTriangles(cells, axis, out.triangles);
        ++stats.edges;
        continue;
      }
      const bool complete = contour::appendRegularEdgeQuad(
          [&](int q) -> std::optional<contour::EdgeVertex> {
            const std::int64_t j = around[static_cast<std::size_t>(q)];
            if (j == LinearOctree::kNone) return std::nullopt;
            const SeamCell& cell = *edgeTree.cells[static_cast<std::size_t>(j)];
            const int g = cell::dmcVertexOfEdge(cell.cornerSigns, cell.alternative, axis, q);
            if (g < 0 || cell.size != leaf.size) return std::nullopt;
            return contour::EdgeVertex{cell.vertices[static_cast<std::size_t>(g)],
                                       cell.positions[static_cast<std::size_t>(g)]};
          },
          axis, (leaf.cornerSigns & 1) != 0, out.triangles);
      if (!complete) {
        ++stats.missingCells;
        continue;
      }
      ++stats.edges;
    }
  }
}

/// Adaptive mode: the minimal edges the seam owns, with Ju–Udeshi envelopes; cell
/// vertices the meta-cells did not use yet are added on first use.
void stitchAdaptive(const Seam& seam, const EdgeOctree& edgeTree, int s, bool intersectionFree,
                    const contour::VertexAdder& addVertex, contour::FaceVertexMap& faceVertices, mesh::Mesh& out,
                    StitchStats& stats) {
  const LinearOctree& tree = edgeTree.tree;
  const std::size_t n = tree.leafCount();
  std::vector<std::uint32_t> firstVertex(n + 1, 0);
  std::vector<char> alternative(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const SeamCell& cell = *edgeTree.cells[i];
    firstVertex[i + 1] = firstVertex[i] + cell::dmcEntry(cell.cornerSigns, cell.alternative).vertexCount;
    alternative[i] = cell.alternative;
  }
  std::vector<contour::Vec3d> cellPoints(firstVertex[n]);
  for (std::size_t i = 0; i < n; ++i)
    for (std::uint32_t v = firstVertex[i]; v < firstVertex[i + 1]; ++v) {
      const mesh::Vec3f& p = edgeTree.cells[i]->positions[v - firstVertex[i]];
      cellPoints[v] = {p[0], p[1], p[2]};
    }
  const contour::AdaptiveTree source{
      .tree = &tree,
      .origin = tree.origin(),
      .firstVertex = &firstVertex,
      .cellPoints = &cellPoints,
      .alternative = &alternative,
      .crossing = [&](std::size_t leaf, int e) -> double {
        return static_cast<double>(edgeTree.cells[leaf]->edgeCrossing[static_cast<std::size_t>(e)]);
      },
      .inRegion = [&](const std::array<int, 3>& start, int axis) { return seam.ownsEdge(start, axis, s); },
      .partial = true};
  const auto cellVertex = [&](std::int64_t leaf, int group) {
    SeamCell& cell = *edgeTree.cells[static_cast<std::size_t>(leaf)];
    std::uint32_t& vertex = cell.vertices[static_cast<std::size_t>(group)];
    if (vertex == contour::kNoVertex)
      vertex = addVertex(cellPoints[firstVertex[static_cast<std::size_t>(leaf)] + static_cast<std::size_t>(group)]);
    return vertex;
  };
  contour::LeafEdges edges;
  for (std::size_t i = 0; i < n; ++i) {
    if (tree.leaf(i).bipolarEdges() == 0) continue;
    edges.records.clear();
    contour::collectMinimalEdges(source, i, intersectionFree, edges);
    for (const contour::EdgeRecord& r : edges.records) {
      contour::emitEdgeRecord(r, cellVertex, addVertex, faceVertices, out.triangles);
      ++stats.edges;
      if (r.how.fan) ++stats.fannedEdges;
    }
  }
  stats.missingCells += edges.boundary + edges.withoutVertex;
}

}  // namespace

void SeamStore::add(const MetaCellIndex& index, contour::MetaCellSeam seam) {
  cells_ += seam.cells.size();
  seams_[{index[2], index[1], index[0]}] = std::move(seam);
}

contour::MetaCellSeam* SeamStore::find(const MetaCellIndex& index) {
  const auto it = seams_.find({index[2], index[1], index[0]});
  return it == seams_.end() ? nullptr : &it->second;
}

void stitchSeams(SeamStore& store, const cell::ContourSettings& options, int metaCellSize, std::uint32_t vertexBase,
                 mesh::Mesh& out, StitchStats* stats, Interrupter* interrupter) {
  ProgressStage progress(interrupter, "stitching seams");
  StitchStats local;
  local.seamCells = static_cast<std::int64_t>(store.cellCount());
  const int s = metaCellSize;
  const contour::VertexAdder addVertex = contour::appendingTo(out, vertexBase);
  contour::FaceVertexMap faceVertices;
  for (const auto& [zyx, seam] : store.byZyx())
    for (const contour::SeamFace& face : seam.faces) faceVertices.emplace(face.face, face.vertex);

  auto stitch = [&](const Seam& seam) {
    const std::vector<int> octants = seam.octants();
    std::vector<std::vector<SeamCell>*> around;
    for (const int o : octants) {
      const MetaCellIndex index{seam.reference[0] + (o & 1), seam.reference[1] + ((o >> 1) & 1),
                                seam.reference[2] + ((o >> 2) & 1)};
      contour::MetaCellSeam* m = store.find(index);
      if (!m || m->cells.empty()) return;  // a sign change on the seam would have made it a contoured meta-cell
      around.push_back(&m->cells);
    }
    const EdgeOctree edgeTree = buildEdgeOctree(seam, around, s);
    if (!options.contoursByMinimalEdges())
      stitchRegular(seam, edgeTree, s, options.topology == cell::RegularTopology::Voxels, out, local);
    else
      stitchAdaptive(seam, edgeTree, s, options.intersectionFree, addVertex, faceVertices, out, local);
    ++(seam.kind == Seam::Kind::Face ? local.metaFaces : local.metaEdges);
  };

  // Stitching only changes kept cells (adaptive vertex ids), never the store's map.
  std::size_t visited = 0;
  const std::size_t total = store.metaCellCount();
  for (const auto& [zyx, seam] : store.byZyx()) {
    const MetaCellIndex reference{zyx[2], zyx[1], zyx[0]};
    for (int axis = 0; axis < 3; ++axis) stitch(Seam{Seam::Kind::Face, reference, axis});
    for (int axis = 0; axis < 3; ++axis) stitch(Seam{Seam::Kind::Edge, reference, axis});
    progress.update(static_cast<double>(++visited), static_cast<double>(total));
  }
  if (stats) *stats = local;
}

}  // namespace isovdb::stitch
