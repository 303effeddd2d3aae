// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/stitch/stitch_seams.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <vector>

#include "isovdb/contour/adaptive_edges.h"
#include "isovdb/errors.h"
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
void stitchRegular(const Seam& seam, const EdgeOctree& edgeTree, int s, bool voxels, bool intersectionFree,
                   const contour::VertexAdder& addVertex, mesh::Mesh& out, StitchStats& stats) {
  const LinearOctree& tree = edgeTree.tree;
  const contour::EdgePointFn none;
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
        // The owner's local edge 4 * axis starts at its origin; its crossing came with the cell.
        const SeamCell& owner = *edgeTree.cells[i];
        const contour::EdgePointFn addEdgePoint = [&] {
          contour::Vec3d point{static_cast<double>(owner.origin[0]), static_cast<double>(owner.origin[1]),
                               static_cast<double>(owner.origin[2])};
          point[static_cast<std::size_t>(axis)] +=
              static_cast<double>(owner.edgeCrossing[static_cast<std::size_t>(4 * axis)]);
          return addVertex(point);
        };
        contour::voxelEdgeTriangles(cells, axis, owner.origin, owner.size, out.triangles,
                                    intersectionFree ? addEdgePoint : none);
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
void stitchAdaptive(const Seam& seam, const EdgeOctree& edgeTree, int s, bool intersectionFree, bool voxels,
                    const contour::VertexAdder& addVertex, contour::FaceVertexMap& faceVertices, mesh::Mesh& out,
                    StitchStats& stats) {
  const LinearOctree& tree = edgeTree.tree;
  const std::size_t n = tree.leafCount();
  std::vector<std::uint32_t> firstVertex(n + 1, 0);
  std::vector<char> alternative(n, 0);
  // Cells read as the voxel object (cell::ContourSettings::adaptiveReadsVoxels): their
  // meta-cell made every vertex of theirs, split vertices included.
  std::vector<char> voxelCells(voxels ? n : 0, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const SeamCell& cell = *edgeTree.cells[i];
    const bool read = voxels && cell.size == 1 && cell::voxelReadingDiffers(cell.cornerSigns);
    if (voxels) voxelCells[i] = read;
    const int count = read ? contour::voxelCellVertexCount(cell.cornerSigns)
                           : cell::dmcEntry(cell.cornerSigns, cell.alternative).vertexCount;
    firstVertex[i + 1] = firstVertex[i] + static_cast<std::uint32_t>(count);
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
      .partial = true,
      .voxelCells = voxels ? &voxelCells : nullptr,
      .regularVertex = {}};
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
  if (!voxels) return;
  // The seam's edges of cells read as voxels, by the leaf in quadrant 3 (as stitchRegular).
  contour::forEachVoxelReadingEdge(
      tree, voxelCells, [&](const std::array<int, 3>& origin, int axis) { return seam.ownsEdge(origin, axis, s); },
      [&](const std::array<int, 3>& origin, int axis) { return tree.leavesAroundEdge(origin, axis); },
      [&](std::size_t i, int axis, const std::array<std::int64_t, 4>& around) {
        if (std::any_of(around.begin(), around.end(), [&](std::int64_t l) {
              return l == LinearOctree::kNone || tree.leaf(static_cast<std::size_t>(l)).size != 1;
            })) {
          ++stats.missingCells;
          return;
        }
        const SeamCell& owner = *edgeTree.cells[i];
        contour::VoxelReadingEdge edge;
        edge.axis = axis;
        edge.start = owner.origin;
        edge.crossing = static_cast<double>(owner.edgeCrossing[static_cast<std::size_t>(4 * axis)]);
        for (int q = 0; q < 4; ++q) {
          const auto uq = static_cast<std::size_t>(q);
          const auto l = static_cast<std::size_t>(around[uq]);
          SeamCell& cell = *edgeTree.cells[l];
          edge.cells[uq] = voxelEdgeCell(cell);
          edge.voxelCell[uq] = voxelCells[l] != 0;
          const int g = std::max(
              0,
              static_cast<int>(
                  contour::voxelDmcEntry(cell.cornerSigns).vertexOfEdge[static_cast<std::size_t>(4 * axis + 3 - q)]));
          edge.groups[uq] = g;
          edge.points[uq] = cellPoints[firstVertex[l] + static_cast<std::size_t>(g)];
          // A voxel cell's vertices were made with its meta-cell; the others' when first used.
          if (!edge.voxelCell[uq]) edge.cells[uq].vertices[static_cast<std::size_t>(g)] = cellVertex(around[uq], g);
        }
        contour::emitVoxelReadingEdge(edge, addVertex, faceVertices, out.triangles);
        ++stats.edges;
      });
}

}  // namespace

void SeamStore::add(const MetaCellIndex& index, contour::MetaCellSeam seam) {
  cells_ += seam.cells.size();
  held_ += seam.cells.size();
  contour::MetaCellSeam& slot = seams_[{index[2], index[1], index[0]}];
  held_ -= slot.cells.size();  // a meta-cell added again replaces its seam
  slot = std::move(seam);
}

contour::MetaCellSeam* SeamStore::find(const MetaCellIndex& index) {
  const auto it = seams_.find({index[2], index[1], index[0]});
  return it == seams_.end() ? nullptr : &it->second;
}

void SeamStore::dropBelow(int z) {
  const auto end = seams_.lower_bound({z, std::numeric_limits<int>::min(), std::numeric_limits<int>::min()});
  for (auto it = seams_.begin(); it != end; ++it) held_ -= it->second.cells.size();
  seams_.erase(seams_.begin(), end);
}

namespace {

/// Provisional ids of the stitcher's vertices until the output's vertex count is known.
constexpr std::uint32_t kProvisionalBase = std::uint32_t{1} << 31;

}  // namespace

SeamStitcher::SeamStitcher(const cell::ContourSettings& settings, int metaCellSize)
    : settings_(settings),
      metaCellSize_(metaCellSize),
      stitchedBelow_(std::numeric_limits<int>::min()),
      lastZ_(std::numeric_limits<int>::min()) {}

void SeamStitcher::add(const MetaCellIndex& index, contour::MetaCellSeam seam) {
  if (index[2] > lastZ_) {
    // Every layer below this one is complete: the seams whose reference lies below the
    // previous layer read nothing more to come, and their cells nothing later reads.
    if (lastZ_ != std::numeric_limits<int>::min()) {
      stitchBelow(index[2] - 1, nullptr);
      store_.dropBelow(index[2] - 1);
    }
    lastZ_ = index[2];
  }
  for (const contour::SeamFace& face : seam.faces) faceVertices_.emplace(face.face, face.vertex);
  stats_.seamCells += static_cast<std::int64_t>(seam.cells.size());
  store_.add(index, std::move(seam));
  stats_.peakHeldCells = std::max(stats_.peakHeldCells, static_cast<std::int64_t>(store_.heldCellCount()));
}

void SeamStitcher::stitchBelow(int z, Interrupter* interrupter) {
  const int s = metaCellSize_;
  const contour::VertexAdder addVertex = contour::appendingTo(tail_, kProvisionalBase);
  auto stitch = [&](const Seam& seam) {
    const std::vector<int> octants = seam.octants();
    std::vector<std::vector<SeamCell>*> around;
    for (const int o : octants) {
      const MetaCellIndex index{seam.reference[0] + (o & 1), seam.reference[1] + ((o >> 1) & 1),
                                seam.reference[2] + ((o >> 2) & 1)};
      contour::MetaCellSeam* m = store_.find(index);
      if (!m || m->cells.empty()) return;  // a sign change on the seam would have made it a contoured meta-cell
      around.push_back(&m->cells);
    }
    const EdgeOctree edgeTree = buildEdgeOctree(seam, around, s);
    if (!settings_.contoursByMinimalEdges())
      stitchRegular(seam, edgeTree, s, settings_.topology == cell::RegularTopology::Voxels, settings_.intersectionFree,
                    addVertex, tail_, stats_);
    else
      stitchAdaptive(seam, edgeTree, s, settings_.intersectionFree, settings_.adaptiveReadsVoxels(), addVertex,
                     faceVertices_, tail_, stats_);
    ++(seam.kind == Seam::Kind::Face ? stats_.metaFaces : stats_.metaEdges);
  };
  // Stitching only changes kept cells (adaptive vertex ids), never the store's map.
  ProgressStage progress(interrupter, "stitching seams");
  const auto& seams = store_.byZyx();
  const auto first =
      seams.lower_bound({stitchedBelow_, std::numeric_limits<int>::min(), std::numeric_limits<int>::min()});
  const auto end = seams.lower_bound({z, std::numeric_limits<int>::min(), std::numeric_limits<int>::min()});
  const auto total = static_cast<double>(std::distance(first, end));
  double visited = 0;
  for (auto it = first; it != end; ++it) {
    const MetaCellIndex reference{it->first[2], it->first[1], it->first[0]};
    for (int axis = 0; axis < 3; ++axis) stitch(Seam{Seam::Kind::Face, reference, axis});
    for (int axis = 0; axis < 3; ++axis) stitch(Seam{Seam::Kind::Edge, reference, axis});
    progress.update(++visited, total);
  }
  stitchedBelow_ = std::max(stitchedBelow_, z);
}

void SeamStitcher::finish(std::uint32_t vertexBase, mesh::Mesh& out, Interrupter* interrupter) {
  stitchBelow(std::numeric_limits<int>::max(), interrupter);
  if (vertexBase > kProvisionalBase || tail_.positions.size() > kProvisionalBase - vertexBase)
    throw InputError("the mesh has more than 2^31 vertices; use a larger --max-error or --meta-cell");
  for (mesh::Triangle& t : tail_.triangles)
    for (std::uint32_t& v : t)
      if (v >= kProvisionalBase) v = v - kProvisionalBase + vertexBase;
  out.positions.insert(out.positions.end(), tail_.positions.begin(), tail_.positions.end());
  out.triangles.insert(out.triangles.end(), tail_.triangles.begin(), tail_.triangles.end());
  tail_ = {};
  store_.dropBelow(std::numeric_limits<int>::max());
}

}  // namespace isovdb::stitch
